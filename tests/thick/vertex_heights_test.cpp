// The seed's thick vertex models as panels with hinges on their faces: every DH model of
// kernel/thick/thick_vertex_models.hpp has offsets d = 0 and link lengths a_i, which is what
// horizontal hinges at heights h_i stepping by +-a_i around the vertex give
// (hinge_heights.hpp). For each model this finds the step signs whose thick sheet folds with
// the zero-thickness fold angles - an independent construction of the same linkage (face
// geometry and ClosureSystem's hole closure instead of DH matrices) - and checks it over the
// range with one DOF. The waterbomb with mu = 1/2, built the same way, is mobile alone but
// off the zero-thickness motion, and thick_mobility names it.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "tests/closure/closure_test_utils.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/thick_mobility.hpp"
#include "kernel/thick/thick_vertex_models.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

struct HeightModel {
  std::vector<double> heights;  // per flat edge
  double worst = 0.0;           // largest closure residual over the zero-thickness range
};

Eigen::VectorXd fold_vector(const CreasePattern& flat, const std::vector<double>& rho) {
  Eigen::VectorXd fold = Eigen::VectorXd::Zero(flat.num_edges());
  for (std::size_t i = 0; i < rho.size(); ++i) fold[i] = rho[i];
  return fold;
}

// Every sign choice s (s_0 = +1) with sum s_i a_i = 0; the ones whose sheet closes at the
// zero-thickness states (residual <= 1e-12 over 39 states). A link of length 0 (Myard's a34)
// gives the same heights for both of its signs, so it is counted twice.
std::vector<HeightModel> closing_height_models(const ThickVertexModel& model, const std::function<std::vector<double>(double)>& zero) {
  const int n = static_cast<int>(model.sectors.size());
  const CreasePattern flat = testing::single_vertex_from_sectors(model.sectors);
  const Topology topology = build_topology(flat);
  std::vector<double> a(n);
  for (int i = 0; i < n; ++i) a[i] = std::abs(model.thick.loops[0].joints[i].link.length);
  std::vector<HeightModel> found;
  for (int mask = 0; mask < (1 << (n - 1)); ++mask) {
    std::vector<double> h(flat.num_edges(), 0.0);
    double level = 0.0;
    for (int i = 0; i + 1 < n; ++i) {
      level += (i == 0 || (mask >> (i - 1) & 1) ? 1.0 : -1.0) * a[i];
      h[i + 1] = level;
    }
    const double sign_last = (mask >> (n - 2) & 1) ? 1.0 : -1.0;
    if (std::abs(level + sign_last * a[n - 1]) > 1e-12) continue;  // the heights must come back
    const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat, topology, h);
    const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
    HeightModel candidate{h, 0.0};
    for (int k = 1; k < 40; ++k) {
      const Eigen::VectorXd fold = fold_vector(flat, zero(model.mountain_valley[0] * kPi * k / 40));
      candidate.worst = std::max(candidate.worst, system.residual(system.unknowns_from_edges(sheet.sheet_edge_angles(fold))).cwiseAbs().maxCoeff());
    }
    if (candidate.worst <= 1e-12) found.push_back(candidate);
  }
  return found;
}

void expect_realisable(const ThickVertexModel& model, const std::function<std::vector<double>(double)>& zero) {
  const std::vector<HeightModel> found = closing_height_models(model, zero);
  ASSERT_FALSE(found.empty()) << model.name << ": no hinge heights fold with the zero-thickness angles";
  const CreasePattern flat = testing::single_vertex_from_sectors(model.sectors);
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat, build_topology(flat), found[0].heights);
  const ThickMobilityReport report =
      thick_mobility(sheet, fold_vector(flat, zero(model.mountain_valley[0] * 1.0)), {}, 1e-12);
  EXPECT_EQ(report.dof, 1) << model.name;
  std::printf("%s as hinge heights:", model.name.c_str());
  for (std::size_t i = 0; i < model.sectors.size(); ++i) std::printf(" %.3f", found[0].heights[i]);
  std::printf("  (closure over the range %.1e; %zu height orders close)\n", found[0].worst, found.size());
}

TEST(ThickVertexHeights, BennettMyardAndBricardModelsAreSlabsWithHingesOnFaces) {
  expect_realisable(bennett_vertex(0.7, 1.1, 0.2), [](double r0) { return bennett_zero_thickness(0.7, 1.1, r0); });
  expect_realisable(myard_vertex(kPi / 6, 0.1), [](double r0) { return myard_zero_thickness(kPi / 6, r0); });
  expect_realisable(diamond_vertex(0.3, 0.1, 0.15), [](double r0) { return diamond_zero_thickness(0.3, r0); });
  expect_realisable(waterbomb_vertex(1.0, 0.1), [](double r0) { return waterbomb_zero_thickness(r0); });
}

// mu = 1/2: the same hinge order as mu = 1 (the step signs found above) with a34 = a45 =
// mu * t. Its loop alone still moves (DOF 1 at a folded state of its own: the seed's (4-58)
// motion, tests/thick/thick_waterbomb_mu_test.cpp) but leaves the zero-thickness motion, and
// thick_mobility names the vertex.
TEST(ThickVertexHeights, WaterbombMuOneHalfIsMobileAloneButOffTheZeroThicknessMotion) {
  const ThickVertexModel unit = waterbomb_vertex(1.0, 0.1);
  const auto zero = [](double r0) { return waterbomb_zero_thickness(r0); };
  const std::vector<HeightModel> found = closing_height_models(unit, zero);
  ASSERT_EQ(found.size(), 1u);
  const int n = 6;
  const double t = 0.1, mu = 0.5;
  const std::vector<double> a{t * (1 + mu), t, t * mu, t * mu, t, t * (1 + mu)};
  const CreasePattern flat = testing::single_vertex_from_sectors(unit.sectors);
  std::vector<double> h(flat.num_edges(), 0.0);
  for (int i = 0; i + 1 < n; ++i) h[i + 1] = h[i] + (found[0].heights[i + 1] > found[0].heights[i] ? 1.0 : -1.0) * a[i];
  ASSERT_NEAR(std::abs(h[n - 1] - h[0]), a[n - 1], 1e-15);  // the heights come back round
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat, build_topology(flat), h);
  std::vector<Eigen::VectorXd> zero_states;
  for (int k = 1; k < 10; ++k) zero_states.push_back(fold_vector(flat, zero(-kPi * k / 10)));
  const ThickMobilityReport report = thick_mobility(sheet, Eigen::VectorXd::Zero(flat.num_edges()), zero_states);
  ASSERT_EQ(report.vertices.size(), 1u);
  EXPECT_EQ(report.off_motion_vertices, std::vector<int>{0});
  EXPECT_GT(report.vertices[0].off_motion, 1e-3);
  // Mobile alone: from a zero-thickness state, project onto the thick loop with crease 0 held
  // (the general corrector) and count the DOF there.
  const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
  NewtonOptions newton;
  newton.tolerance = 1e-14;
  newton.held_unknowns = {system.unknown_of_edge(0)};
  const NewtonResult projected =
      newton_project(system, system.unknowns_from_edges(sheet.sheet_edge_angles(zero_states[4])), newton);
  ASSERT_TRUE(projected.converged);
  const Eigen::VectorXd thick_state = sheet.fold_angles(system.edges_from_unknowns(projected.x));
  const ThickMobilityReport moved = thick_mobility(sheet, thick_state, {});
  EXPECT_EQ(moved.dof, 1);
  double largest = 0.0;
  for (int i = 0; i < n; ++i) largest = std::max(largest, std::abs(thick_state[i] - zero_states[4][i]));
  EXPECT_GT(largest, 1e-2);
  std::printf("waterbomb mu = 1/2 as hinge heights: off the zero-thickness motion by up to %.2e (residual), DOF %d at a state "
              "%.3f rad from the zero-thickness one at equal crease 0\n",
              report.vertices[0].off_motion, moved.dof, largest);
}

}}  // namespace
}  // namespace rigidfold
