#include "design/sorce/sorce_profile.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "design/sorce/sorce_taylor.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

Vec2 perp(const Vec2& v) { return Vec2(-v.y(), v.x()); }  // J v

double signed_curvature(const Vec2& d1, const Vec2& d2) {
  const double speed = d1.norm();
  const double cross = d1.x() * d2.y() - d1.y() * d2.x();
  if (speed == 0.0) return cross >= 0.0 ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  return cross / (speed * speed * speed);
}

VectorJet split_jet(const FoldMotion& m, double t) { return m.d ? m.d(t) : VectorJet{}; }

double fold_sign(double gamma, double dgamma) {
  const double s = gamma != 0.0 ? gamma : dgamma;
  return s > 0.0 ? 1.0 : (s < 0.0 ? -1.0 : 0.0);
}

std::string number(double x) { return std::to_string(x); }

}  // namespace

// eqs 56/57 from eq 54 (i = left: theta_l = 0, r_l = (0, z_l); j = right: theta_r = gamma,
// r_r = d + R(gamma)(0, z_r)): with q = r_r - r_l, s_l = q + J q' / gamma' and
// s_r = R(-gamma) J q' / gamma', where q' = d' + gamma' J R(gamma)(0, z_r) + R(gamma)(0, z_r')
// - (0, z_l'); expanding gives the forms in the header (the digest's restored signs). The
// tests compare both with planar_centrodes on the same poses, and eq 54 itself with finite
// differences of the contact and rolling conditions on random motions.
ProfilePoint profile_point(const FoldMotion& m, double t) {
  using detail::derivative_series;
  using detail::series;
  const Jet gj = m.gamma(t), zl = m.z_left(t), zr = m.z_right(t);
  const VectorJet dj = split_jet(m, t);
  if (gj[1] == 0.0) throw InputError("t", "gamma'(" + number(t) + ") = 0: the profile is undefined there (ill-behaved or a pivot)");
  const auto g = series<2>(gj), dg = derivative_series<2>(gj);
  const auto a = series<2>(zl), da = derivative_series<2>(zl);
  const auto b = series<2>(zr), db = derivative_series<2>(zr);
  const auto dx = series<2>(dj[0]), ddx = derivative_series<2>(dj[0]);
  const auto dy = series<2>(dj[1]), ddy = derivative_series<2>(dj[1]);
  const auto c = cos(g), s = sin(g);
  // eq 56: s_l = [z_r' u(pi + gamma) + z_l' u(0) + J d'] / gamma' - z_l e_y + d
  const auto lx = (da - db * c - ddy) / dg + dx;
  const auto ly = (ddx - db * s) / dg - a + dy;
  // eq 57: s_r = [z_l' u(-gamma) + z_r' u(pi) + R(pi/2 - gamma) d'] / gamma' - z_r e_y
  const auto rx = (da * c - db - c * ddy + s * ddx) / dg;
  const auto ry = (s * ddy + c * ddx - da * s) / dg - b;

  ProfilePoint p;
  p.t = t;
  p.gamma = gj[0];
  p.dgamma = gj[1];
  p.s_left = Vec2(lx.derivative(0), ly.derivative(0));
  p.ds_left = Vec2(lx.derivative(1), ly.derivative(1));
  p.dds_left = Vec2(lx.derivative(2), ly.derivative(2));
  p.s_right = Vec2(rx.derivative(0), ry.derivative(0));
  p.ds_right = Vec2(rx.derivative(1), ry.derivative(1));
  p.dds_right = Vec2(rx.derivative(2), ry.derivative(2));
  p.curvature_left = signed_curvature(p.ds_left, p.dds_left);
  p.curvature_right = signed_curvature(p.ds_right, p.dds_right);
  const double sg = fold_sign(p.gamma, p.dgamma);
  p.convexity_left = sg * p.curvature_left;
  p.convexity_right = -sg * p.curvature_right;
  return p;
}

double initial_contact_offset(const FoldMotion& m) {
  const double dg = m.gamma(0.0)[1];
  if (dg == 0.0) throw InputError("t", "gamma'(0) = 0: s0 (eq 20) is undefined");
  return (m.z_left(0.0)[1] - m.z_right(0.0)[1]) / dg;
}

FoldEndPoints end_points(const FoldMotion& m) {
  const Jet g0 = m.gamma(0.0), zl0 = m.z_left(0.0), zr0 = m.z_right(0.0);
  const VectorJet d0 = split_jet(m, 0.0);
  constexpr double kZero = 1e-12;
  if (std::abs(g0[0]) > kZero || std::abs(zl0[0]) > kZero || std::abs(zr0[0]) > kZero ||
      std::abs(d0[0][0]) > kZero || std::abs(d0[1][0]) > kZero)
    throw InputError("motion", "gamma, z and d must vanish at t = 0 (flat and coplanar)");
  if (g0[1] == 0.0) throw InputError("t", "gamma'(0) = 0: no analytic end point at t = 0");
  FoldEndPoints e;
  // eq 29 (+ the split term J d'/gamma' of eqs 56/57 at gamma = 0, where both agree).
  const Vec2 dd0(d0[0][1], d0[1][1]);
  e.left0 = (Vec2(zl0[1] - zr0[1], 0.0) + perp(dd0)) / g0[1];
  e.right0 = e.left0;

  const Jet g1 = m.gamma(1.0);
  if (g1[1] == 0.0) throw InputError("t", "gamma'(1) = 0: no analytic end point at t = 1");
  e.flat_folded_end = std::abs(std::abs(g1[0]) - kPi) <= 1e-12;
  if (!e.flat_folded_end) {
    const ProfilePoint p = profile_point(m, 1.0);
    e.left1 = p.s_left;
    e.right1 = p.s_right;
    return e;
  }
  const Jet zl1 = m.z_left(1.0), zr1 = m.z_right(1.0);
  const VectorJet d1 = split_jet(m, 1.0);
  const Vec2 d(d1[0][0], d1[1][0]), dd(d1[0][1], d1[1][1]);
  // eqs 30, 31 with gamma = +-pi exactly: u(pi + gamma) = e_x, u(-gamma) = u(pi) = -e_x,
  // R(pi/2 - gamma) = R(-pi/2) = -J.
  const double lateral = (zl1[1] + zr1[1]) / g1[1];
  e.left1 = Vec2(lateral, -zl1[0]) + perp(dd) / g1[1] + d;
  e.right1 = Vec2(-lateral, -zr1[0]) - perp(dd) / g1[1];
  return e;
}

CentrodePair planar_centrodes(const PlanarPose& i, const PlanarPose& j) {
  const double w = i.dtheta - j.dtheta;
  if (w == 0.0) throw InputError("dtheta", "no relative rotation: the motion is ill-behaved (eq 50)");
  // eq 54 and its swap.
  CentrodePair c;
  c.s_ij = rotation(-i.theta) * (j.dtheta * (i.r - j.r) + perp(i.dr - j.dr)) / w;
  c.s_ji = rotation(-j.theta) * (i.dtheta * (j.r - i.r) + perp(j.dr - i.dr)) / (-w);
  return c;
}

FoldPoses fold_poses(const FoldMotion& m, double t) {
  const Jet g = m.gamma(t), zl = m.z_left(t), zr = m.z_right(t);
  const VectorJet dj = split_jet(m, t);
  FoldPoses p;
  p.left.r = Vec2(0.0, zl[0]);
  p.left.dr = Vec2(0.0, zl[1]);
  const Eigen::Matrix2d R = rotation(g[0]);
  const Vec2 up(0.0, zr[0]);
  p.right.theta = g[0];
  p.right.dtheta = g[1];
  p.right.r = Vec2(dj[0][0], dj[1][0]) + R * up;
  p.right.dr = Vec2(dj[0][1], dj[1][1]) + g[1] * perp(R * up) + R * Vec2(0.0, zr[1]);
  return p;
}

RollingResidual rolling_residual(const FoldMotion& m, double t) {
  const ProfilePoint p = profile_point(m, t);
  const Eigen::Matrix2d R = rotation(p.gamma);
  const VectorJet dj = split_jet(m, t);
  const Vec2 d(dj[0][0], dj[1][0]);
  RollingResidual r;
  r.rolling = (p.ds_left - R * p.ds_right).norm();
  r.contact = (p.s_left + Vec2(0.0, m.z_left(t)[0]) - R * (p.s_right + Vec2(0.0, m.z_right(t)[0])) - d).norm();
  return r;
}

SampledProfiles sample_profiles(const FoldMotion& motion, int samples) {
  if (samples < 2) throw InputError("samples", "need at least 2 points per profile");
  const FoldEndPoints ends = end_points(motion);
  SampledProfiles s;
  for (int k = 0; k < samples; ++k) {
    const double t = static_cast<double>(k) / (samples - 1);
    if (k == 0 || k == samples - 1) {
      s.t.push_back(t);
      s.left.push_back(k == 0 ? ends.left0 : ends.left1);
      s.right.push_back(k == 0 ? ends.right0 : ends.right1);
      continue;
    }
    try {
      const ProfilePoint p = profile_point(motion, t);
      s.t.push_back(t);
      s.left.push_back(p.s_left);
      s.right.push_back(p.s_right);
    } catch (const InputError&) {  // gamma'(t) = 0: fold_report lists it (ill_behaved / stationary)
    }
  }
  return s;
}

}  // namespace rigidfold::sorce
