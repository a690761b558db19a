// SORCE joints over a whole crease pattern (design/sorce/sorce_pattern.hpp), the path traced
// by the kernel's general solver: a single degree-4 vertex against the analytic vertex
// (sorce_vertex.hpp), the bundled 4x4 Miura folded flat, and the rigid square twist (type 1)
// over its traced range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "design/sorce/sorce_pattern.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

const VertexSectors kVertexA = {to_radians(120.0), to_radians(80.0), to_radians(60.0), to_radians(100.0)};

// The seed's vertex A as a FOLD pattern: creases from the centre outward (fold j is edge j - 1,
// at angle alpha_1 + .. + alpha_{j-1}), panel j the triangle of sector alpha_j (face j - 1).
CreasePattern vertex_a_pattern() {
  std::string coords = "[[0,0]";
  double angle = 0.0;
  for (int j = 0; j < 4; ++j) {
    char buffer[80];
    std::snprintf(buffer, sizeof buffer, ",[%.17g,%.17g]", std::cos(angle), std::sin(angle));
    coords += buffer;
    angle += kVertexA[j];
  }
  coords += "]";
  const std::string text = R"({"file_spec":1.1,"vertices_coords":)" + coords +
                           R"(,"edges_vertices":[[0,1],[0,2],[0,3],[0,4],[1,2],[2,3],[3,4],[4,1]],)"
                           R"("edges_assignment":["V","V","M","V","B","B","B","B"],)"
                           R"("faces_vertices":[[0,1,2],[0,2,3],[0,3,4],[0,4,1]]})";
  return parse_fold(text, "vertex_a");
}

void expect_verified(const PatternSorce& s) {
  for (const CreaseJoint& j : s.creases) {
    if (!j.folds) continue;
    EXPECT_LE(j.report.max_rolling_residual, 1e-10) << j.edge;
    EXPECT_LE(j.report.max_contact_residual, 1e-10) << j.edge;
    EXPECT_NEAR(j.report.arc_length_left, j.report.arc_length_right, 1e-10) << j.edge;
  }
  EXPECT_LE(s.checks.consistency, 1e-12);
  EXPECT_LE(s.checks.pitch, 1e-12);
  EXPECT_LE(s.checks.closure_knots, 1e-12);
  EXPECT_LE(s.checks.contact, 1e-10);
}

void print_checks(const char* name, const PatternSorce& s) {
  std::size_t hits = 0;
  for (const auto& i : s.checks.interference) hits += i.face_pairs.size();
  std::printf(
      "%s: consistency %.1e pitch %.1e closure knots %.1e samples %.1e contact %.1e rolling %.1e planar contact "
      "%.1e flat %d stack %d end gap %.1e stacking margin %.1e interfering pairs (all samples) %zu skipped faces %zu\n",
      name, s.checks.consistency, s.checks.pitch, s.checks.closure_knots, s.checks.closure_samples, s.checks.contact,
      s.checks.rolling, s.checks.contact_planar, s.checks.flat_folded_end, s.checks.all_stack, s.checks.end_gap, s.checks.stacking_margin, hits,
      s.checks.skipped_faces.size());
}

TEST(SorcePattern, SingleVertexReproducesTheAnalyticVertex) {
  const CreasePattern p = vertex_a_pattern();
  const double h = 0.1;
  PatternSorceRequest rq;
  rq.thickness = h;
  rq.trace.drive = 1;  // fold 2, a major fold: t = gamma_2 / pi is eq 24's kMajorLinear
  rq.trace.to = M_PI;
  rq.trace.steps = 40;
  const PatternSorce s = pattern_sorce(p, rq);
  print_checks("vertex A", s);
  ASSERT_EQ(s.creases.size(), 4u);
  // The stacking rule gives the seed's eq 4 offsets.
  const double expected[4] = {-1.5 * h, 0.5 * h, 0.5 * h, -1.5 * h};
  for (int f = 0; f < 4; ++f) EXPECT_NEAR(s.faces[f].end_value, expected[f], 1e-14) << f;
  expect_verified(s);
  EXPECT_TRUE(s.checks.flat_folded_end);
  EXPECT_TRUE(s.checks.all_stack);

  std::array<ScalarFunction, 4> offset;
  for (int i = 0; i < 4; ++i) offset[i] = power_function(expected[i], 1);
  const SorceVertex v = sorce_vertex(kVertexA, vertex_fold_angles(kVertexA, VertexParameterization::kMajorLinear),
                                     offset, {h, h, h, h});
  double err_gamma = 0.0, err_profile = 0.0;
  for (int j = 0; j < 4; ++j) {
    const CreaseJoint& c = s.creases[j];
    ASSERT_EQ(c.edge, j);
    EXPECT_EQ(c.left_face, (j + 3) % 4);  // panel alpha_{j-1}
    EXPECT_EQ(c.right_face, j);           // panel alpha_j
    for (int i = 1; i < 200; ++i) {
      const double t = i / 200.0;
      const ProfilePoint a = profile_point(c.motion, t), b = profile_point(v.folds[j], t);
      err_gamma = std::max(err_gamma, std::abs(a.gamma - b.gamma));
      err_profile = std::max({err_profile, (a.s_left - b.s_left).norm(), (a.s_right - b.s_right).norm()});
    }
  }
  std::printf("vertex A vs analytic: gamma %.2e, profiles %.2e (h = %.2f)\n", err_gamma, err_profile, h);
  // Measured with 40 steps: gamma 9.2e-07, profiles 2.7e-07 (the spline's error, see
  // sorce_path_spline_test.cpp; the trace's own samples agree with eq 25 to ~1e-14).
  EXPECT_LE(err_gamma, 2e-6);
  EXPECT_LE(err_profile, 6e-7);

  // Pose table at t = 1: the four panels (all overlapping near the vertex) lie flat in distinct
  // layers, mid-planes at least h apart, each face's normal along +-z.
  const std::vector<Eigen::Isometry3d>& end = s.poses.back();
  ASSERT_EQ(s.pose_times.back(), 1.0);
  std::vector<double> height;
  for (int f = 0; f < 4; ++f) {
    EXPECT_NEAR(std::abs((end[f].linear() * Eigen::Vector3d::UnitZ()).z()), 1.0, 1e-12) << f;
    height.push_back((end[f] * Eigen::Vector3d::Zero()).z());  // the vertex lies in every face
  }
  std::sort(height.begin(), height.end());
  for (int f = 0; f + 1 < 4; ++f) EXPECT_GE(height[f + 1] - height[f], h - 1e-12) << f;
}

// Given end offsets, per-face thicknesses and the seed's basis offsets (eq 36) go through to
// the folds unchanged: the pattern's profiles match the analytic vertex built with them.
TEST(SorcePattern, GivenOffsetsAndBasesMatchTheAnalyticVertex) {
  const CreasePattern p = vertex_a_pattern();
  PatternSorceRequest rq;
  rq.face_thickness = {0.1, 0.1, 0.1, 0.1};
  rq.end_offsets = {-0.15, 0.05, 0.05, -0.15};
  rq.offset_coefficients = {{0.2, -0.1}, {0.0, 0.3, 0.1}, {}, {-0.2}};
  rq.trace.drive = 1;
  rq.trace.to = M_PI;
  rq.trace.steps = 40;
  const PatternSorce s = pattern_sorce(p, rq);
  expect_verified(s);
  EXPECT_TRUE(s.checks.all_stack);
  std::array<ScalarFunction, 4> offset;
  for (int i = 0; i < 4; ++i) offset[i] = basis_offset(rq.end_offsets[i], rq.offset_coefficients[i], seed_offset_bases());
  const SorceVertex v = sorce_vertex(kVertexA, vertex_fold_angles(kVertexA, VertexParameterization::kMajorLinear),
                                     offset, {0.1, 0.1, 0.1, 0.1});
  double err = 0.0;
  for (int j = 0; j < 4; ++j)
    for (int i = 1; i < 100; ++i) {
      const ProfilePoint a = profile_point(s.creases[j].motion, i / 100.0), b = profile_point(v.folds[j], i / 100.0);
      err = std::max({err, (a.s_left - b.s_left).norm(), (a.s_right - b.s_right).norm()});
    }
  std::printf("vertex A with bases vs analytic: profiles %.2e\n", err);
  EXPECT_LE(err, 6e-7);
}

const std::string kBundled = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/";

TEST(SorcePattern, MiuraFoldedFlatStacksAndCloses) {
  const CreasePattern p = read_fold(kBundled + "miura_4x4_alpha60.fold");
  PatternSorceRequest rq;
  rq.thickness = 0.05;
  rq.trace.drive = 4;  // an M crease
  rq.trace.to = -M_PI;
  rq.trace.steps = 30;
  rq.report.samples = 401;
  const PatternSorce s = pattern_sorce(p, rq);
  print_checks("miura 4x4", s);
  EXPECT_EQ(s.creases.size(), 24u);
  expect_verified(s);
  for (const auto& i : s.checks.interference) EXPECT_TRUE(i.face_pairs.empty()) << i.t;
  // The general solver stops the flat fold just short of pi (its fold-limit end, "clamped"), so
  // the reports' stacking test (|gamma(1)| = pi within 1e-12) does not apply; the end offsets
  // satisfy every crease's stacking condition all the same (margin 0: the binding ones are tight).
  EXPECT_FALSE(s.checks.flat_folded_end);
  EXPECT_LT(s.checks.end_gap, 1e-5);
  EXPECT_GE(s.checks.stacking_margin, -1e-15);
  EXPECT_LE(s.checks.stacking_margin, 1e-15);
  ASSERT_EQ(s.poses.size(), 11u);
  ASSERT_EQ(s.poses[0].size(), 16u);
  for (int f = 0; f < 16; ++f) EXPECT_LE((s.poses[0][f].matrix() - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff(), 1e-15);
}

// The slab check sees interference where there is some: with every offset 0 (plain revolute
// joints at the zero-thickness creases) the thick Miura's layers pass through each other as it
// folds flat; with the stacking offsets they do not.
TEST(SorcePattern, SlabCheckFindsZeroOffsetLayersInterfering) {
  const CreasePattern p = read_fold(kBundled + "miura_4x4_alpha60.fold");
  PatternSorceRequest rq;
  rq.thickness = 0.05;
  rq.trace.drive = 4;
  rq.trace.to = -M_PI;
  rq.trace.steps = 30;
  rq.report.samples = 101;
  rq.end_offsets.assign(16, 0.0);
  const PatternSorce s = pattern_sorce(p, rq);
  ASSERT_EQ(s.checks.interference.size(), 21u);
  EXPECT_TRUE(s.checks.interference.front().face_pairs.empty());  // flat: slabs side by side
  EXPECT_FALSE(s.checks.interference.back().face_pairs.empty());
  std::printf("zero offsets: %zu interfering pairs at t = 1\n", s.checks.interference.back().face_pairs.size());
  EXPECT_LT(s.checks.stacking_margin, 0.0);
}

TEST(SorcePattern, SquareTwistOverItsTracedRange) {
  const CreasePattern p = read_fold(kBundled + "square_twist_30_type1.fold");
  PatternSorceRequest rq;
  rq.thickness = 0.02;
  rq.trace.steps = 20;
  rq.report.samples = 401;
  const PatternSorce s = pattern_sorce(p, rq);
  print_checks("square twist type 1", s);
  expect_verified(s);
  EXPECT_FALSE(s.checks.flat_folded_end);
}

TEST(SorcePattern, BadInputNamesThePlace) {
  const CreasePattern p = vertex_a_pattern();
  PatternSorceRequest rq;
  rq.trace.drive = 1;
  rq.trace.to = M_PI;
  rq.trace.steps = 10;
  auto place = [&](const PatternSorceRequest& r) {
    try {
      pattern_sorce(p, r);
    } catch (const InputError& e) {
      return e.place();
    }
    return std::string("none");
  };
  EXPECT_EQ(place(rq), "thickness");
  rq.thickness = 0.1;
  PatternSorceRequest bad = rq;
  bad.end_offsets = {0.0, 0.0, std::nan(""), 0.0};
  EXPECT_EQ(place(bad), "end_offsets[2]");
  bad = rq;
  bad.face_thickness = {0.1, 0.1, -1.0, 0.1};
  EXPECT_EQ(place(bad), "face_thickness[2]");
  bad = rq;
  bad.pose_times = {0.5, 1.5};
  EXPECT_EQ(place(bad), "pose_times[1]");
  bad = rq;
  bad.offset_coefficients = {{}, {0.1, 0.1, 0.1, 0.1}, {}, {}};
  EXPECT_EQ(place(bad), "offset_coefficients[1]");
  bad = rq;
  bad.end_offsets = {0.0, 0.0};
  EXPECT_EQ(place(bad), "end_offsets");
  bad = rq;
  bad.trace.steps = 5;
  EXPECT_EQ(place(bad), "branch");
}

}}  // namespace
}  // namespace rigidfold::sorce
