// Double-corrugated units P and Q (seed 003 §3.2): sectors per vertex type, shared creases,
// the numbers of flat-foldable and rigid M-V assignments (P: 10 / 4, Q: 6 / 4), closure of
// the rigid ones, and the square twist as unit Q with beta = pi/2.
#include <gtest/gtest.h>

#include <set>

#include "data/generators/double_corrugated.hpp"
#include "data/generators/generator_common.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/data/generator_test_utils.hpp"
#include "tests/support/input_error_place.hpp"

namespace rigidfold::test {
namespace { namespace RIGIDFOLD_UNITY_ID {

using generators::CorrugatedParams;
using generators::CorrugatedUnit;

CorrugatedParams angles(double alpha_deg, double beta_deg) {
  CorrugatedParams p;
  p.alpha = to_radians(alpha_deg);
  p.beta = to_radians(beta_deg);
  p.a = 1.1;
  p.b = 0.9;
  return p;
}

const std::vector<std::pair<double, double>> kAngles{{135, 60}, {135, 120}, {100, 85}, {150, 40}, {120, 90}};

TEST(GeneratorCorrugated, SectorsFollowVertexTypes) {
  for (auto unit : {CorrugatedUnit::P, CorrugatedUnit::Q})
    for (auto [al, be] : kAngles) {
      const CreasePattern p = generators::corrugated_unit(unit, angles(al, be), generators::corrugated_rigid_assignment(unit));
      EXPECT_EQ(p.num_vertices(), 16);
      EXPECT_EQ(p.num_edges(), 24);
      EXPECT_EQ(p.num_faces(), 9);
      const Topology topo = build_topology(p);
      ASSERT_EQ(topo.interior_vertices.size(), 4u);
      const double a = to_radians(al), b = to_radians(be), g = kPi - a, d = kPi - b;
      for (const auto& vx : generators::corrugated_vertices(unit)) {
        const Fan& fan = topo.stars[vx.vertex].fans[0];
        ASSERT_EQ(fan.edges.size(), 4u);
        int i0 = 0;
        while (fan.edges[i0] != vx.joints[0]) ++i0;
        const std::array<double, 4> expected = vx.type_one ? std::array<double, 4>{a, b, g, d} : std::array<double, 4>{a, d, g, b};
        for (int j = 0; j < 4; ++j) {
          EXPECT_EQ(fan.edges[(i0 + j) % 4], vx.joints[j]) << vx.name << " joints must run counter-clockwise";
          EXPECT_NEAR(fan.sectors[(i0 + j) % 4], expected[j], 1e-12) << to_string(unit) << " " << vx.name;
        }
        EXPECT_NEAR(kawasaki_residual(topo, vx.vertex), 0.0, 1e-12);
      }
    }
}

TEST(GeneratorCorrugated, SharedCreasesAreTheSeeds) {
  const auto P = generators::corrugated_vertices(CorrugatedUnit::P);  // A B C D
  EXPECT_EQ(P[0].joints[1], P[1].joints[2]);  // a2 = b3
  EXPECT_EQ(P[1].joints[3], P[2].joints[0]);  // b4 = c1
  EXPECT_EQ(P[2].joints[1], P[3].joints[2]);  // c2 = d3
  EXPECT_EQ(P[3].joints[3], P[0].joints[0]);  // d4 = a1
  const auto Q = generators::corrugated_vertices(CorrugatedUnit::Q);  // A B E F
  EXPECT_EQ(Q[3].joints[2], Q[2].joints[1]);  // f3 = e2
  EXPECT_EQ(Q[2].joints[2], Q[1].joints[1]);  // e3 = b2
  EXPECT_EQ(Q[1].joints[2], Q[0].joints[1]);  // b3 = a2
  EXPECT_EQ(Q[0].joints[2], Q[3].joints[1]);  // a3 = f2
  // P and Q lie on the two sides of their common crease AB, with the same A and B stars.
  for (int k = 0; k < 2; ++k) EXPECT_EQ(P[k].type_one, Q[k].type_one);
}

// Seed 003 §3.2: "ten distinct assignments for the P unit ... and six for the Q unit", of
// which P1-P4 and Q1-Q4 are rigid. Distinct = up to global M/V flip and the unit's 2-fold
// rotation (vertex k <-> k+2).
TEST(GeneratorCorrugated, AssignmentCountsMatchSeed003) {
  for (auto unit : {CorrugatedUnit::P, CorrugatedUnit::Q}) {
    const auto choices = generators::corrugated_flat_foldable_assignments(unit);
    EXPECT_EQ(choices.size(), unit == CorrugatedUnit::P ? 16u : 8u);
    std::set<std::array<int, 4>> classes, rigid_classes;
    for (const auto& c : choices) {
      const std::array<int, 4> rotated{c.odd_joint[2], c.odd_joint[3], c.odd_joint[0], c.odd_joint[1]};
      const auto key = std::min(c.odd_joint, rotated);
      classes.insert(key);
      if (c.rigid) rigid_classes.insert(key);
    }
    EXPECT_EQ(classes.size(), unit == CorrugatedUnit::P ? 10u : 6u);
    EXPECT_EQ(rigid_classes.size(), 4u);
  }
}

TEST(GeneratorCorrugated, FlatFoldableAndRigidityByClosure) {
  for (auto unit : {CorrugatedUnit::P, CorrugatedUnit::Q})
    for (auto [al, be] : kAngles) {
      for (const auto& c : generators::corrugated_flat_foldable_assignments(unit)) {
        const CreasePattern p = generators::corrugated_unit(unit, angles(al, be), c.assignment);
        const Topology topo = build_topology(p);
        for (int v : topo.interior_vertices) {
          const auto [m, vv] = mountains_valleys(p, topo, v);
          EXPECT_EQ(std::abs(m - vv), 2);
          const Fan& fan = topo.stars[v].fans[0];
          const int small = static_cast<int>(std::min_element(fan.sectors.begin(), fan.sectors.end()) - fan.sectors.begin());
          EXPECT_NE(p.assignments[fan.edges[small]], p.assignments[fan.edges[(small + 1) % 4]]);  // Big-Little-Big
        }
        const auto w = propagate_multipliers(p, topo);
        EXPECT_EQ(w.has_value(), c.rigid) << to_string(unit) << " " << generators::assignment_letters(c.assignment);
        if (!w) continue;
        for (double tau : {0.1, 0.9, 3.0}) {
          const auto rho = folds_from_multipliers(*w, tau);
          for (int v : topo.interior_vertices) EXPECT_LE(loop_residual(topo, v, rho), 1e-12);
          EXPECT_LE(place(p, topo, rho).mismatch, 1e-12);
        }
      }
    }
}

TEST(GeneratorCorrugated, DefaultRigidAssignments) {
  EXPECT_EQ(generators::assignment_letters(generators::corrugated_rigid_assignment(CorrugatedUnit::P)), "MVVMMVVVVMMM");
  EXPECT_EQ(generators::assignment_letters(generators::corrugated_rigid_assignment(CorrugatedUnit::Q)), "MMVVMMVMVVMV");
  for (auto unit : {CorrugatedUnit::P, CorrugatedUnit::Q}) {
    const CreasePattern p = generators::corrugated_unit(unit, angles(135, 60), generators::corrugated_rigid_assignment(unit));
    EXPECT_TRUE(propagate_multipliers(p, build_topology(p)).has_value());
    const auto interior = generators::corrugated_interior_edges(unit);
    for (int e = 0; e < p.num_edges(); ++e) {
      const bool is_interior = std::find(interior.begin(), interior.end(), e) != interior.end();
      EXPECT_EQ(p.assignments[e] == Assignment::Boundary, !is_interior);
    }
    const CreasePattern q = round_trip(p, std::string("corrugated_") + to_string(unit));
    EXPECT_EQ(q.vertices, p.vertices);
    EXPECT_EQ(q.edges, p.edges);
    EXPECT_EQ(q.assignments, p.assignments);
  }
}

// Seed 003 §3.3: with beta = delta = pi/2 unit Q is the square twist (sectors pi/2, pi/2,
// gamma, pi - gamma; the central panel a square).
TEST(GeneratorCorrugated, QWithRightBetaIsASquareTwist) {
  const CreasePattern p = generators::corrugated_unit(CorrugatedUnit::Q, angles(150, 90), generators::corrugated_rigid_assignment(CorrugatedUnit::Q));
  const auto vs = generators::corrugated_vertices(CorrugatedUnit::Q);
  const Topology topo = build_topology(p);
  for (const auto& v : vs) {
    std::vector<double> s = topo.stars[v.vertex].fans[0].sectors;
    std::sort(s.begin(), s.end());
    EXPECT_NEAR(s[0], to_radians(30), 1e-12);
    EXPECT_NEAR(s[1], kPi / 2, 1e-12);
    EXPECT_NEAR(s[2], kPi / 2, 1e-12);
    EXPECT_NEAR(s[3], to_radians(150), 1e-12);
  }
}

TEST(GeneratorCorrugated, BadParametersNameTheParameter) {
  auto place_of = [](auto&& f) { return test::input_error_place(f); };
  const auto rigid = generators::corrugated_rigid_assignment(CorrugatedUnit::P);
  EXPECT_EQ(place_of([&] { generators::corrugated_unit(CorrugatedUnit::P, angles(80, 60), rigid); }), "alpha");
  EXPECT_EQ(place_of([&] { generators::corrugated_unit(CorrugatedUnit::P, angles(135, 30), rigid); }), "beta");
  EXPECT_EQ(place_of([&] { generators::corrugated_unit(CorrugatedUnit::P, angles(135, 140), rigid); }), "beta");
  EXPECT_EQ(place_of([&] { generators::corrugated_unit(CorrugatedUnit::P, angles(135, 60), std::vector<Assignment>(5)); }),
            "assignment");
  EXPECT_EQ(place_of([] { generators::corrugated_assignment(CorrugatedUnit::Q, {3, 4, 4, 4}); }), "odd_joint");
  EXPECT_EQ(place_of([] { generators::corrugated_assignment(CorrugatedUnit::P, {3, 4, 2, 4}); }), "odd_joint");
}

}}  // namespace
}  // namespace rigidfold::test
