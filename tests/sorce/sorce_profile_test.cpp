// SORCE (seed 002) profile pairs: the circle oracle, the eq 28 closed forms of vertex A,
// end points as analytic limits (eqs 29-31), eqs 56/57 against the general planar
// centrode (eq 54), which is itself checked on random motions by finite differences, and
// the built-in rolling and contact residuals.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "design/sorce/sorce_profile.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::vertex_a_linear;
using testing::vertex_b_split;

std::vector<double> grid(int n) {
  std::vector<double> t;
  for (int k = 0; k <= n; ++k) t.push_back(static_cast<double>(k) / n);
  return t;
}

Eigen::Matrix2d rot(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

// All example folds (vertex A linear, vertex B eq 60, eq 61, circular construction).
std::vector<FoldMotion> example_folds() {
  std::vector<FoldMotion> folds;
  for (const SorceVertex& v : {vertex_a_linear(1.0), vertex_a_linear(0.37), vertex_b_split(1), vertex_b_split(2),
                               circular_split_vertex(testing::vertex_b_sectors(), VertexParameterization::kSymmetric, 0.1)})
    for (const FoldMotion& f : v.folds) folds.push_back(f);
  return folds;
}

// Circle oracle (section 3): z_l = z_r = -r tan(gamma/4) gives circles of radius r centred
// at (-r, 0) (left) and (r, 0) (right), convexity 1/r on both, for valleys and mountains and
// any parameterization of gamma.
TEST(SorceProfile, CircleOracle) {
  const double r = 0.3;
  for (const ScalarFunction& gamma : {linear_fold(kPi), linear_fold(-kPi), tan_half_fold(2.0), tan_half_fold(-0.6)}) {
    FoldMotion m{gamma, circular_offset(r, gamma), circular_offset(r, gamma), {}, 2 * r, 2 * r};
    double radius_error = 0.0, convexity_error = 0.0;
    for (double t : grid(200)) {
      const ProfilePoint p = profile_point(m, t);
      radius_error = std::max({radius_error, std::abs((p.s_left - Vec2(-r, 0)).norm() - r), std::abs((p.s_right - Vec2(r, 0)).norm() - r)});
      convexity_error = std::max({convexity_error, std::abs(p.convexity_left - 1 / r), std::abs(p.convexity_right - 1 / r)});
    }
    EXPECT_LE(radius_error, 1e-10);
    EXPECT_LE(convexity_error, 1e-10);
    // The contact starts on the fold line (s0 = 0) and ends on the zero-thickness plane (eq 30).
    EXPECT_NEAR(initial_contact_offset(m), 0.0, 1e-15);
    const FoldEndPoints e = end_points(m);
    const double sgn = gamma(1.0)[0] > 0 ? 1.0 : -1.0;
    EXPECT_NEAR((e.left1 - Vec2(-r, sgn * r)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((e.right1 - Vec2(r, sgn * r)).norm(), 0.0, 1e-15);
  }
}

// eq 28 (digest's restored signs), P = pi t.
std::array<Vec2, 8> eq28(double d, double mu, double t) {
  const double P = kPi * t, c = std::cos(P), s = std::sin(P);
  const double a = 3 * d / (2 * kPi * mu), b = d / (2 * kPi), e = d / (2 * kPi * mu);
  return {a * Vec2(-1 + c, mu * (P + s)), a * Vec2(1 - c, mu * (P + s)), b * Vec2(-3 - c, 3 * P - s),
          b * Vec2(-1 - 3 * c, -P + 3 * s),  e * Vec2(-1 + c, -mu * (P + s)), e * Vec2(1 - c, -mu * (P + s)),
          b * Vec2(1 + 3 * c, -P + 3 * s),   b * Vec2(3 + c, 3 * P - s)};
}

TEST(SorceProfile, VertexAReproducesEq28ClosedForms) {
  const double mu = std::sin(to_radians(100)) / std::sin(to_radians(20));
  for (double d : {1.0, 0.37}) {
    const SorceVertex v = vertex_a_linear(d);
    double worst = 0.0;
    for (double t : grid(400)) {
      const auto cf = eq28(d, mu, t);
      for (int j = 0; j < 4; ++j) {
        const ProfilePoint p = profile_point(v.folds[j], t);
        worst = std::max({worst, (p.s_left - cf[2 * j]).norm(), (p.s_right - cf[2 * j + 1]).norm()});
      }
    }
    EXPECT_LE(worst, 1e-10) << "d " << d;  // measured 4.4e-16 at d = 1
    // End points by their limits (eqs 29-31) against eq 28 at t = 0 and 1.
    const auto c0 = eq28(d, mu, 0.0), c1 = eq28(d, mu, 1.0);
    for (int j = 0; j < 4; ++j) {
      const FoldEndPoints e = end_points(v.folds[j]);
      EXPECT_TRUE(e.flat_folded_end);
      EXPECT_LE((e.left0 - c0[2 * j]).norm(), 1e-14);
      EXPECT_LE((e.right0 - c0[2 * j + 1]).norm(), 1e-14);
      EXPECT_LE((e.left1 - c1[2 * j]).norm(), 1e-14);
      EXPECT_LE((e.right1 - c1[2 * j + 1]).norm(), 1e-14);
      EXPECT_NEAR(initial_contact_offset(v.folds[j]), c0[2 * j].x(), 1e-15);  // eq 20 = eq 29
    }
  }
}

// End points from the limit forms agree with eqs 56/57 evaluated at t = 0 and 1 with exact
// derivatives, also for the split folds (the J d' terms).
TEST(SorceProfile, EndPointsAgreeWithProfileAtTheEnds) {
  for (const FoldMotion& m : example_folds()) {
    const FoldEndPoints e = end_points(m);
    const ProfilePoint p0 = profile_point(m, 0.0), p1 = profile_point(m, 1.0);
    EXPECT_LE((e.left0 - p0.s_left).norm(), 1e-14);
    EXPECT_LE((e.right0 - p0.s_right).norm(), 1e-14);
    EXPECT_LE((e.left1 - p1.s_left).norm(), 1e-14);
    EXPECT_LE((e.right1 - p1.s_right).norm(), 1e-14);
    // Contact on the zero-thickness plane at both ends: s_l(1).y = -z_l(1) (eq 30) unless split.
    if (!m.d) {
      EXPECT_NEAR(e.left1.y(), -m.z_left(1.0)[0], 1e-15);
    }
  }
}

// eq 54 on random planar motions: the two centrode points coincide in the world (eq 42) and
// roll (eq 43: R_i s_ij' = R_j s_ji'), derivatives by central differences.
TEST(SorceProfile, GeneralPlanarCentrodesRollOnRandomMotions) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    double c[10];
    for (double& x : c) x = u(rng);
    auto pose_i = [&](double t) {
      return PlanarPose{c[0] * t + 0.3 * t * t, c[0] + 0.6 * t, Vec2(c[1] * t, c[2] * t * t), Vec2(c[1], 2 * c[2] * t)};
    };
    auto pose_j = [&](double t) {
      return PlanarPose{c[3] + 2.0 * t, 2.0, Vec2(c[4] + c[5] * std::sin(t), c[6] * t * t * t),
                        Vec2(c[5] * std::cos(t), 3 * c[6] * t * t)};
    };
    auto at = [&](double t) { return planar_centrodes(pose_i(t), pose_j(t)); };
    for (double t : {0.2, 0.45, 0.8}) {
      const PlanarPose pi = pose_i(t), pj = pose_j(t);
      if (std::abs(pi.dtheta - pj.dtheta) < 0.2) continue;  // keep away from ill-behaved t
      const CentrodePair s = at(t);
      EXPECT_LE((rot(pi.theta) * s.s_ij + pi.r - rot(pj.theta) * s.s_ji - pj.r).norm(), 1e-12);
      const double h = 1e-6;
      const Vec2 dij = (at(t + h).s_ij - at(t - h).s_ij) / (2 * h), dji = (at(t + h).s_ji - at(t - h).s_ji) / (2 * h);
      EXPECT_LE((rot(pi.theta) * dij - rot(pj.theta) * dji).norm(), 1e-7 * std::max(1.0, dij.norm()));
    }
  }
  EXPECT_THROW(planar_centrodes(PlanarPose{0, 1, Vec2(0, 0), Vec2(1, 0)}, PlanarPose{1, 1, Vec2(0, 0), Vec2(0, 0)}), InputError);
}

// eqs 56/57 (and 18/19) are eq 54 applied to the fold's poses (eq 55).
TEST(SorceProfile, FoldProfilesAreGeneralCentrodes) {
  double worst = 0.0;
  for (const FoldMotion& m : example_folds()) {
    for (double t : grid(100)) {
      const FoldPoses poses = fold_poses(m, t);
      const CentrodePair c = planar_centrodes(poses.left, poses.right);
      const ProfilePoint p = profile_point(m, t);
      worst = std::max({worst, (c.s_ij - p.s_left).norm(), (c.s_ji - p.s_right).norm()});
    }
  }
  EXPECT_LE(worst, 1e-12);
}

// Exact profile derivatives against central differences of the profile, inside (0, 1).
TEST(SorceProfile, ProfileDerivativesMatchFiniteDifferencesInside) {
  const double h = 1e-5;
  for (const FoldMotion& m : example_folds()) {
    for (double t : {0.1, 0.35, 0.6, 0.9}) {
      const ProfilePoint a = profile_point(m, t - h), b = profile_point(m, t + h), p = profile_point(m, t);
      EXPECT_LE(((b.s_left - a.s_left) / (2 * h) - p.ds_left).norm(), 1e-8 * std::max(1.0, p.ds_left.norm()));
      EXPECT_LE(((b.s_right - a.s_right) / (2 * h) - p.ds_right).norm(), 1e-8 * std::max(1.0, p.ds_right.norm()));
      EXPECT_LE(((b.ds_left - a.ds_left) / (2 * h) - p.dds_left).norm(), 1e-7 * std::max(1.0, p.dds_left.norm()));
    }
  }
}

// Rolling (s_l' = R(gamma) s_r') and contact (eq 14 with d) residuals along every profile.
TEST(SorceProfile, RollingAndContactResidualsVanish) {
  double rolling = 0.0, contact = 0.0;
  for (const FoldMotion& m : example_folds()) {
    for (double t : grid(500)) {
      const RollingResidual r = rolling_residual(m, t);
      rolling = std::max(rolling, r.rolling);
      contact = std::max(contact, r.contact);
    }
  }
  EXPECT_LE(rolling, 1e-10);  // measured ~1e-15
  EXPECT_LE(contact, 1e-10);
}

// A wrong sign in the split term is caught by the contact residual (the check can fail).
TEST(SorceProfile, ResidualDetectsAWrongSplitOffset) {
  FoldMotion m = vertex_b_split(1).folds[2];
  const VectorFunction d = m.d;
  FoldMotion wrong = m;
  wrong.d = [d](double t) {  // the profile is generated with -d, checked against +d
    VectorJet v = d(t);
    for (auto& c : v)
      for (double& x : c) x = -x;
    return v;
  };
  const ProfilePoint p = profile_point(wrong, 0.5);
  const Eigen::Matrix2d R = rot(p.gamma);
  const VectorJet dj = d(0.5);
  const double contact = (p.s_left + Vec2(0, m.z_left(0.5)[0]) - R * (p.s_right + Vec2(0, m.z_right(0.5)[0])) - Vec2(dj[0][0], dj[1][0])).norm();
  EXPECT_GT(contact, 1e-2);
}

TEST(SorceProfile, UndefinedWhereGammaRateVanishes) {
  FoldMotion m{[](double t) { return Jet{2 * t * (1 - t), 2 - 4 * t, -4, 0}; }, power_function(0.1, 1), power_function(0.1, 1), {}, 0, 0};
  EXPECT_THROW(profile_point(m, 0.5), InputError);
  EXPECT_NO_THROW(profile_point(m, 0.4));
}

}}  // namespace
}  // namespace rigidfold::sorce
