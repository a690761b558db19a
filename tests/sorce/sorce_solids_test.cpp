// SORCE panel solids (design/sorce/sorce_solids.hpp) written as binary STL and read back:
// every shell closed and outward (each directed edge once, its reverse once), the mesh's
// enclosed volume equal to the shells' volumes computed from their 2D sections, and the cam
// section of the circle oracle equal to its analytic area (quarter disc and rectangles, less
// the chord segments of the sampled arc).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "design/sorce/sorce_dxf.hpp"
#include "design/sorce/sorce_solids.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/sorce/sorce_examples.hpp"
#include "tests/support/stl_mesh.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using Eigen::Vector3d;
using rigidfold::testing::enclosed_volume;
using rigidfold::testing::open_or_misoriented_edges;
using rigidfold::testing::parse_stl;

// Left profile of the circular CORE joint of radius r: the quarter arc centred (-r, 0) from
// (0, 0) to (-r, r), sampled at n + 1 points.
std::vector<Vec2> core_left_profile(double r, int n) {
  std::vector<Vec2> p;
  for (int k = 0; k <= n; ++k) {
    const double a = std::numbers::pi / 2 * k / n;
    p.emplace_back(-r + r * std::cos(a), r * std::sin(a));
  }
  return p;
}

double sum(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s;
}

TEST(SorceSolids, CircleOracleCamIsClosedAndHasTheAnalyticVolume) {
  const double h = 0.2, r = h / 2;
  const int n = 64;
  PanelSolidInput in;
  in.polygon = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)};
  in.thickness = h;
  // Crease along x = 1 (the panel's right side), the panel on the fold's left: x_axis = +x.
  CamSide c;
  c.origin = Vector3d(1, 0, 0);
  c.fold_direction = Vector3d::UnitY();
  c.x_axis = Vector3d::UnitX();
  c.w0 = 0.0;
  c.w1 = 1.0;
  c.left = true;
  c.profile = core_left_profile(r, n);
  in.cams = {c};
  const SolidOptions o;  // margin 0.1 h, overlap 0.05 h, vertex gap h
  const PanelSolid s = panel_solid(in, o);
  ASSERT_EQ(s.shell_volumes.size(), 2u);
  EXPECT_TRUE(s.cams_skipped.empty());

  // Slab: the square cut back to x = 1 - r - margin h + overlap h.
  const double slab_depth = 1.0 - (r + o.margin * h - o.overlap * h);
  EXPECT_NEAR(s.shell_volumes[0], slab_depth * 1.0 * h, 1e-15);
  // Cam section: x_base = -r - margin h; below y = 0 the rectangle [x_base, 0] x [-r, 0];
  // above, [x_base, -r] x [0, r] and the quarter disc, less n chord segments r^2 (d - sin d)/2.
  const double x_base = -r - o.margin * h, d = std::numbers::pi / 2 / n;
  const double area = -x_base * r + (-r - x_base) * r + std::numbers::pi * r * r / 4 - n * r * r * (d - std::sin(d)) / 2;
  EXPECT_NEAR(s.shell_volumes[1], area * (1.0 - 2 * h), 1e-14);

  const auto tris = parse_stl(polygons_stl(s.polygons, 0, "rigidfold test: circle oracle cam"));
  EXPECT_EQ(open_or_misoriented_edges(tris), 0);
  // float32 vertices: relative volume error ~1e-7.
  EXPECT_NEAR(enclosed_volume(tris), sum(s.shell_volumes), 1e-6 * sum(s.shell_volumes));
}

TEST(SorceSolids, VertexAPanelsAreClosedAtEveryPose) {
  // Vertex A (seed section 5) with linear offsets, thickness 0.1: four triangular panels of
  // radius 1, each with the cams of its two folds, placed at t = 0.5 by a pose.
  const double h = 0.1;
  const SorceVertex v = testing::vertex_a_linear(h);
  double theta[4];  // fold j's direction angle, fold 1 along +x, sectors counter-clockwise
  theta[0] = 0.0;
  for (int j = 1; j < 4; ++j) theta[j] = theta[j - 1] + v.sectors[j - 1];
  auto dir = [](double a) { return Vector3d(std::cos(a), std::sin(a), 0.0); };
  for (int i = 0; i < 4; ++i) {  // panel i (sector alpha_{i+1}) between folds i and i+1
    SCOPED_TRACE("panel " + std::to_string(i + 1));
    const int j_right_of = i, j_left_of = (i + 1) % 4;  // fold j's right panel is sector j, its left sector j-1
    PanelSolidInput in;
    in.polygon = {Vector3d::Zero(), dir(theta[i]), dir(theta[i] + v.sectors[i])};
    in.thickness = h;
    for (int j : {j_right_of, j_left_of}) {
      const SampledProfiles p = sample_profiles(v.folds[j], 101);
      CamSide c;
      c.origin = Vector3d::Zero();
      c.fold_direction = dir(theta[j]);
      c.x_axis = dir(theta[j] + std::numbers::pi / 2);  // into the fold's right (counter-clockwise) panel
      c.w0 = 0.0;
      c.w1 = 1.0;
      c.left = j == j_left_of;
      c.profile = c.left ? p.left : p.right;
      in.cams.push_back(c);
    }
    const PanelSolid s = panel_solid(in, {0.1, 0.05, 0.2});
    EXPECT_EQ(s.shell_volumes.size(), 3u);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.rotate(Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()));
    pose.translate(Vector3d(0.3, -0.2, 0.05));
    const auto tris = parse_stl(polygons_stl(transformed(s.polygons, pose), 0, "rigidfold test: vertex A panel"));
    EXPECT_EQ(open_or_misoriented_edges(tris), 0);
    EXPECT_NEAR(enclosed_volume(tris), sum(s.shell_volumes), 1e-5 * sum(s.shell_volumes));
    for (double vol : s.shell_volumes) EXPECT_GT(vol, 0.0);
  }
}

TEST(SorceSolids, PlainRevoluteGetsNoCamButACutBack) {
  PanelSolidInput in;
  in.polygon = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)};
  in.thickness = 0.1;
  CamSide c;
  c.origin = Vector3d(1, 0, 0);
  c.left = true;
  c.profile = {Vec2::Zero(), Vec2::Zero()};
  in.cams = {c};
  const PanelSolid s = panel_solid(in);
  EXPECT_EQ(s.cams_skipped, std::vector<int>{0});
  EXPECT_NEAR(s.shell_volumes.at(0), (1.0 - 0.1 * 0.1) * 0.1, 1e-15);
}

TEST(SorceSolids, BadInputNamesThePlace) {
  PanelSolidInput in;
  in.polygon = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)};
  in.thickness = 0.1;
  auto place = [&](const PanelSolidInput& x, const SolidOptions& o = {}) -> std::string {
    try {
      panel_solid(x, o);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  PanelSolidInput clockwise = in;
  std::reverse(clockwise.polygon.begin(), clockwise.polygon.end());
  EXPECT_NE(place(clockwise).find("polygon["), std::string::npos);
  PanelSolidInput thin = in;
  thin.thickness = 0.0;
  EXPECT_NE(place(thin).find("thickness"), std::string::npos);
  EXPECT_NE(place(in, {0.05, 0.1, -1}).find("options"), std::string::npos);
  // A profile that crosses itself (its first and third segments meet at (-0.02, 0.02)).
  PanelSolidInput loop = in;
  CamSide c;
  c.origin = Vector3d(1, 0, 0);
  c.profile = {Vec2(0, 0), Vec2(-0.04, 0.04), Vec2(-0.04, 0), Vec2(0, 0.04)};
  loop.cams = {c};
  EXPECT_NE(place(loop).find("cams[0]"), std::string::npos);
  PanelSolidInput skew = in;
  c.profile = core_left_profile(0.05, 8);
  c.x_axis = Vector3d(1, 0.1, 0);
  skew.cams = {c};
  EXPECT_NE(place(skew).find("cams[0]"), std::string::npos);
}

// DXF of vertex A's folds: per fold, the left/right profiles as POLYLINEs whose VERTEX
// entities read back to the sampled points exactly (shortest round-trip numbers).
TEST(SorceDxf, ProfilesReadBackExactly) {
  const SorceVertex v = testing::vertex_a_linear(1.0);
  std::vector<NamedFold> folds;
  for (int j = 0; j < 4; ++j) folds.push_back({"FOLD" + std::to_string(j + 1), v.folds[j]});
  const std::string text = fold_profiles_dxf(folds, 11);
  // Walk the groups: collect the VERTEX points per layer.
  std::istringstream in(text);
  std::string code, value, entity, layer;
  std::map<std::string, std::vector<Vec2>> points;
  Vec2 p = Vec2::Zero();
  while (std::getline(in, code) && std::getline(in, value)) {
    const int c = std::stoi(code);
    if (c == 0) {
      if (entity == "VERTEX") points[layer].push_back(p);
      entity = value;
    } else if (c == 8) {
      layer = value;
    } else if (c == 10) {
      p.x() = std::stod(value);
    } else if (c == 20) {
      p.y() = std::stod(value);
    }
  }
  EXPECT_EQ(entity, "EOF");
  for (int j = 0; j < 4; ++j) {
    const SampledProfiles s = sample_profiles(v.folds[j], 11);
    const std::string name = "FOLD" + std::to_string(j + 1);
    ASSERT_EQ(points[name + "_LEFT"].size(), 11u);
    ASSERT_EQ(points[name + "_RIGHT"].size(), 11u);
    for (int k = 0; k < 11; ++k) {
      EXPECT_EQ(points[name + "_LEFT"][k], s.left[k]) << name << " " << k;
      EXPECT_EQ(points[name + "_RIGHT"][k], s.right[k]) << name << " " << k;
    }
  }
  EXPECT_THROW(fold_profiles_dxf({{"bad name", v.folds[0]}}), InputError);
  EXPECT_THROW(fold_profiles_dxf(folds, 1), InputError);
}

}}  // namespace
}  // namespace rigidfold::sorce
