// The closure gap the rounding of the coordinates can cause (kernel/analysis/
// rounding_residual_bound.hpp), float32 coordinates (coordinate_precision.hpp), and the
// norm-constrained search (kernel/solve/amplitude_search.hpp) the verdict's evidence uses.
// The exact Miura-ori is known in closed form here, so the bound is checked against the gap
// the rounding really leaves at exact states, not assumed.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>

#include "data/generators/miura.hpp"
#include "kernel/analysis/general_verdict.hpp"
#include "kernel/analysis/rounding_residual_bound.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/closure/vertex_residuals.hpp"
#include "kernel/pattern/coordinate_precision.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/validate_pattern.hpp"
#include "kernel/solve/amplitude_search.hpp"
#include "kernel/solve/portable_random.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

generators::MiuraParams miura_3x3(double perturbation = 0.0) {
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  m.a = 0.7;
  m.b = 1.3;
  m.perturbation = perturbation;
  m.seed = 5;
  return m;
}

// The pattern with every coordinate replaced by its nearest float32, as a float32 writer would.
CreasePattern as_float32(CreasePattern p) {
  for (Eigen::Vector3d& v : p.vertices)
    for (int k = 0; k < 3; ++k) v[k] = static_cast<double>(static_cast<float>(v[k]));
  return p;
}

CreasePattern rounded_to_decimals(CreasePattern p, int decimals) {
  const double s = std::pow(10.0, decimals);
  for (Eigen::Vector3d& v : p.vertices)
    for (int k = 0; k < 3; ++k) v[k] = std::round(v[k] * s) / s;
  return p;
}

TEST(CoordinatePrecision, Float32CoordinatesAreReadAsSinglePrecision) {
  const CreasePattern exact = generators::miura_ori(miura_3x3());
  const CoordinatePrecision pe = coordinate_precision(exact);
  EXPECT_FALSE(pe.rounded);
  EXPECT_FALSE(pe.single_precision);
  const CreasePattern p = as_float32(exact);
  const CoordinatePrecision pf = coordinate_precision(p);
  EXPECT_TRUE(pf.rounded);
  EXPECT_TRUE(pf.single_precision);
  double scale = 0.0;
  for (const Eigen::Vector3d& v : p.vertices) scale = std::max(scale, v.cwiseAbs().maxCoeff());
  EXPECT_NEAR(pf.max_rounding, std::ldexp(scale, -24), std::ldexp(scale, -50));
  // Every coordinate's true (double) value lies within its bound.
  for (std::size_t i = 0; i < p.vertices.size(); ++i)
    EXPECT_LE((p.vertices[i] - exact.vertices[i]).cwiseAbs().maxCoeff(), pf.vertex_rounding[i]) << "vertex " << i;
  // Short decimals stay decimals, even though 0.5 and 0.25 are float32 values too.
  const CoordinatePrecision pd = coordinate_precision(rounded_to_decimals(exact, 3));
  EXPECT_FALSE(pd.single_precision);
  EXPECT_EQ(pd.decimal_places, 3);
  EXPECT_NE(describe_precision(pf).find("float32"), std::string::npos);
}

// At exact states of the true Miura the rounded file's gap is within the bound, at every
// vertex, and the bound is not vacuous (the gap reaches a sizeable part of it somewhere).
TEST(RoundingResidualBound, HoldsAtExactStatesOfTheTruePatternAndIsNotVacuous) {
  const generators::MiuraParams m = miura_3x3();
  const CreasePattern exact = generators::miura_ori(m);
  for (int form = 0; form < 2; ++form) {
    const CreasePattern p = form == 0 ? as_float32(exact) : rounded_to_decimals(exact, 4);
    const Topology t = build_topology(p);
    double largest_ratio = 0.0;
    for (double fold : {0.01, 0.1, 0.5, 1.5}) {
      const Eigen::VectorXd rho = testing::miura_edge_angles(exact, m, fold);
      const RoundingResidualCheck c = rounding_explains_residual(p, t, rho);
      EXPECT_TRUE(c.explained) << (form ? "4 decimals" : "float32") << ", fold " << fold << ": ratio " << c.worst_ratio
                               << " at vertex " << c.worst_vertex;
      EXPECT_GT(max_vertex_closure_residual(t, rho), 0.0);  // the rounding did leave a gap
      largest_ratio = std::max(largest_ratio, c.worst_ratio);
    }
    std::cout << "    " << (form ? "4 decimals" : "float32") << ": largest gap / bound " << largest_ratio << "\n";
    EXPECT_GT(largest_ratio, 1e-3);
  }
}

// A gap the geometry forces is not explained: a Miura whose vertices moved by 1e-3, written as
// float32, judged at the exact Miura's state.
TEST(RoundingResidualBound, AGeometricGapIsNotExplained) {
  const generators::MiuraParams m = miura_3x3();
  const CreasePattern exact = generators::miura_ori(m);
  const CreasePattern moved = as_float32(generators::miura_ori(miura_3x3(1e-3)));
  const Topology t = build_topology(moved);
  const RoundingResidualCheck c = rounding_explains_residual(moved, t, testing::miura_edge_angles(exact, m, 0.5));
  EXPECT_FALSE(c.explained);
  EXPECT_GT(c.worst_ratio, 100.0);
}

// An SVG's vertices are computed from the drawn points (means, crossings) and carry no digits
// of their own; the bound must come from the box of the points drawn for each vertex. A Miura
// whose vertices moved by up to 1e-3 (full-precision numbers), each box +-2e-3 about the true
// vertex: the gap at the true pattern's states is explained by the boxes; without them the
// numbers read as exact and the same gap is not.
TEST(RoundingResidualBound, AnSvgsDrawnBoxesBoundItsComputedVertices) {
  const generators::MiuraParams m = miura_3x3();
  const CreasePattern exact = generators::miura_ori(m);
  CreasePattern drawn = exact;
  SplitMix64 rng{3};
  const double w = 1e-3;
  drawn.position_bounds.lo.resize(exact.vertices.size());
  drawn.position_bounds.hi.resize(exact.vertices.size());
  for (std::size_t i = 0; i < exact.vertices.size(); ++i) {
    for (int k = 0; k < 2; ++k) drawn.vertices[i][k] += w * (2 * rng.uniform() - 1);
    drawn.position_bounds.lo[i] = exact.vertices[i].head<2>() - Eigen::Vector2d::Constant(2 * w);
    drawn.position_bounds.hi[i] = exact.vertices[i].head<2>() + Eigen::Vector2d::Constant(2 * w);
  }
  drawn.position_bounds.max_half_width = 2 * w;
  CreasePattern undrawn = drawn;
  undrawn.position_bounds = {};
  const Topology t = build_topology(drawn);
  for (double fold : {0.1, 0.5}) {
    const Eigen::VectorXd rho = testing::miura_edge_angles(exact, m, fold);
    ASSERT_GT(max_vertex_closure_residual(t, rho), 1e-6);
    const RoundingResidualCheck with_boxes = rounding_explains_residual(drawn, t, rho);
    EXPECT_TRUE(with_boxes.explained) << fold << ": ratio " << with_boxes.worst_ratio;
    const RoundingResidualCheck as_numbers = rounding_explains_residual(undrawn, t, rho);
    EXPECT_FALSE(as_numbers.explained) << fold << ": ratio " << as_numbers.worst_ratio;
  }
}

// The letters as bounds (valley >= 0, mountain <= 0, at most a half turn) and a pseudo-random
// start on the letters' sides, per unknown.
struct LetterBox {
  Eigen::VectorXd lower, upper, start;
  std::vector<int> sign;
  LetterBox(const CreasePattern& p, const ClosureSystem& sys, std::uint64_t seed) {
    const int n = sys.num_unknowns();
    lower.resize(n);
    upper.resize(n);
    start.resize(n);
    sign.resize(n);
    SplitMix64 rng{seed};
    for (int i = 0; i < n; ++i) {
      sign[i] = assigned_fold_sign(p.assignments[sys.edge_of_unknown(i)]);
      lower[i] = sign[i] > 0 ? 0.0 : -M_PI;
      upper[i] = sign[i] < 0 ? 0.0 : M_PI;
      start[i] = sign[i] * (0.05 + rng.uniform());
    }
  }
};

// The norm search finds the Miura's one motion at the size asked for, from a letter-respecting
// start, with no crease held: the closed form's state at the same norm.
TEST(AmplitudeSearch, FindsTheMiuraStateOfTheGivenNorm) {
  const generators::MiuraParams m = miura_3x3();
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t);
  const LetterBox box(p, sys, 3);
  const Eigen::VectorXd &lower = box.lower, &upper = box.upper, &x0 = box.start;
  for (double eps : {0.3, 0.01}) {
    AmplitudeSearchOptions o;
    o.amplitude = eps;
    // Near flat the Jacobian's least nonzero singular value shrinks with the fold (~eps), so a
    // residual r leaves the state up to ~r / eps from the manifold: ask for 1e-14.
    o.tolerance = 1e-14;
    const AmplitudeSearchResult r = amplitude_search(sys, x0 * (eps / x0.norm()), lower, upper, o);
    ASSERT_TRUE(r.converged) << "eps " << eps << ": residual " << r.closure_residual << ", norm " << r.amplitude;
    EXPECT_LE(r.closure_residual, 1e-14);
    EXPECT_NEAR(r.amplitude, eps, 1e-14);
    // The closed form at the straight-crease angle that gives the same norm (bisection).
    auto norm_at = [&](double fold) { return sys.unknowns_from_edges(testing::miura_edge_angles(p, m, fold)).norm(); };
    double lo = 0.0, hi = 3.0;
    for (int it = 0; it < 200; ++it) (norm_at(0.5 * (lo + hi)) < eps ? lo : hi) = 0.5 * (lo + hi);
    const Eigen::VectorXd expected = sys.unknowns_from_edges(testing::miura_edge_angles(p, m, 0.5 * (lo + hi)));
    EXPECT_LE((r.x - expected).cwiseAbs().maxCoeff(), 1e-9 * eps) << "eps " << eps;
  }
}

// Logarithmic steps (lettered creases stepped in log|x|) reach the same closed-form state,
// every lettered crease strictly on its letter's side at every accepted point's end.
TEST(AmplitudeSearch, LogarithmicStepsFindTheSameMiuraStateKeepingEveryLetterStrictly) {
  const generators::MiuraParams m = miura_3x3();
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t);
  const int n = sys.num_unknowns();
  const LetterBox box(p, sys, 5);
  const Eigen::VectorXd &lower = box.lower, &upper = box.upper, &x0 = box.start;
  const std::vector<int>& sign = box.sign;
  for (double eps : {0.3, 0.01}) {
    AmplitudeSearchOptions o;
    o.amplitude = eps;
    o.tolerance = 1e-14;
    o.logarithmic = true;
    const AmplitudeSearchResult r = amplitude_search(sys, x0 * (eps / x0.norm()), lower, upper, o);
    ASSERT_TRUE(r.converged) << "eps " << eps << ": residual " << r.closure_residual << ", norm " << r.amplitude;
    EXPECT_NEAR(r.amplitude, eps, 1e-14);
    for (int i = 0; i < n; ++i)
      if (sign[i] != 0) {
        EXPECT_GT(sign[i] * r.x[i], 0.0) << i;
      }
    auto norm_at = [&](double fold) { return sys.unknowns_from_edges(testing::miura_edge_angles(p, m, fold)).norm(); };
    double lo = 0.0, hi = 3.0;
    for (int it = 0; it < 200; ++it) (norm_at(0.5 * (lo + hi)) < eps ? lo : hi) = 0.5 * (lo + hi);
    const Eigen::VectorXd expected = sys.unknowns_from_edges(testing::miura_edge_angles(p, m, 0.5 * (lo + hi)));
    EXPECT_LE((r.x - expected).cwiseAbs().maxCoeff(), 1e-9 * eps) << "eps " << eps;
  }
}

TEST(AmplitudeSearch, RejectsBadArguments) {
  const CreasePattern p = generators::miura_ori(miura_3x3());
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t);
  const int n = sys.num_unknowns();
  const Eigen::VectorXd z = Eigen::VectorXd::Zero(n), one = Eigen::VectorXd::Ones(n);
  AmplitudeSearchOptions o;
  EXPECT_THROW(amplitude_search(sys, Eigen::VectorXd::Zero(n + 1), -one, one, o), std::invalid_argument);
  EXPECT_THROW(amplitude_search(sys, z, one, -one, o), std::invalid_argument);
  o.amplitude = 0.0;
  EXPECT_THROW(amplitude_search(sys, z, -one, one, o), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// The verdict on a pattern whose motion needs its exact geometry (a Miura-ori turned by 0.3
// rad in its plane, so that no crease line stays parallel to an axis), written with 4
// decimals: the rounding leaves no exact motion (unturned, it would keep every straight line
// straight, and the pattern folds), the searches close only to the rounding's gap, and that
// gap is no evidence of rigidity. The same geometry in double precision folds (certified),
// and a gap the geometry forces (vertices moved by 1e-2, float32) is still evidence.
TEST(GeneralVerdictRounding, RoundedMiuraIsNotCalledRigid) {
  generators::MiuraParams m = miura_3x3();
  m.rows = m.cols = 4;
  CreasePattern exact = generators::miura_ori(m);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (Eigen::Vector3d& v : exact.vertices) v = turn * v;
  {
    const GeneralVerdict g = general_verdict(exact, build_topology(exact));
    EXPECT_EQ(g.verdict, Verdict::kRigidlyFoldable) << g.reason;
  }
  const CreasePattern p = rounded_to_decimals(exact, 4);
  const GeneralVerdict g = general_verdict(p, build_topology(p));
  std::cout << "    turned Miura 4x4 at 4 decimals: " << g.reason << "\n";
  EXPECT_EQ(g.verdict, Verdict::kUndecided) << g.reason;
  ASSERT_FALSE(g.evidence.empty()) << g.reason;
  EXPECT_TRUE(g.evidence[0].explained_by_rounding);
  EXPECT_GT(g.evidence[0].least_residual, 1e-12);  // the rounding did leave a gap

  m.perturbation = 1e-2;
  const CreasePattern bent = as_float32(generators::miura_ori(m));
  const GeneralVerdict gb = general_verdict(bent, build_topology(bent));
  std::cout << "    perturbed float32 Miura 4x4: " << gb.reason << "\n";
  EXPECT_EQ(gb.verdict, Verdict::kNotRigidlyFoldable) << gb.reason;
  ASSERT_FALSE(gb.evidence.empty());
  EXPECT_FALSE(gb.evidence[0].explained_by_rounding);
}

}}  // namespace
}  // namespace rigidfold
