// SORCE (seed 002) per-fold diagnostics on the seed's examples: vertex A's convexity signs,
// concave spans, pivots and protrusions (section 5), the bird's-foot vertex B's cusp with
// eq 60 and its absence with eq 61 (section 10), the circular construction (eqs 62-69),
// ill-behaved points, and the figure of merit.
#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cmath>
#include <vector>

#include "design/sorce/sorce_fold_report.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::vertex_a_linear;
using testing::vertex_b_sectors;
using testing::vertex_b_split;

TEST(SorceFoldReport, VertexAConvexitySpansPivotsAndProtrusion) {
  const SorceVertex v = vertex_a_linear(1.0);
  std::array<FoldReport, 4> r;
  for (int j = 0; j < 4; ++j) r[j] = fold_report(v.folds[j]);
  // Folds 1 and 3 (minor): both profiles convex toward the mate, and the contact ends in a
  // pivot (|s'| -> 0 at t = 1: "rotation takes place about a point").
  for (int j : {0, 2}) {
    EXPECT_GT(r[j].min_convexity_left, 0.0) << "fold " << j + 1;
    EXPECT_GT(r[j].min_convexity_right, 0.0) << "fold " << j + 1;
    EXPECT_TRUE(r[j].concave_left.empty() && r[j].concave_right.empty());
    EXPECT_TRUE(r[j].pivot_at_end);
    EXPECT_FALSE(r[j].pivot_at_start);
    EXPECT_TRUE(std::isinf(r[j].max_convexity_left));  // curvature diverges at t = 1
  }
  // Folds 2 and 4 (major): one profile has a concave span. From eq 28, the left profile of
  // fold 2 turns with x'y'' - y'x'' proportional to 1 - 3 cos(pi t), so c_l < 0 exactly on
  // [0, acos(1/3)/pi); the right profile of fold 4 mirrors it.
  const double end = std::acos(1.0 / 3.0) / kPi;
  ASSERT_EQ(r[1].concave_left.size(), 1u);
  EXPECT_EQ(r[1].concave_left[0].begin, 0.0);
  EXPECT_NEAR(r[1].concave_left[0].end, end, 1e-12);
  EXPECT_TRUE(r[1].concave_right.empty());
  EXPECT_GT(r[1].min_convexity_right, 0.0);
  ASSERT_EQ(r[3].concave_right.size(), 1u);
  EXPECT_NEAR(r[3].concave_right[0].end, end, 1e-12);
  EXPECT_TRUE(r[3].concave_left.empty());
  for (int j : {1, 3}) EXPECT_FALSE(r[j].pivot_at_end);
  for (const FoldReport& f : r) EXPECT_TRUE(f.cusps.empty() && f.ill_behaved.empty());

  // Protrusion beyond the slab faces (thickness d = 1): folds 1, 2, 4 protrude, fold 3 does
  // not. Expected values from a dense scan of the eq 28 heights: the ends at t = 1 give
  // 3d/2 - d/2 = d, and fold 3 and the other profiles of 2, 4 stay within d/2.
  const std::array<std::array<double, 2>, 4> expect{{{1.0, 1.0}, {1.0, 0.0}, {0.0, 0.0}, {0.0, 1.0}}};
  for (int j = 0; j < 4; ++j) {
    EXPECT_NEAR(r[j].protrusion_left, expect[j][0], 1e-12) << "fold " << j + 1;
    EXPECT_NEAR(r[j].protrusion_right, expect[j][1], 1e-12) << "fold " << j + 1;
  }

  // Arc lengths: equal on both sides and equal to an independent integral of the eq 28
  // speed of fold 2, |s_l2'| = (d/2) sqrt(10 - 6 cos(pi t)) (tanh-sinh quadrature).
  boost::math::quadrature::tanh_sinh<double> ts;
  const double len2 = ts.integrate([](double t) { return 0.5 * std::sqrt(10 - 6 * std::cos(kPi * t)); }, 0.0, 1.0);
  EXPECT_NEAR(r[1].arc_length_left, len2, 1e-12);
  for (const FoldReport& f : r) EXPECT_NEAR(f.arc_length_left, f.arc_length_right, 1e-12 * f.arc_length_left);
  for (const FoldReport& f : r) {
    EXPECT_LE(f.max_rolling_residual, 1e-10);
    EXPECT_LE(f.max_contact_residual, 1e-10);
  }
  // s0 (eq 20): folds 2 and 4 start off the fold line by -+2d/pi; folds 1 and 3 on it.
  EXPECT_NEAR(r[1].s0, -2 / kPi, 1e-15);
  EXPECT_NEAR(r[3].s0, 2 / kPi, 1e-15);
  EXPECT_NEAR(r[0].s0, 0.0, 1e-15);
  // Any divergent convexity makes the figure of merit infinite.
  EXPECT_TRUE(std::isinf(figure_of_merit({r.begin(), r.end()}, 1e-3)));
}

TEST(SorceFoldReport, BirdsFootEq60HasACuspOnFold3AndEq61None) {
  const SorceVertex a = vertex_b_split(1), b = vertex_b_split(2);
  for (int j = 0; j < 4; ++j) {
    const FoldReport ra = fold_report(a.folds[j]), rb = fold_report(b.folds[j]);
    EXPECT_EQ(ra.cusps.size(), j == 2 ? 1u : 0u) << "eq 60, fold " << j + 1;
    EXPECT_TRUE(rb.cusps.empty()) << "eq 61, fold " << j + 1;
    // eq 61: "all of the surfaces are smooth and convex toward one another".
    EXPECT_GT(rb.min_convexity_left, 0.0) << "eq 61, fold " << j + 1;
    EXPECT_GT(rb.min_convexity_right, 0.0) << "eq 61, fold " << j + 1;
    EXPECT_LE(std::max(ra.max_rolling_residual, rb.max_rolling_residual), 1e-10);
    EXPECT_LE(std::max(ra.max_contact_residual, rb.max_contact_residual), 1e-10);
    EXPECT_NEAR(ra.arc_length_left, ra.arc_length_right, 1e-12);
    if (j == 2) {
      // The cusp: the profile speed nearly vanishes and the tangent turns back on itself.
      const double t = ra.cusps[0];
      const ProfilePoint p = profile_point(a.folds[2], t);
      EXPECT_LT(p.ds_left.norm(), 1e-3 * ra.max_speed);
      const ProfilePoint before = profile_point(a.folds[2], t - 0.02), after = profile_point(a.folds[2], t + 0.02);
      EXPECT_LT(before.ds_left.dot(after.ds_left), 0.0);
      // With eq 61 the same fold keeps a speed well away from zero.
      EXPECT_GT(rb.min_speed, 0.1 * rb.max_speed);
    }
  }
}

// Section 11: folds 2-4 exact circles of radius r (in each panel's own coordinates, centred
// at (-r, 0) and (r, 0)); fold 1 "nicely behaved": convex, no cusp.
TEST(SorceFoldReport, CircularConstructionGivesCircles) {
  const double r = 0.1;
  const SorceVertex v = circular_split_vertex(vertex_b_sectors(), VertexParameterization::kSymmetric, r);
  double radius_error = 0.0, convexity_error = 0.0;
  for (int j = 1; j < 4; ++j) {
    for (int k = 0; k <= 400; ++k) {
      const ProfilePoint p = profile_point(v.folds[j], k / 400.0);
      radius_error = std::max({radius_error, std::abs((p.s_left - Vec2(-r, 0)).norm() - r), std::abs((p.s_right - Vec2(r, 0)).norm() - r)});
      convexity_error = std::max({convexity_error, std::abs(p.convexity_left - 1 / r), std::abs(p.convexity_right - 1 / r)});
    }
  }
  EXPECT_LE(radius_error, 1e-10);
  EXPECT_LE(convexity_error, 1e-10);
  const FoldReport f1 = fold_report(v.folds[0]);
  EXPECT_GT(f1.min_convexity_left, 0.0);
  EXPECT_GT(f1.min_convexity_right, 0.0);
  EXPECT_TRUE(f1.cusps.empty());
  // The split with eq 69 is needed: without it fold 3 is not a circle.
  SorceVertex unsplit = v;
  unsplit.folds[2].d = {};
  const ProfilePoint p = profile_point(unsplit.folds[2], 0.5);
  EXPECT_GT(std::abs((p.s_left - Vec2(-r, 0)).norm() - r), 1e-3);
  // Figure of merit of the circular folds alone is 1.
  std::vector<FoldReport> circles;
  for (int j = 1; j < 4; ++j) circles.push_back(fold_report(v.folds[j]));
  EXPECT_NEAR(figure_of_merit(circles, 0.0), 1.0, 1e-9);
}

// Stacking at t = 1: vertex A's panels end -(z_l(1) + z_r(1)) apart (3, 1, -1, 1 thicknesses
// from eq 27), on the valley side for folds 1, 2, 4 and the mountain side for fold 3; the
// bird's-foot vertex stacks with the digest's z_i = -0.1 t and not with the OCR's +0.1 t
// (the sign law behind the digest's correction of eqs 60, 61).
TEST(SorceFoldReport, PanelsStackAtTheEnd) {
  const SorceVertex a = vertex_a_linear(1.0);
  for (int j = 0; j < 4; ++j) {
    const FoldReport r = fold_report(a.folds[j], {101});
    EXPECT_NEAR(r.end_separation, -(a.folds[j].z_left(1.0)[0] + a.folds[j].z_right(1.0)[0]), 1e-15);
    EXPECT_TRUE(r.stacks) << "fold " << j + 1;
  }
  EXPECT_LT(fold_report(a.folds[2], {101}).end_separation, 0.0);  // mountain
  for (int power : {1, 2}) {
    const SorceVertex b = vertex_b_split(power);
    for (int j = 0; j < 4; ++j) EXPECT_TRUE(fold_report(b.folds[j], {101}).stacks) << "fold " << j + 1;
  }
  const VertexSectors bs = vertex_b_sectors();
  const auto gamma = vertex_fold_angles(bs, VertexParameterization::kSymmetric);
  const ScalarFunction up = power_function(0.1, 1);
  const SorceVertex ocr = sorce_vertex(bs, gamma, {up, up, up, up}, {0.2, 0.2, 0.2, 0.2}, collinear_split(bs, gamma, power_function(0.4, 2)));
  int stacking = 0;
  for (int j = 0; j < 4; ++j) stacking += fold_report(ocr.folds[j], {101}).stacks;
  EXPECT_LT(stacking, 4);
  // The circular construction stacks as well.
  const SorceVertex c = circular_split_vertex(bs, VertexParameterization::kSymmetric, 0.1);
  for (int j = 0; j < 4; ++j) EXPECT_TRUE(fold_report(c.folds[j], {101}).stacks) << "fold " << j + 1;
}

TEST(SorceFoldReport, IllBehavedAndStationaryPoints) {
  // gamma = 2 t (1 - t): gamma' = 0 at t = 1/2.
  const ScalarFunction gamma = [](double t) { return Jet{2 * t * (1 - t), 2 - 4 * t, -4, 0}; };
  const FoldReport ill = fold_report(FoldMotion{gamma, power_function(0.1, 1), power_function(-0.1, 1), {}, 0, 0}, {2000});
  ASSERT_EQ(ill.ill_behaved.size(), 1u);
  EXPECT_NEAR(ill.ill_behaved[0], 0.5, 1e-14);
  EXPECT_TRUE(ill.stationary.empty());
  EXPECT_TRUE(std::isnan(ill.arc_length_left));
  // Offsets that are functions of gamma stop with it: not ill-behaved (a limit exists).
  const FoldReport ok = fold_report(FoldMotion{gamma, circular_offset(0.1, gamma), circular_offset(0.1, gamma), {}, 0, 0}, {2000});
  EXPECT_TRUE(ok.ill_behaved.empty());
  ASSERT_EQ(ok.stationary.size(), 1u);
}

TEST(SorceFoldReport, FigureOfMeritClipsWithEpsilon) {
  // Vertex A eq 28 folds 2 and 4 only (finite convexities, one negative).
  const SorceVertex v = vertex_a_linear(1.0);
  const std::vector<FoldReport> r{fold_report(v.folds[1]), fold_report(v.folds[3])};
  const double hi = std::max({r[0].max_convexity_left, r[0].max_convexity_right, r[1].max_convexity_left, r[1].max_convexity_right});
  ASSERT_LT(std::min(r[0].min_convexity_left, r[1].min_convexity_right), 0.0);
  EXPECT_NEAR(figure_of_merit(r, 0.01), hi / 0.01, 1e-9 * hi / 0.01);
  EXPECT_TRUE(std::isinf(figure_of_merit(r, 0.0)));
}

}}  // namespace
}  // namespace rigidfold::sorce
