// Square-twist tessellation generator: geometry and validity of the sheet, the
// assignment rule, rigidity of the Type4 / Type3Rows layouts with 1 DOF by the exact
// multiplier model (several sizes and twist angles), agreement of the general loop-closure
// solver with it on 2 x 2 (verdict, DOF, folded states), the non-rigid AllType1 / AllType2
// counterparts, and bad parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "data/generators/generator_common.hpp"
#include "data/generators/square_twist.hpp"
#include "data/generators/square_twist_tessellation.hpp"
#include "kernel/analysis/general_verdict.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/solve/rank.hpp"
#include "tests/data/generator_test_utils.hpp"

namespace rigidfold::test {
namespace { namespace RIGIDFOLD_UNITY_ID {

using generators::SquareTwistTessellationLayout;
using generators::SquareTwistTessellationParams;
using Layout = SquareTwistTessellationLayout;
constexpr Assignment M = Assignment::Mountain, V = Assignment::Valley;
constexpr Layout kRigid[] = {Layout::Type4, Layout::Type3Rows};
constexpr Layout kNotRigid[] = {Layout::AllType1, Layout::AllType2};

SquareTwistTessellationParams params(int rows, int cols, double twist_deg, Layout layout) {
  SquareTwistTessellationParams p;
  p.rows = rows;
  p.cols = cols;
  p.twist = to_radians(twist_deg);
  p.side = 1.3;
  p.spacing = 2.6;  // > 1.3 * sqrt(2), valid for every twist angle
  p.layout = layout;
  return p;
}

std::string name(const SquareTwistTessellationParams& p) {
  return std::to_string(p.rows) + "x" + std::to_string(p.cols) + " " + generators::to_string(p.layout) + " t " +
         std::to_string(std::lround(to_degrees(p.twist))) + " deg";
}

// mu = tan(pi/4 - t/2): ratio of the two crease magnitudes at every twist vertex.
double mu(double t) { return (1 - std::sin(t)) / std::cos(t); }

TEST(GeneratorSquareTwistTessellation, CountsGeometryAndValidSheet) {
  for (auto [rows, cols] : {std::pair{1, 1}, {2, 2}, {2, 3}, {3, 3}})
    for (double t : {15.0, 45.0, 75.0})
      for (Layout layout : {Layout::Type4, Layout::Type3Rows, Layout::AllType1, Layout::AllType2}) {
        const auto sp = params(rows, cols, t, layout);
        const std::string where = name(sp);
        const CreasePattern p = generators::square_twist_tessellation(sp);  // validated by the generator
        const int mn = rows * cols, ring = rows + cols;
        EXPECT_EQ(p.num_vertices(), 4 * mn + 4 * ring + 4) << where;
        EXPECT_EQ(p.num_edges(), 8 * mn + 6 * ring + 4) << where;
        EXPECT_EQ(p.num_faces(), 4 * mn + 2 * ring + 1) << where;
        const Topology topo = build_topology(p);
        // One disk: chi = 1, one boundary loop, no holes.
        ASSERT_EQ(topo.components.size(), 1u) << where;
        EXPECT_EQ(topo.components[0].euler_characteristic, 1) << where;
        EXPECT_EQ(topo.components[0].boundary_loops, 1) << where;
        EXPECT_EQ(topo.components[0].holes, 0) << where;
        EXPECT_EQ(topo.components[0].genus, 0) << where;
        // The interior vertices are exactly the twist vertices 0 .. 4 mn - 1.
        ASSERT_EQ(static_cast<int>(topo.interior_vertices.size()), 4 * mn) << where;
        for (int k = 0; k < 4 * mn; ++k) EXPECT_EQ(topo.interior_vertices[k], k) << where;
        for (int v : topo.interior_vertices) {
          const Fan& fan = topo.stars[v].fans[0];
          ASSERT_EQ(fan.edges.size(), 4u) << where << " vertex " << v;
          EXPECT_NEAR(kawasaki_residual(topo, v), 0.0, 1e-12) << where << " vertex " << v;
          // Sectors are those of the single twist: {pi/2, pi/2, pi - t, t}.
          std::vector<double> s = fan.sectors;
          std::sort(s.begin(), s.end());
          const double tr = to_radians(t);
          std::vector<double> expected{tr, kPi / 2, kPi / 2, kPi - tr};
          std::sort(expected.begin(), expected.end());
          for (int i = 0; i < 4; ++i) EXPECT_NEAR(s[i], expected[i], 1e-12) << where;
          // Maekawa and Big-Little-Big (the creases beside the sector t differ).
          const auto [m, vv] = mountains_valleys(p, topo, v);
          EXPECT_EQ(std::abs(m - vv), 2) << where << " vertex " << v;
          const int small = static_cast<int>(std::min_element(fan.sectors.begin(), fan.sectors.end()) -
                                             fan.sectors.begin());
          EXPECT_NE(p.assignments[fan.edges[small]], p.assignments[fan.edges[(small + 1) % 4]]) << where;
        }
        // Every crease other than a side is axis-parallel; every side has length `side`.
        for (int e = 0; e < p.num_edges(); ++e) {
          const Eigen::Vector3d d = p.vertices[p.edges[e][1]] - p.vertices[p.edges[e][0]];
          if (e < 4 * mn) {
            EXPECT_NEAR(d.norm(), sp.side, 1e-12) << where;
          } else {
            EXPECT_NEAR(std::min(std::fabs(d.x()), std::fabs(d.y())), 0.0, 1e-12) << where << " edge " << e;
          }
          EXPECT_EQ(p.assignments[e] == Assignment::Boundary, !topo.edge_is_hinge[e]) << where;
        }
        // Twist (1, 0) is the mirror image of twist (0, 0) in x = spacing / 2.
        if (cols > 1) {
          for (int k = 0; k < 4; ++k) {
            EXPECT_NEAR(p.vertices[4 + k].x(), sp.spacing - p.vertices[k].x(), 1e-12) << where;
            EXPECT_NEAR(p.vertices[4 + k].y(), p.vertices[k].y(), 1e-12) << where;
          }
        }
      }
}

TEST(GeneratorSquareTwistTessellation, OneByOneIsTheSquareTwistInASquareSheet) {
  // Same twist vertices, same first 12 edges (sides, then o_a o_b of A..D).
  const auto sp = params(1, 1, 30, Layout::Type4);
  const CreasePattern p = generators::square_twist_tessellation(sp);
  generators::SquareTwistParams single;
  single.twist = sp.twist;
  single.side = sp.side;
  const auto sides = generators::square_twist_tessellation_twist_sides(Layout::Type4, 0);
  const CreasePattern q = generators::square_twist(single, generators::square_twist_assignment(sides));
  for (int v = 0; v < 4; ++v) EXPECT_LE((p.vertices[v] - q.vertices[v]).norm(), 1e-12);
  for (int e = 0; e < 12; ++e) {
    EXPECT_EQ(p.edges[e][0], q.edges[e][0]) << e;
    EXPECT_EQ(p.assignments[e], q.assignments[e]) << e;
    const Eigen::Vector3d dp = (p.vertices[p.edges[e][1]] - p.vertices[p.edges[e][0]]).normalized();
    const Eigen::Vector3d dq = (q.vertices[q.edges[e][1]] - q.vertices[q.edges[e][0]]).normalized();
    EXPECT_LE((dp - dq).norm(), 1e-12) << e;
  }
}

TEST(GeneratorSquareTwistTessellation, LayoutsFollowTheHeaderRule) {
  using S = std::array<Assignment, 4>;
  EXPECT_EQ(generators::square_twist_tessellation_twist_sides(Layout::Type4, 3), (S{V, M, M, M}));
  EXPECT_EQ(generators::square_twist_tessellation_twist_sides(Layout::Type3Rows, 0), (S{V, M, M, V}));
  EXPECT_EQ(generators::square_twist_tessellation_twist_sides(Layout::Type3Rows, 1), (S{M, V, V, M}));
  EXPECT_EQ(generators::square_twist_tessellation_twist_sides(Layout::AllType1, 2), (S{M, M, M, M}));
  EXPECT_EQ(generators::square_twist_tessellation_twist_sides(Layout::AllType2, 2), (S{V, M, V, M}));
  for (Layout l : kRigid) EXPECT_EQ(generators::square_twist_tessellation_dof(l), 1);
  for (Layout l : kNotRigid) EXPECT_EQ(generators::square_twist_tessellation_dof(l), 0);
  for (Layout l : {Layout::Type4, Layout::Type3Rows, Layout::AllType1, Layout::AllType2})
    EXPECT_EQ(generators::square_twist_tessellation_layout_from_string(generators::to_string(l)), l);
  // The outer creases follow the single-twist rule at every vertex (o_a = previous side;
  // o_b = previous side if the sides differ, else its opposite). Edge order: the first
  // crease made at a vertex slot is o_a, so check by direction instead: the crease leaving
  // vertex k of an unmirrored twist along (k-1) pi/2 is o_a.
  const auto sp = params(3, 2, 40, Layout::Type3Rows);
  const CreasePattern p = generators::square_twist_tessellation(sp);
  const auto sides = generators::square_twist_tessellation_sides(sp);
  for (int w = 0; w < 6; ++w) {
    const int i = w % 2, j = w / 2;
    const double flip = (i + j) % 2 ? -1 : 1;  // mirrored twists negate x
    for (int k = 0; k < 4; ++k) {
      const int v = 4 * w + k;
      const Assignment prev = sides[w][(k + 3) % 4], twist_side = sides[w][k];
      const Assignment o_a = prev, o_b = prev != twist_side ? prev : (prev == M ? V : M);
      const Eigen::Vector2d da(flip * std::cos((k - 1) * kPi / 2), std::sin((k - 1) * kPi / 2));
      const Eigen::Vector2d db(flip * std::cos(k * kPi / 2), std::sin(k * kPi / 2));
      int found = 0;
      for (int e = 4 * 6; e < p.num_edges(); ++e) {
        if (p.assignments[e] == Assignment::Boundary) continue;
        const int a = p.edges[e][0], b = p.edges[e][1];
        if (a != v && b != v) continue;
        const Eigen::Vector3d d3 = p.vertices[a == v ? b : a] - p.vertices[v];
        const Eigen::Vector2d d = d3.head<2>().normalized();
        if ((d - da).norm() < 1e-9) {
          EXPECT_EQ(p.assignments[e], o_a) << "twist " << w << " vertex " << k;
          ++found;
        }
        if ((d - db).norm() < 1e-9) {
          EXPECT_EQ(p.assignments[e], o_b) << "twist " << w << " vertex " << k;
          ++found;
        }
      }
      EXPECT_EQ(found, 2) << "twist " << w << " vertex " << k;
    }
  }
}

// The exact multiplier model: rigid layouts fold with 1 DOF at every size and twist angle,
// every face loop with gain 1, and the certificate's faces close.
TEST(GeneratorSquareTwistTessellation, MultiplierModelRigidLayoutsOneDof) {
  for (auto [rows, cols] : {std::pair{1, 1}, {2, 2}, {3, 3}, {4, 5}})
    for (double t : {15.0, 30.0, 45.0, 60.0, 75.0})
      for (Layout layout : kRigid) {
        const auto sp = params(rows, cols, t, layout);
        const std::string where = name(sp);
        const CreasePattern p = generators::square_twist_tessellation(sp);
        const Topology topo = build_topology(p);
        ASSERT_TRUE(multiplier_model_applicable(p, topo).applicable) << where;
        const FoldabilityVerdict v = verdict_with_assignment(p, topo);
        ASSERT_EQ(v.verdict, Verdict::kRigidlyFoldable) << where << ": " << v.reason;
        EXPECT_EQ(v.dof, 1) << where;
        EXPECT_EQ(v.dof, generators::square_twist_tessellation_dof(layout)) << where;
        EXPECT_LE(v.max_loop_defect, 1e-12) << where;
        EXPECT_LE(v.certificate_mismatch, 1e-12) << where;
        // Every crease folds (no crease pinned flat) and with its letter's sign.
        ASSERT_TRUE(v.family.has_value());
        const Eigen::VectorXd rho = v.family->angles(0.5);
        for (int e = 0; e < p.num_edges(); ++e) {
          if (p.assignments[e] != Assignment::Boundary) {
            EXPECT_GT(rho[e] * sign_of(p.assignments[e]), 0.0) << where;
          }
        }
        // First-principles check, independent of the kernel's model: the test helper's
        // propagation of the multipliers closes every vertex loop.
        if (rows * cols <= 9) {
          const auto w = propagate_multipliers(p, topo);
          ASSERT_TRUE(w.has_value()) << where;
          const auto r = folds_from_multipliers(*w, 0.7);
          for (int vtx : topo.interior_vertices) EXPECT_LE(loop_residual(topo, vtx, r), 1e-12) << where;
          EXPECT_LE(place(p, topo, r).mismatch, 1e-12) << where;
        }
      }
}

// 1 x 1: the same verdict, DOF and fold angles as the single square twist of the same type.
TEST(GeneratorSquareTwistTessellation, OneByOneEqualsSingleSquareTwistVerdict) {
  for (Layout layout : {Layout::Type4, Layout::Type3Rows, Layout::AllType1, Layout::AllType2}) {
    const auto sp = params(1, 1, 35, layout);
    const CreasePattern p = generators::square_twist_tessellation(sp);
    generators::SquareTwistParams single;
    single.twist = sp.twist;
    single.side = sp.side;
    const CreasePattern q = generators::square_twist(
        single, generators::square_twist_assignment(generators::square_twist_tessellation_twist_sides(layout, 0)));
    const FoldabilityVerdict vp = verdict_with_assignment(p, build_topology(p));
    const FoldabilityVerdict vq = verdict_with_assignment(q, build_topology(q));
    EXPECT_EQ(vp.verdict, vq.verdict) << name(sp);
    EXPECT_EQ(vp.dof, vq.dof) << name(sp);
    if (vp.verdict != Verdict::kRigidlyFoldable) continue;
    for (double side0 : {0.2, 1.0, 2.5}) {
      const double signed0 = side0 * sign_of(p.assignments[0]);
      const Eigen::VectorXd a = vp.family->angles(vp.family->parameter_for(0, signed0));
      const Eigen::VectorXd b = vq.family->angles(vq.family->parameter_for(0, signed0));
      for (int e = 0; e < 12; ++e) EXPECT_NEAR(a[e], b[e], 1e-12) << name(sp) << " edge " << e;
    }
  }
}

// Among the 16 "every twist alike" side patterns of a 2 x 2 sheet, the consistent and rigid
// ones are exactly Type 4 with BC = DA (V M M M, M M V M and their flips), as derived in the
// header; the others either give a pleat two letters or fail a loop.
TEST(GeneratorSquareTwistTessellation, UniformSidePatternsRigidExactlyForType4WithBcEqualDa) {
  const auto sp = params(2, 2, 30, Layout::Type4);
  std::set<std::string> rigid;
  int consistent = 0;
  for (int mask = 0; mask < 16; ++mask) {
    std::array<Assignment, 4> s{};
    for (int k = 0; k < 4; ++k) s[k] = (mask >> k) & 1 ? V : M;
    CreasePattern p;
    try {
      p = generators::square_twist_tessellation(sp, std::vector<std::array<Assignment, 4>>(4, s));
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), "sides");
      continue;
    }
    ++consistent;
    const FoldabilityVerdict v = verdict_with_assignment(p, build_topology(p));
    if (v.verdict == Verdict::kRigidlyFoldable) {
      EXPECT_EQ(v.dof, 1);
      rigid.insert(generators::assignment_letters(std::vector<Assignment>(s.begin(), s.end())));
    } else {
      EXPECT_EQ(v.verdict, Verdict::kNotRigidlyFoldable);
    }
  }
  EXPECT_EQ(consistent, 8);  // BC = DA and o_b(B) = o_b(D)
  EXPECT_EQ(rigid, (std::set<std::string>{"VMMM", "MMVM", "MVVV", "VVMV"}));
}

// The general loop-closure solver (any pattern) agrees with the multiplier model on 2 x 2:
// rigidly foldable, 1 DOF, and every traced state lies on the multiplier family at the same
// driving-crease angle.
TEST(GeneratorSquareTwistTessellation, GeneralSolverAgreesWithMultiplierModel2x2) {
  for (Layout layout : kRigid)
    for (double t : {20.0, 60.0}) {
      const auto sp = params(2, 2, t, layout);
      const std::string where = name(sp);
      const CreasePattern p = generators::square_twist_tessellation(sp);
      const Topology topo = build_topology(p);
      const FoldabilityVerdict mv = verdict_with_assignment(p, topo);
      ASSERT_EQ(mv.verdict, Verdict::kRigidlyFoldable) << where;
      const GeneralVerdict g = general_verdict(p, topo);
      ASSERT_EQ(g.verdict, Verdict::kRigidlyFoldable) << where << ": " << g.reason;
      EXPECT_EQ(g.trace.dof_at_departure, mv.dof) << where;
      EXPECT_EQ(g.trace.dof_at_departure, 1) << where;
      EXPECT_LE(g.trace.max_residual, 1e-12) << where;
      EXPECT_LE(g.certificate_mismatch, 1e-10) << where;
      double worst = 0;
      int compared = 0;
      for (const Eigen::VectorXd& rho : g.trace.path) {
        if (rho.cwiseAbs().maxCoeff() > 2.8) continue;  // tan(rho/2) blows up near the flat-folded end
        const double tau = mv.family->parameter_for(g.trace.driving_edge, rho[g.trace.driving_edge]);
        worst = std::max(worst, (mv.family->angles(tau) - rho).cwiseAbs().maxCoeff());
        ++compared;
      }
      EXPECT_GE(compared, 3) << where;
      EXPECT_LE(worst, 1e-10) << where;
      char value[32];
      std::snprintf(value, sizeof value, "%.3g", worst);
      RecordProperty("path_vs_family_" + std::string(generators::to_string(layout)) + "_" +
                         std::to_string(static_cast<int>(t)),
                     value);
    }
}

// Rank of the closure Jacobian at a folded state of the multiplier family: 1 DOF, on a
// sheet larger than the general verdict's test (3 x 3 and 4 x 5).
TEST(GeneratorSquareTwistTessellation, ClosureJacobianHasOneDofAtFoldedState) {
  for (auto [rows, cols] : {std::pair{3, 3}, {4, 5}})
    for (Layout layout : kRigid) {
      const auto sp = params(rows, cols, 50, layout);
      const std::string where = name(sp);
      const CreasePattern p = generators::square_twist_tessellation(sp);
      const Topology topo = build_topology(p);
      const FoldabilityVerdict mv = verdict_with_assignment(p, topo);
      ASSERT_EQ(mv.verdict, Verdict::kRigidlyFoldable) << where;
      const ClosureSystem sys(p, topo);
      const double rho0 = 0.9 * sign_of(p.assignments[0]);
      const Eigen::VectorXd x = sys.unknowns_from_edges(mv.family->angles(mv.family->parameter_for(0, rho0)));
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> J;
      sys.evaluate(x, r, J);
      EXPECT_LE(r.lpNorm<Eigen::Infinity>(), 1e-12) << where;
      EXPECT_EQ(jacobian_rank(J).dof, 1) << where;
    }
}

// The non-rigid counterparts: the multiplier model proves 0 DOF (a loop-gain obstruction
// of mu^(4k), the central squares' gain), at every size; the general solver finds no
// folded state with the letters on 2 x 2.
TEST(GeneratorSquareTwistTessellation, NonRigidLayoutsHaveZeroDof) {
  for (auto [rows, cols] : {std::pair{1, 1}, {2, 2}, {3, 3}, {4, 5}})
    for (double t : {15.0, 45.0, 75.0})
      for (Layout layout : kNotRigid) {
        const auto sp = params(rows, cols, t, layout);
        const std::string where = name(sp);
        const CreasePattern p = generators::square_twist_tessellation(sp);
        const Topology topo = build_topology(p);
        const FoldabilityVerdict v = verdict_with_assignment(p, topo);
        ASSERT_EQ(v.verdict, Verdict::kNotRigidlyFoldable) << where << ": " << v.reason;
        EXPECT_EQ(v.dof, 0) << where;
        ASSERT_TRUE(v.obstruction.has_value()) << where;
        EXPECT_EQ(v.obstruction->kind, Obstruction::Kind::kLoopGain) << where;
        const double k = std::log(v.obstruction->loop_gain) / std::log(std::pow(mu(sp.twist), 4));
        EXPECT_NEAR(k, std::round(k), 1e-9) << where;
        EXPECT_NE(std::lround(k), 0) << where;
      }
  for (Layout layout : kNotRigid) {
    const auto sp = params(2, 2, 30, layout);
    const CreasePattern p = generators::square_twist_tessellation(sp);
    const GeneralVerdict g = general_verdict(p, build_topology(p));
    EXPECT_EQ(g.verdict, Verdict::kNotRigidlyFoldable) << name(sp) << ": " << g.reason;
    EXPECT_FALSE(g.is_proof);
  }
}

TEST(GeneratorSquareTwistTessellation, BadParametersNameTheParameter) {
  auto place_of = [](const SquareTwistTessellationParams& sp) -> std::string {
    try {
      generators::square_twist_tessellation(sp);
    } catch (const InputError& e) {
      return e.place();
    }
    return "(no error)";
  };
  auto with = [](auto change) {
    auto sp = params(2, 2, 30, Layout::Type4);
    change(sp);
    return sp;
  };
  EXPECT_EQ(place_of(with([](auto& s) { s.rows = 0; })), "rows");
  EXPECT_EQ(place_of(with([](auto& s) { s.rows = 501; })), "rows");
  EXPECT_EQ(place_of(with([](auto& s) { s.cols = -3; })), "cols");
  EXPECT_EQ(place_of(with([](auto& s) { s.twist = 0; })), "twist");
  EXPECT_EQ(place_of(with([](auto& s) { s.twist = kPi / 2; })), "twist");
  EXPECT_EQ(place_of(with([](auto& s) { s.twist = std::nan(""); })), "twist");
  EXPECT_EQ(place_of(with([](auto& s) { s.side = 0; })), "side");
  EXPECT_EQ(place_of(with([](auto& s) { s.side = -1; })), "side");
  EXPECT_EQ(place_of(with([](auto& s) { s.spacing = s.side * (std::sin(s.twist) + std::cos(s.twist)); })),
            "spacing");
  EXPECT_EQ(place_of(with([](auto& s) { s.spacing = std::numeric_limits<double>::infinity(); })), "spacing");
  // Explicit sides: wrong count, a letter other than M/V, letters that disagree on a pleat.
  const auto sp = params(2, 2, 30, Layout::Type4);
  auto sides_place = [&](const std::vector<std::array<Assignment, 4>>& sides) -> std::string {
    try {
      generators::square_twist_tessellation(sp, sides);
    } catch (const InputError& e) {
      return e.place();
    }
    return "(no error)";
  };
  const std::array<Assignment, 4> good{V, M, M, M};
  EXPECT_EQ(sides_place(std::vector<std::array<Assignment, 4>>(3, good)), "sides");
  EXPECT_EQ(sides_place({good, good, good, {V, M, Assignment::Flat, M}}), "sides");
  // Twist (1, 1) with CD = V: its o_a at D (= CD) meets the left neighbour's o_a at D (= M).
  EXPECT_EQ(sides_place({good, good, good, {M, M, V, M}}), "sides");
  EXPECT_EQ(sides_place(std::vector<std::array<Assignment, 4>>(4, good)), "(no error)");
  EXPECT_THROW(generators::square_twist_tessellation_layout_from_string("type5"), InputError);
  try {
    generators::square_twist_tessellation_layout_from_string("rigid");
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "layout");
  }
}

}}  // namespace
}  // namespace rigidfold::test
