// Inverse design of Miura strings: closed form per vertex, Ceres trajectories, NLopt
// curves, each checked by the forward closed form and the general loop-closure solver.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "design/strings/miura_string.hpp"
#include "design/strings/string_fit_ceres.hpp"
#include "design/strings/string_fit_nlopt.hpp"
#include "design/strings/string_inverse.hpp"
#include "design/strings/string_kinematics.hpp"
#include "design/strings/string_verify.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::design {
namespace { namespace RIGIDFOLD_UNITY_ID {


MiuraString random_string(int n, std::uint64_t seed, double lo_deg = 30, double hi_deg = 70) {
  return random_miura_string(n, seed, to_radians(lo_deg), to_radians(hi_deg), 0.5);
}

std::vector<Eigen::Vector3d> helix(double radius, double rise, double step_deg, int count) {
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < count; ++k)
    p.emplace_back(radius * std::cos(to_radians(k * step_deg)), radius * std::sin(to_radians(k * step_deg)), rise * k);
  return p;
}

// Folds the designed string with the general solver (driven crease fixed at 2 theta0,
// Newton from the closed form) and maps the folded spine into the design frame by the
// rigid motion fixed by frame C_0 (no fitting). Returns max |P_k - Q_k|.
double verified_target_error(const MiuraString& designed, double theta0, const StringPose& pose,
                             const std::vector<Eigen::Vector3d>& target) {
  MiuraString s = designed;
  s.width = 0.9 * max_string_width(s);
  const StringState st = string_forward(s, theta0);
  const CreasePattern p = build_string_pattern(s, st.edge_fold_angles);
  const StringVerification v = verify_string_with_general_solver(s, p, st, 1e-4);
  EXPECT_TRUE(v.converged);
  EXPECT_LE(v.closure_residual, 1e-12);
  const StringPose pp = pattern_pose(theta0);
  const Eigen::Matrix3d R = pose.frame * pp.frame.transpose();
  double worst = 0;
  for (std::size_t k = 0; k < target.size(); ++k)
    worst = std::max(worst, (R * (v.folded.vertices[k] - pp.start) + pose.start - target[k]).norm());
  return worst;
}

TEST(StringInverse, DeflectionsRecoverTheAlphasOfATransmittedString) {
  const MiuraString s = random_string(40, 1, 15, 75);
  const double theta0 = 0.35;
  const StringState st = string_forward(s, theta0);
  std::vector<double> phi, psi;
  for (const auto& v : st.vertices) {
    phi.push_back(v.phi);
    psi.push_back(v.psi);
  }
  const DeflectionDesign d = design_from_deflections(phi, psi, transmitted_thetas(theta0, 40));
  ASSERT_TRUE(d.feasible);
  for (int i = 0; i < 40; ++i) {
    EXPECT_NEAR(d.vertices[i].alpha1, s.alpha1[i], 1e-11);
    EXPECT_NEAR(d.vertices[i].alpha2, s.alpha2[i], 1e-11);
    EXPECT_LE(std::fabs(d.vertices[i].phi_error), 1e-13);
    EXPECT_LE(std::fabs(d.vertices[i].psi_error), 1e-13);
  }
  // Same targets at the wrong sign pattern (all theta equal): odd vertices need phi of
  // the sign of theta, so they are reported unreachable.
  const DeflectionDesign bad = design_from_deflections(phi, psi, std::vector<double>(40, theta0));
  EXPECT_FALSE(bad.feasible);
  EXPECT_TRUE(bad.vertices[0].feasible);
  EXPECT_FALSE(bad.vertices[1].feasible);
  EXPECT_FALSE(bad.vertices[1].reason.empty());
}

TrajectoryTarget trajectories_of(const MiuraString& s, const std::vector<double>& thetas) {
  TrajectoryTarget t;
  t.theta = thetas;
  t.phi.assign(s.size(), {});
  t.psi.assign(s.size(), {});
  for (double th : thetas) {
    const StringState st = string_forward(s, th);
    for (int i = 0; i < s.size(); ++i) {
      t.phi[i].push_back(st.vertices[i].phi);
      t.psi[i].push_back(st.vertices[i].psi);
    }
  }
  return t;
}

TEST(StringCeres, TrajectoriesFromAGenericStartRecoverTheString) {
  const MiuraString s = random_string(30, 2, 20, 70);
  TrajectoryTarget t = trajectories_of(s, {0.1, 0.2, 0.3, 0.4, 0.5});
  const TrajectoryFitResult r = fit_string_trajectories(t, {}, 200, /*closed_form_start=*/false);
  EXPECT_TRUE(r.converged) << r.report;
  EXPECT_LE(r.max_residual, 1e-10);
  for (int i = 0; i < 30; ++i) {
    EXPECT_NEAR(r.alpha1[i], s.alpha1[i], 1e-8);
    EXPECT_NEAR(r.alpha2[i], s.alpha2[i], 1e-8);
  }
  EXPECT_TRUE(r.binding.empty());
}

TEST(StringCeres, NoisyAndOutOfBoundsTrajectoriesGiveTheBestFitAndTheBindingBound) {
  MiuraString s = random_string(4, 3, 30, 60);
  s.alpha1[2] = to_radians(5);  // below the default alpha_min = 10 deg
  s.width = 0.5 * max_string_width(s);
  TrajectoryTarget t = trajectories_of(s, {0.1, 0.25, 0.4});
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0, 1e-4);
  for (auto& row : t.phi)
    for (auto& v : row) v += noise(rng);
  const TrajectoryFitResult r = fit_string_trajectories(t);
  // alpha1[2] binds; alpha2[2] may follow it to the bound in the best fit; no other vertex.
  ASSERT_FALSE(r.binding.empty()) << r.report;
  EXPECT_EQ(r.binding[0], "alpha1[2] = alpha_min");
  for (const auto& b : r.binding) EXPECT_NE(b.find("[2]"), std::string::npos) << b;
  EXPECT_GT(r.vertex_rms[2], 1e-3);   // cannot follow
  EXPECT_LT(r.vertex_rms[0], 3e-4);   // noise level
  EXPECT_LT(r.vertex_rms[1], 3e-4);
}

TEST(StringCurve, Reachable100VertexHelixIsReproducedAndVerifiedByTheGeneralSolver) {
  // A helix sampled at nearly half a turn per point with a large rise: consecutive turns
  // alternate, which a transmitted string (theta_i = (-1)^i theta0) can follow.
  const auto target = helix(0.15, 1.0, 172, 102);
  const CurveDesign d = design_from_curve(target);
  ASSERT_TRUE(d.feasible) << "first infeasible vertex " << d.first_infeasible;
  double total = 0;
  for (double L : d.string.lengths) total += L;
  const double seg = total / 101;
  double max_err, rms;
  curve_errors(d.string, d.theta0, d.pose, target, max_err, rms);
  EXPECT_LE(max_err, 1e-9 * seg);
  EXPECT_LE(verified_target_error(d.string, d.theta0, d.pose, target), 1e-9 * seg);
}

TEST(StringCurve, UnreachableHelixGetsTheBestFitAndBindingBounds) {
  // A smooth helix turns the same way at every vertex: the alternating theta cannot follow.
  const auto target = helix(3.0, 0.3, 20, 22);
  const CurveDesign seed = design_from_curve(target);
  EXPECT_FALSE(seed.feasible);
  double seed_max, seed_rms;
  curve_errors(seed.string, seed.theta0, seed.pose, target, seed_max, seed_rms);
  NloptFitOptions o;
  o.max_time = 20;
  const NloptFitResult r = fit_string_to_curve(target, o);
  EXPECT_FALSE(r.reachable);
  EXPECT_GT(r.max_error, 1e-3);
  EXPECT_LT(r.rms_error, seed_rms);  // better than the clamped closed form
  EXPECT_FALSE(r.binding.empty());
  // The reported errors are the real ones: the forward model at the returned design.
  double m, q;
  curve_errors(r.string, r.theta0, r.pose, target, m, q);
  EXPECT_DOUBLE_EQ(m, r.max_error);
}

TEST(StringCurve, NloptFindsAnExactDesignWhenTheClosedFormSeedIsWrong) {
  // Target from a known string; the seed is forced to a wrong theta0 and roll, so only
  // the optimiser can reach the points.
  const MiuraString s = random_string(10, 8, 35, 60);
  const double theta0 = 0.5;
  StringPose pose;
  pose.start = Eigen::Vector3d(1, 2, 3);
  const StringState st = string_forward(s, theta0, pose);
  NloptFitOptions o;
  o.seed.theta0 = 0.2;
  o.seed.roll = 0.4;
  o.tolerance = 1e-7;
  const NloptFitResult r = fit_string_to_curve(st.spine, o);
  EXPECT_FALSE(r.seed_feasible && std::fabs(r.theta0 - 0.2) < 1e-12);
  EXPECT_TRUE(r.reachable) << r.status << " max error " << r.max_error;
  EXPECT_TRUE(r.binding.empty());
}

}}  // namespace
}  // namespace rigidfold::design
