// The SORCE front door's path (design/sorce/sorce_design.hpp): the multiplier model's exact
// fold angles where it traces the pattern, so that no diagnostic depends on the step count,
// and otherwise a splined path refined until the joints' diagnostics settle, or said not to. Oracle: the
// seed's vertex A (sorce_vertex.hpp, whose end points are eq 28's to 1e-14,
// sorce_profile_test.cpp) with its eq 4 offsets.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "design/sorce/sorce_design.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

const std::string kVertexAFile = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/sorce/vertex_a.fold";
constexpr double kThickness = 0.1;

// As `rigidfold sorce data/sorce/vertex_a.fold --thickness 0.1 --drive 1 --to 180` asks it.
SorceDesign vertex_a_design(int steps, bool general) {
  SorceDesignRequest rq;
  rq.sorce.thickness = kThickness;
  rq.sorce.trace.drive = 1;
  rq.sorce.trace.to = M_PI;
  rq.sorce.trace.steps = steps;
  rq.sorce.trace.force_general = general;
  rq.sorce.check_interference = false;
  return sorce_design(read_fold(kVertexAFile), rq);
}

// Every diagnostic of `got` as the analytic vertex's fold reports give it; end points within
// `ends` of eq 28.
void expect_analytic_diagnostics(const SorceDesign& got, double ends, const std::string& what) {
  const SorceVertex v = testing::vertex_a_linear(kThickness);
  ASSERT_EQ(got.sorce.creases.size(), 4u) << what;
  for (int j = 0; j < 4; ++j) {
    const FoldReport& r = got.sorce.creases[j].report;
    const FoldReport expected = fold_report(v.folds[j]);
    EXPECT_TRUE(r.cusps.empty()) << what << " fold " << j + 1 << ": cusp at t = " << r.cusps.front();
    EXPECT_EQ(r.pivot_at_start, expected.pivot_at_start) << what << " fold " << j + 1;
    EXPECT_EQ(r.pivot_at_end, expected.pivot_at_end) << what << " fold " << j + 1;
    EXPECT_EQ(r.concave_left.size(), expected.concave_left.size()) << what << " fold " << j + 1;
    EXPECT_EQ(r.concave_right.size(), expected.concave_right.size()) << what << " fold " << j + 1;
    EXPECT_TRUE(r.ill_behaved.empty()) << what << " fold " << j + 1;
    const FoldEndPoints e = end_points(v.folds[j]);
    EXPECT_LE((r.ends.left0 - e.left0).norm(), ends) << what << " fold " << j + 1;
    EXPECT_LE((r.ends.right0 - e.right0).norm(), ends) << what << " fold " << j + 1;
    EXPECT_LE((r.ends.left1 - e.left1).norm(), ends) << what << " fold " << j + 1;
    EXPECT_LE((r.ends.right1 - e.right1).norm(), ends) << what << " fold " << j + 1;
  }
}

// The seed: folds 1 and 3 pivot at t = 1, no fold has a cusp. At 40 splined steps the spline
// made a cusp at t = 0.99866 on folds 1 and 3 and missed the end points by 1.2e-5.
TEST(SorceDesignPath, VertexAOnTheExactPathHasTheSeedsDiagnosticsAtAnyStepCount) {
  const SorceDesign coarse = vertex_a_design(40, false), fine = vertex_a_design(400, false);
  EXPECT_TRUE(coarse.refinement.exact);
  EXPECT_TRUE(coarse.sorce.path.exact);
  EXPECT_EQ(coarse.refinement.steps_tried, std::vector<int>{40});
  expect_analytic_diagnostics(coarse, 1e-12, "40 steps");
  expect_analytic_diagnostics(fine, 1e-12, "400 steps");
  EXPECT_TRUE(coarse.sorce.creases[0].report.pivot_at_end);
  EXPECT_TRUE(coarse.sorce.creases[2].report.pivot_at_end);
  for (int j = 0; j < 4; ++j) {
    const FoldReport &a = coarse.sorce.creases[j].report, &b = fine.sorce.creases[j].report;
    EXPECT_EQ(a.s0, b.s0) << j;  // the same functions: the step count only places the knots
    EXPECT_EQ(a.arc_length_left, b.arc_length_left) << j;
    EXPECT_EQ(a.min_convexity_left, b.min_convexity_left) << j;
  }
}

// The general solver's path is splined: doubled twice from 40 steps, and said to be settled only
// when the last two paths agree. It stops the flat fold a few 1e-6 rad short of pi, so the
// stacking at t = 1 can still change (and is then reported as unsettled); the spline's
// spurious cusp of 40 steps is gone.
TEST(SorceDesignPath, VertexAOnTheGeneralSolversPathIsRefinedAndSaysWhetherItSettled) {
  const SorceDesign d = vertex_a_design(40, true);
  EXPECT_FALSE(d.refinement.exact);
  EXPECT_FALSE(d.sorce.path.exact);
  const std::vector<int>& tried = d.refinement.steps_tried;
  ASSERT_GE(tried.size(), 2u);
  ASSERT_LE(tried.size(), 3u);  // at most two doublings; settled at 80 steps it stops there
  for (std::size_t k = 0; k < tried.size(); ++k) EXPECT_EQ(tried[k], 40 << k);
  EXPECT_EQ(d.sorce.path.knots.size(), static_cast<std::size_t>(tried.back() + 1));  // the finest path is used
  EXPECT_EQ(d.refinement.settled, d.refinement.change.empty()) << d.refinement.change;
  for (const CreaseJoint& c : d.sorce.creases) EXPECT_TRUE(c.report.cusps.empty()) << "crease " << c.edge;
}

TEST(SorceDesignPath, TanHalfPathIsTheMultiplierFamilyWithExactJets) {
  const ScalarFunction f = tan_half_path(-0.6, 2.5), g = tan_half_path(1.7, M_PI), h = tan_half_fold(1.7);
  for (double t : {0.0, 0.1, 0.5, 0.9, 1.0}) {
    EXPECT_NEAR(f(t)[0], 2 * std::atan(-0.6 * std::tan(1.25 * t)), 1e-15) << t;
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(g(t)[k], h(t)[k], 1e-12 * (1 + std::abs(h(t)[k]))) << t << " " << k;
  }
  // Derivatives against central differences of the value and of the lower derivatives.
  const double dt = 1e-5;
  for (double t : {0.2, 0.6}) {
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(f(t)[k + 1], (f(t + dt)[k] - f(t - dt)[k]) / (2 * dt), 1e-7 * (1 + std::abs(f(t)[k + 1]))) << t << " " << k;
  }
  EXPECT_EQ(tan_half_path(0.0, 1.0)(0.7)[0], 0.0);
  EXPECT_THROW(tan_half_path(1.0, 4.0), InputError);
}

}}  // namespace
}  // namespace rigidfold::sorce
