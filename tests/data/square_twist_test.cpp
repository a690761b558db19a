// Square twist generator: geometry, the 16 flat-foldable assignments, rigidity of the four
// types (seed 001 §2), the T1 identification (seed 003 §3.3) and Types 1M/2M (seed 001 §3).
#include <gtest/gtest.h>

#include "data/generators/square_twist.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/data/generator_test_utils.hpp"
#include "tests/support/input_error_place.hpp"

namespace rigidfold::test {
namespace { namespace RIGIDFOLD_UNITY_ID {

using generators::SquareTwistModifiedType;
using generators::SquareTwistParams;
using generators::SquareTwistType;
constexpr Assignment M = Assignment::Mountain, V = Assignment::Valley;

SquareTwistParams params(double twist_deg) {
  SquareTwistParams p;
  p.twist = to_radians(twist_deg);
  p.side = 1.3;
  p.pleat = 0.8;
  return p;
}

int edge_between(const CreasePattern& p, int a, int b) {
  for (int e = 0; e < p.num_edges(); ++e)
    if ((p.edges[e][0] == a && p.edges[e][1] == b) || (p.edges[e][0] == b && p.edges[e][1] == a)) return e;
  return -1;
}

// Index in the vertex's CCW fan of edge e.
int position(const Fan& fan, int e) {
  for (std::size_t i = 0; i < fan.edges.size(); ++i)
    if (fan.edges[i] == e) return static_cast<int>(i);
  return -1;
}

TEST(GeneratorSquareTwist, CountsSectorsAndTwistSide) {
  for (double t : {10.0, 30.0, 45.0, 80.0}) {
    const CreasePattern p = generators::square_twist(params(t), SquareTwistType::Type3);
    EXPECT_EQ(p.num_vertices(), 16);
    EXPECT_EQ(p.num_edges(), 24);
    EXPECT_EQ(p.num_faces(), 9);
    const Topology topo = build_topology(p);
    ASSERT_EQ(topo.interior_vertices, (std::vector<int>{0, 1, 2, 3}));
    for (int k = 0; k < 4; ++k) {
      const Fan& fan = topo.stars[k].fans[0];
      ASSERT_EQ(fan.edges.size(), 4u);
      // CCW from the side to the next vertex: pi/2, pi - t, pi/2, t.
      const int i0 = position(fan, edge_between(p, k, (k + 1) % 4));
      ASSERT_GE(i0, 0);
      const double expected[4] = {kPi / 2, kPi - to_radians(t), kPi / 2, to_radians(t)};
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(fan.sectors[(i0 + j) % 4], expected[j], 1e-12) << "t " << t << " v " << k;
      EXPECT_EQ(fan.edges[(i0 + 1) % 4], edge_between(p, k, (k + 3) % 4));  // side to the previous vertex
      EXPECT_EQ(fan.edges[(i0 + 2) % 4], 4 + 2 * k);                         // o_a
      EXPECT_EQ(fan.edges[(i0 + 3) % 4], 5 + 2 * k);                         // o_b, before the twist sector
    }
    // Outer creases are axis-parallel; the central square has the requested side.
    for (int e = 4; e < 12; ++e) {
      const Eigen::Vector3d d = p.vertices[p.edges[e][1]] - p.vertices[p.edges[e][0]];
      EXPECT_NEAR(std::min(std::fabs(d.x()), std::fabs(d.y())), 0.0, 1e-12);
      EXPECT_NEAR(d.norm(), 0.8, 1e-12);
    }
    EXPECT_NEAR((p.vertices[1] - p.vertices[0]).norm(), 1.3, 1e-12);
  }
}

TEST(GeneratorSquareTwist, TypesMatchSeed001SideTable) {
  using S = std::array<Assignment, 4>;
  EXPECT_EQ(generators::square_twist_sides(SquareTwistType::Type1), (S{M, M, M, M}));
  EXPECT_EQ(generators::square_twist_sides(SquareTwistType::Type2), (S{V, M, V, M}));
  EXPECT_EQ(generators::square_twist_sides(SquareTwistType::Type3), (S{M, V, V, M}));
  EXPECT_EQ(generators::square_twist_sides(SquareTwistType::Type4), (S{V, V, V, M}));
  // Seed 001 eq. (17) (Type 1 vertex A): theta_1..4 = M, M, V, M with joints side-to-previous,
  // twist side, o_b, o_a.
  const auto a1 = generators::square_twist_assignment(SquareTwistType::Type1);
  EXPECT_EQ(a1[3], M);  // DA
  EXPECT_EQ(a1[0], M);  // AB
  EXPECT_EQ(a1[5], V);  // o_b of A
  EXPECT_EQ(a1[4], M);  // o_a of A
  // Seed 001 eq. (21) (Type 2 vertex A): M, V, M, M.
  const auto a2 = generators::square_twist_assignment(SquareTwistType::Type2);
  EXPECT_EQ(a2[3], M);
  EXPECT_EQ(a2[0], V);
  EXPECT_EQ(a2[5], M);
  EXPECT_EQ(a2[4], M);
}

// All 2^4 side patterns are flat-foldable; rigid (loop gain 1, folds close) iff exactly two
// vertices have their odd crease on a side.
TEST(GeneratorSquareTwist, AllSixteenAssignmentsFlatFoldableAndRigidityRule) {
  for (int mask = 0; mask < 16; ++mask) {
    std::array<Assignment, 4> sides{};
    for (int k = 0; k < 4; ++k) sides[k] = (mask >> k) & 1 ? V : M;
    const CreasePattern p = generators::square_twist(params(30), generators::square_twist_assignment(sides));
    const Topology topo = build_topology(p);
    int side_odd = 0;
    for (int v : topo.interior_vertices) {
      EXPECT_NEAR(kawasaki_residual(topo, v), 0.0, 1e-12);
      const auto [m, vv] = mountains_valleys(p, topo, v);
      EXPECT_EQ(std::abs(m - vv), 2) << "mask " << mask << " vertex " << v;
      // Big-Little-Big: the creases beside the smallest sector (t) differ.
      const Fan& fan = topo.stars[v].fans[0];
      const int small = static_cast<int>(std::min_element(fan.sectors.begin(), fan.sectors.end()) - fan.sectors.begin());
      EXPECT_NE(p.assignments[fan.edges[small]], p.assignments[fan.edges[(small + 1) % 4]]);
      side_odd += sides[(v + 3) % 4] != sides[v];
    }
    const auto w = propagate_multipliers(p, topo);
    EXPECT_EQ(w.has_value(), side_odd == 2) << "mask " << mask;
    if (w) {
      for (double tau : {0.05, 0.4, 2.0}) {
        const auto rho = folds_from_multipliers(*w, tau);
        for (int v : topo.interior_vertices) EXPECT_LE(loop_residual(topo, v, rho), 1e-12) << "mask " << mask;
        EXPECT_LE(place(p, topo, rho).mismatch, 1e-12);
      }
    }
  }
}

TEST(GeneratorSquareTwist, NonRigidTypesHaveSeed001LoopGain) {
  // Seed 001 eqs. (7), (8): going once round the loop multiplies tan(theta/2) by
  // cos^4 t / (1 -+ sin t)^4 != 1, so the multipliers cannot agree.
  for (auto type : {SquareTwistType::Type1, SquareTwistType::Type2}) {
    const CreasePattern p = generators::square_twist(params(30), type);
    EXPECT_FALSE(propagate_multipliers(p, build_topology(p)).has_value());
  }
  for (auto type : {SquareTwistType::Type3, SquareTwistType::Type4}) {
    const CreasePattern p = generators::square_twist(params(30), type);
    EXPECT_TRUE(propagate_multipliers(p, build_topology(p)).has_value());
  }
}

// Seed 003 §3.3: "the rectangle panels in T1 are all parallel to each other". Of the two
// rigid types only Type 3 keeps its four corner rectangles parallel: T1 = Type 3.
TEST(GeneratorSquareTwist, Type3KeepsCornerRectanglesParallel) {
  auto rectangle_normals = [](SquareTwistType type, double tau) {
    const CreasePattern p = generators::square_twist(params(30), type);
    const Topology topo = build_topology(p);
    const auto rho = folds_from_multipliers(*propagate_multipliers(p, topo), tau);
    const Placement pl = place(p, topo, rho);
    EXPECT_LE(pl.mismatch, 1e-12);
    std::vector<Eigen::Vector3d> normals;
    for (int k = 0; k < 4; ++k) {
      const int f = find_face(p, {k, 4 + 3 * k, 5 + 3 * k, 6 + 3 * k});
      EXPECT_GE(f, 0);
      normals.push_back(pl.rotation[f] * Eigen::Vector3d::UnitZ());
    }
    double worst = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) worst = std::max(worst, normals[i].cross(normals[j]).norm());
    return worst;
  };
  for (double tau : {0.2, 0.7, 1.5}) {
    EXPECT_LE(rectangle_normals(SquareTwistType::Type3, tau), 1e-12) << tau;
    EXPECT_GT(rectangle_normals(SquareTwistType::Type4, tau), 1e-2) << tau;
  }
}

TEST(GeneratorSquareTwist, ModifiedTypesFollowSeed001Section3) {
  for (auto type : {SquareTwistModifiedType::Type1M, SquareTwistModifiedType::Type2M}) {
    const CreasePattern p = generators::square_twist_modified(params(30), type);
    EXPECT_EQ(p.num_vertices(), 16);
    EXPECT_EQ(p.num_edges(), 25);
    EXPECT_EQ(p.num_faces(), 10);
    EXPECT_EQ(p.edges[12], (std::array<int, 2>{1, 3}));  // the diagonal BD
    EXPECT_EQ(p.assignments[12], V);
    const Topology topo = build_topology(p);
    ASSERT_EQ(topo.interior_vertices.size(), 4u);
    for (int v : {0, 2}) EXPECT_EQ(topo.stars[v].fans[0].edges.size(), 4u);
    for (int v : {1, 3}) {
      // Seed 001 eq. (11), joints 1..5 = previous side, diagonal, twist side, o_b, o_a read
      // clockwise here: pi/4, pi/4, t, pi/2, pi - t. Counter-clockwise from the twist side
      // the same sectors come as pi/4, pi/4, pi - t, pi/2, t.
      const Fan& fan = topo.stars[v].fans[0];
      ASSERT_EQ(fan.edges.size(), 5u);
      const int i0 = position(fan, edge_between(p, v, (v + 1) % 4));  // twist side
      const double t = to_radians(30);
      const double expected_ccw[5] = {kPi / 4, kPi / 4, kPi - t, kPi / 2, t};  // twist side, diag, prev side, o_a, o_b
      for (int j = 0; j < 5; ++j) EXPECT_NEAR(fan.sectors[(i0 + j) % 5], expected_ccw[j], 1e-12);
      EXPECT_EQ(fan.edges[(i0 + 1) % 5], 12);
      // Seed 001 eqs. (15) / (19): joints 1..5 = previous side, diagonal, twist side, o_b, o_a.
      const Assignment prev = p.assignments[edge_between(p, v, (v + 3) % 4)];
      const Assignment twist_side = p.assignments[edge_between(p, v, (v + 1) % 4)];
      const Assignment o_b = p.assignments[5 + 2 * v], o_a = p.assignments[4 + 2 * v];
      if (type == SquareTwistModifiedType::Type1M) {
        EXPECT_EQ(prev, M);
        EXPECT_EQ(twist_side, M);
        EXPECT_EQ(o_b, V);
        EXPECT_EQ(o_a, M);
      } else {
        EXPECT_EQ(prev, V);
        EXPECT_EQ(twist_side, M);
        EXPECT_EQ(o_b, V);
        EXPECT_EQ(o_a, V);
      }
    }
    // Seed 001 eqs. (17) / (21) at A and C.
    for (int v : {0, 2}) {
      const Assignment prev = p.assignments[edge_between(p, v, (v + 3) % 4)];
      const Assignment twist_side = p.assignments[edge_between(p, v, (v + 1) % 4)];
      const Assignment o_b = p.assignments[5 + 2 * v], o_a = p.assignments[4 + 2 * v];
      const bool one = type == SquareTwistModifiedType::Type1M;
      EXPECT_EQ(prev, M);
      EXPECT_EQ(twist_side, one ? M : V);
      EXPECT_EQ(o_b, one ? V : M);
      EXPECT_EQ(o_a, M);
    }
  }
}

// Seed 001 §4.1, Type 1M at alpha = pi/6, Path 2: the assigned signs (eqs. (15), (17)) hold
// from the fully folded state down to configuration III_2 at phi_1^b = 0.41 pi, where
// crease b4 (o_b of B; likewise d4) reaches 0 and switches. Locate that point: fix
// rho(b4) = 0 and solve the closure from a nearby state of the path.
TEST(GeneratorSquareTwist, Type1MPath2SwitchesB4AtSeedConfigurationIII) {
  const CreasePattern p = generators::square_twist_modified(params(30), SquareTwistModifiedType::Type1M);
  const Topology topo = build_topology(p);
  std::vector<double> rho(p.num_edges(), 0.0);
  const double guess[13] = {-1.78, -1.24, -1.78, -1.24, -1.78, 1.24, -1.24, 0.0, -1.78, 1.24, -1.24, 0.0, 1.15};
  for (int e = 0; e < 13; ++e) rho[e] = guess[e];
  std::vector<bool> free_edge(p.num_edges(), false);
  for (int e = 0; e < 13; ++e) free_edge[e] = e != 7;  // rho(b4) = 0
  EXPECT_LE(solve_closure(topo, rho, free_edge), 1e-13);
  const double phi1b = kPi - std::fabs(rho[0]);  // dihedral of b1 = side AB
  EXPECT_NEAR(phi1b / kPi, 0.41, 0.005);
  RecordProperty("phi1b_over_pi", std::to_string(phi1b / kPi));
  // Every other crease still folds the assigned way there.
  for (int e = 0; e < 13; ++e)
    if (e != 7 && e != 11) {
      EXPECT_GT(rho[e] * sign_of(p.assignments[e]), 0.0) << "edge " << e;
    }
  EXPECT_NEAR(rho[11], 0.0, 1e-9);  // d4 switches together with b4 (symmetry B <-> D)
}

// Type 2M: a folded state with every crease as assigned exists (seed 001 §4.2).
TEST(GeneratorSquareTwist, Type2MFoldsWithItsAssignment) {
  const CreasePattern p = generators::square_twist_modified(params(30), SquareTwistModifiedType::Type2M);
  const Topology topo = build_topology(p);
  std::vector<double> rho(p.num_edges(), 0.0);
  const double guess[13] = {0.30, -0.51, 0.30, -0.51, -0.30, -0.51, 0.51, 0.44, -0.30, -0.51, 0.51, 0.44, 0.52};
  for (int e = 0; e < 13; ++e) rho[e] = guess[e];
  std::vector<bool> free_edge(p.num_edges(), false);
  for (int e = 1; e < 13; ++e) free_edge[e] = true;  // side AB held at 0.30
  EXPECT_LE(solve_closure(topo, rho, free_edge), 1e-13);
  for (int e = 0; e < 13; ++e) EXPECT_GT(rho[e] * sign_of(p.assignments[e]), 0.0) << "edge " << e;
}

TEST(GeneratorSquareTwist, ExplicitAssignmentAndRoundTrip) {
  std::vector<Assignment> letters(12, M);
  letters[7] = V;
  letters[11] = Assignment::Unassigned;
  const CreasePattern p = generators::square_twist(params(20), letters);
  for (int e = 0; e < 12; ++e) EXPECT_EQ(p.assignments[e], letters[e]);
  for (int e = 12; e < p.num_edges(); ++e) EXPECT_EQ(p.assignments[e], Assignment::Boundary);
  SquareTwistParams with_ac = params(20);
  with_ac.diagonal = generators::SquareTwistDiagonal::AC;
  letters.push_back(V);
  const CreasePattern q = generators::square_twist(with_ac, letters);
  EXPECT_EQ(q.edges[12], (std::array<int, 2>{0, 2}));
  const CreasePattern r = round_trip(q, "square_twist_ac");
  EXPECT_EQ(r.vertices, q.vertices);
  EXPECT_EQ(r.edges, q.edges);
  EXPECT_EQ(r.assignments, q.assignments);
  EXPECT_EQ(r.num_faces(), q.num_faces());
  EXPECT_EQ(r.extra["file_title"], q.extra["file_title"]);
}

TEST(GeneratorSquareTwist, BadParametersNameTheParameter) {
  auto place_of = [](auto&& f) { return test::input_error_place(f); };
  EXPECT_EQ(place_of([] { generators::square_twist(params(90), SquareTwistType::Type1); }), "twist");
  EXPECT_EQ(place_of([] { generators::square_twist(params(0), SquareTwistType::Type1); }), "twist");
  EXPECT_EQ(place_of([] {
              auto p = params(30);
              p.pleat = -1;
              generators::square_twist(p, SquareTwistType::Type1);
            }),
            "pleat");
  EXPECT_EQ(place_of([] { generators::square_twist(params(30), std::vector<Assignment>(11, M)); }), "assignment");
  EXPECT_EQ(place_of([] { generators::square_twist(params(30), std::vector<Assignment>(12, Assignment::Boundary)); }),
            "assignment");
}

}}  // namespace
}  // namespace rigidfold::test
