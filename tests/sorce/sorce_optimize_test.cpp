// SORCE inverse design (seed 002 section 7, digest section 4): optimize_offsets on vertex A
// (eq 35 fold angles, eq 36 offsets with the eq 37 bases, thickness 1), b = (b_i, b_o).
// Every claim about a returned design is re-measured here by fold_report at 2001 samples
// (the optimiser samples 201), not taken from the optimiser's own flags.
#include "design/sorce/sorce_optimize.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "kernel/pattern/input_error.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

// z_outer = -1.5 (t + sum b_o B) on panels 1 and 4, z_inner = 0.5 (t + sum b_i B) on panels 2
// and 3 (eq 36, d = 1); b = (b_i1, b_i2, b_i3, b_o1, b_o2, b_o3).
std::vector<FoldMotion> vertex_a_motions(const std::vector<double>& b) {
  const VertexSectors a = testing::vertex_a_sectors();
  const auto gamma = vertex_fold_angles(a, VertexParameterization::kSymmetric);
  const std::vector<double> bi(b.begin(), b.begin() + 3), bo(b.begin() + 3, b.end());
  const ScalarFunction outer = basis_offset(-1.5, bo, seed_offset_bases());
  const ScalarFunction inner = basis_offset(0.5, bi, seed_offset_bases());
  const SorceVertex v = sorce_vertex(a, gamma, {outer, inner, inner, outer}, {1, 1, 1, 1});
  return {v.folds.begin(), v.folds.end()};
}

// The seed's eq 39 coefficients with the signs recovered in sorce_seed_coefficients_test.cpp.
const std::vector<double> kSeedB = {0.322657, 0.0885048, -0.814152, 0.876535, -0.32912, 0.184345};

OffsetDesignProblem vertex_a_problem(double epsilon) {
  OffsetDesignProblem p;
  p.motions = vertex_a_motions;
  p.lower.assign(6, -2.0);
  p.upper.assign(6, 2.0);
  p.epsilon = epsilon;
  return p;
}

// Independent measurement of b.
struct Check {
  double min_convexity = INFINITY, max_convexity = -INFINITY, max_abs_s0 = 0.0, fom = 0.0;
  std::size_t cusps = 0, undefined = 0;
  std::vector<FoldReport> folds;
};

Check check(const std::vector<double>& b, double epsilon) {
  Check c;
  for (const FoldMotion& m : vertex_a_motions(b)) {
    const FoldReport r = fold_report(m, {2001});
    c.min_convexity = std::min({c.min_convexity, r.min_convexity_left, r.min_convexity_right});
    c.max_convexity = std::max({c.max_convexity, r.max_convexity_left, r.max_convexity_right});
    c.max_abs_s0 = std::max(c.max_abs_s0, std::abs(r.s0));
    c.cusps += r.cusps.size();
    c.undefined += r.ill_behaved.size() + r.stationary.size();
    c.folds.push_back(r);
  }
  c.fom = figure_of_merit(c.folds, epsilon);
  return c;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(SorceOptimize, FromTheSeedCoefficientsLowersTheFigureOfMerit) {
  const double epsilon = 0.01;
  const Check seed = check(kSeedB, epsilon);
  // Setup sanity: the seed's design is all convex with FOM 55.3 (seed section 7).
  ASSERT_GT(seed.min_convexity, epsilon);
  ASSERT_GE(seed.fom, 50.0);
  ASSERT_LE(seed.fom, 60.0);

  const auto t0 = std::chrono::steady_clock::now();
  const OffsetDesign d = optimize_offsets(vertex_a_problem(epsilon), kSeedB);
  const double elapsed = seconds_since(t0);
  EXPECT_TRUE(d.feasible);
  EXPECT_EQ(d.algorithm, "LN_COBYLA");
  EXPECT_GT(d.evaluations, 6);
  EXPECT_LE(d.evaluations, OffsetOptimizeOptions{}.max_evaluations);

  const Check c = check(d.b, epsilon);
  EXPECT_GE(c.min_convexity, epsilon);
  EXPECT_TRUE(std::isfinite(c.max_convexity));
  EXPECT_EQ(c.cusps, 0u);
  EXPECT_EQ(c.undefined, 0u);
  EXPECT_LT(c.fom, seed.fom);
  // The optimiser's own FOM (201 samples) agrees with the independent one to the sampling.
  EXPECT_NEAR(d.fom, c.fom, 1e-3 * c.fom);
  std::printf("seed start: FOM %.4f -> %.4f (2001 samples: %.4f), %d evaluations, %s, %.2f s\n", seed.fom, d.fom, c.fom,
              d.evaluations, d.stop_reason.c_str(), elapsed);
}

TEST(SorceOptimize, FromLinearOffsetsReachesAnAllConvexDesign) {
  const double epsilon = 0.01;
  const std::vector<double> zero(6, 0.0);
  // The start is not a valid design: fold 2 (index 1) has a concave span, and folds 1 and 3
  // pivot at t = 1 (infinite convexities).
  const Check start = check(zero, epsilon);
  ASSERT_FALSE(start.folds[1].concave_left.empty() && start.folds[1].concave_right.empty());
  ASSERT_LT(start.min_convexity, 0.0);

  const auto t0 = std::chrono::steady_clock::now();
  const OffsetDesign d = optimize_offsets(vertex_a_problem(epsilon), zero);
  const double elapsed = seconds_since(t0);
  EXPECT_TRUE(d.feasible);
  EXPECT_TRUE(d.improved);

  const Check c = check(d.b, epsilon);
  EXPECT_GE(c.min_convexity, epsilon);
  EXPECT_TRUE(std::isfinite(c.max_convexity));
  EXPECT_EQ(c.cusps, 0u);
  EXPECT_EQ(c.undefined, 0u);
  for (const FoldReport& f : c.folds) {
    EXPECT_TRUE(f.concave_left.empty());
    EXPECT_TRUE(f.concave_right.empty());
    EXPECT_FALSE(f.pivot_at_start || f.pivot_at_end);
  }
  EXPECT_TRUE(std::isfinite(c.fom));
  std::printf("linear start: FOM %.4f (2001 samples: %.4f), min c %.4g, %d evaluations, %s, %.2f s\n", d.fom, c.fom,
              c.min_convexity, d.evaluations, d.stop_reason.c_str(), elapsed);
}

TEST(SorceOptimize, ReportsTheBindingS0Bound) {
  // The seed's design has |s0| = 0.568 on folds 2 and 4 (index 1, 3; 0 on folds 1, 3 by the
  // vertex's symmetry): a bound of 0.4 cuts it off, and the best design should sit on it.
  const double epsilon = 0.01, bound = 0.4;
  ASSERT_GT(check(kSeedB, epsilon).max_abs_s0, bound);
  OffsetDesignProblem p = vertex_a_problem(epsilon);
  p.max_abs_s0 = bound;
  const OffsetOptimizeOptions options;
  const OffsetDesign d = optimize_offsets(p, kSeedB, options);
  ASSERT_TRUE(d.feasible);

  const Check c = check(d.b, epsilon);
  EXPECT_GE(c.min_convexity, epsilon);
  EXPECT_EQ(c.cusps, 0u);
  EXPECT_LE(c.max_abs_s0, bound);
  int s0_binding = 0;
  for (const BindingConstraint& k : d.binding) {
    if (k.name != "s0") continue;
    ++s0_binding;
    ASSERT_GE(k.index, 0);
    ASSERT_LT(k.index, 4);
    EXPECT_EQ(k.bound, bound);
    // Re-measured: that fold's |s0| is at the bound within the stated relative tolerance.
    const double s0 = std::abs(c.folds[static_cast<std::size_t>(k.index)].s0);
    EXPECT_NEAR(s0, bound, options.binding_tolerance * bound);
    EXPECT_NEAR(k.value, s0, 1e-12);
  }
  EXPECT_GE(s0_binding, 1);
  // Nothing else is reported binding that is not: every reported convexity bound is re-measured.
  for (const BindingConstraint& k : d.binding) {
    if (k.name == "convexity_left" || k.name == "convexity_right") {
      const FoldReport& f = c.folds[static_cast<std::size_t>(k.index)];
      const double v = k.name == "convexity_left" ? f.min_convexity_left : f.min_convexity_right;
      EXPECT_NEAR(v, epsilon, 2 * options.binding_tolerance * epsilon);
    }
  }
  std::printf("s0 <= %.2f: FOM %.4f, max |s0| %.6f, %zu binding, %d evaluations, %s\n", bound, d.fom, c.max_abs_s0,
              d.binding.size(), d.evaluations, d.stop_reason.c_str());
}

TEST(SorceOptimize, UnreachableProtrusionBoundIsReportedInfeasible) {
  // On vertex A the outer panels end at z(1) = -1.5 whatever b is (eq 36 keeps the end
  // values), so fold 1's profiles end 1.5 from the mid-plane, 1.0 beyond a face of the unit
  // slab: a protrusion bound of 0.5 cannot be met, and the result must say so.
  const double epsilon = 0.01, bound = 0.5;
  OffsetDesignProblem p = vertex_a_problem(epsilon);
  p.max_protrusion = bound;
  OffsetOptimizeOptions options;
  options.max_evaluations = 60;
  const OffsetDesign d = optimize_offsets(p, kSeedB, options);
  EXPECT_FALSE(d.feasible);
  EXPECT_LE(d.evaluations, 60);
  EXPECT_GT(d.max_protrusion, bound);
  double protrusion = 0.0;
  for (const FoldReport& f : check(d.b, epsilon).folds)
    protrusion = std::max({protrusion, f.protrusion_left, f.protrusion_right});
  EXPECT_NEAR(protrusion, 1.0, 1e-9);
  EXPECT_NEAR(d.max_protrusion, protrusion, 1e-9);
  // Deterministic: the same run again returns the same design.
  const OffsetDesign again = optimize_offsets(p, kSeedB, options);
  EXPECT_EQ(again.b, d.b);
  EXPECT_EQ(again.evaluations, d.evaluations);
}

template <class F>
void expect_input_error(F&& f, const std::string& place) {
  try {
    f();
    ADD_FAILURE() << "no InputError, expected place " << place;
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), place) << e.what();
  }
}

TEST(SorceOptimize, BadInputThrowsInputErrorWithItsPlace) {
  const OffsetDesignProblem p = vertex_a_problem(0.01);
  expect_input_error([&] { optimize_offsets(p, std::vector<double>(5, 0.0)); }, "start");
  expect_input_error([&] { optimize_offsets(p, std::vector<double>(6, 3.0)); }, "start");  // outside the box
  OffsetDesignProblem inverted = p;
  std::swap(inverted.lower[2], inverted.upper[2]);
  expect_input_error([&] { optimize_offsets(inverted, kSeedB); }, "bounds");
  OffsetDesignProblem short_bounds = p;
  short_bounds.upper.pop_back();
  expect_input_error([&] { optimize_offsets(short_bounds, kSeedB); }, "bounds");
  OffsetDesignProblem negative = p;
  negative.epsilon = -0.1;
  expect_input_error([&] { optimize_offsets(negative, kSeedB); }, "epsilon");
  OffsetDesignProblem no_builder = p;
  no_builder.motions = nullptr;
  expect_input_error([&] { optimize_offsets(no_builder, kSeedB); }, "motions");
  OffsetDesignProblem s0 = p;
  s0.max_abs_s0 = -1.0;
  expect_input_error([&] { optimize_offsets(s0, kSeedB); }, "max_abs_s0");
  OffsetOptimizeOptions o;
  o.max_evaluations = 0;
  expect_input_error([&] { optimize_offsets(p, kSeedB, o); }, "options");
  expect_input_error([&] { evaluate_offsets(p, std::vector<double>(7, 0.0)); }, "b");
}

}}  // namespace
}  // namespace rigidfold::sorce
