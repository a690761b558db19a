#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/math/angle_units.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rigidfold {
namespace {


void check_alpha(double alpha, const char* name) {
  if (!std::isfinite(alpha) || !(alpha > 0.0) || !(alpha < kPi / 2))
    throw std::invalid_argument(std::string(name) + " must be finite and in (0, pi/2) rad, got " +
                                std::to_string(alpha));
}

// Pattern constants shared by every formula: p = sin(a1 + a2), q = sin(a2 - a1),
// S = sin a1 sin a2. p as s1 c2 + c1 s2 (two positive terms, no rounding of a1 + a2 near
// pi); q from a2 - a1 itself, so it is exactly 0 for a symmetric vertex and accurate
// when the alphas are close (cot a1 - cot a2 would cancel).
struct Pattern {
  double s1, c1, s2, c2, p, q, S;
};

Pattern pattern(double alpha1, double alpha2) {
  Pattern k;
  k.s1 = std::sin(alpha1);
  k.c1 = std::cos(alpha1);
  k.s2 = std::sin(alpha2);
  k.c2 = std::cos(alpha2);
  k.p = k.s1 * k.c2 + k.c1 * k.s2;
  k.q = std::sin(alpha2 - alpha1);
  k.S = k.s1 * k.s2;
  return k;
}

// tan^2 theta_limit = p / |q|: at that theta the peripheral crease next to the smaller
// alpha reaches |rho| = pi (derivation in the header). atan2 of square roots stays exact
// at q = 0 (pi/2) and needs no acos near 1 (eq. 40 loses half the digits there).
double theta_limit(const Pattern& k) { return std::atan2(std::sqrt(k.p), std::sqrt(std::fabs(k.q))); }

void check_theta(double theta, double limit) {
  if (!std::isfinite(theta)) throw std::invalid_argument("theta must be finite");
  if (!(std::fabs(theta) <= limit))
    throw std::invalid_argument("theta = " + std::to_string(theta) + " rad is outside [-theta_limit, theta_limit], theta_limit = " +
                                std::to_string(limit) + " rad");
}

// The seed's f scaled by 4 S^2 sin^2 theta (> 0, so the direction is unchanged); see the header.
Eigen::Vector3d scaled_f(const Pattern& k, double s, double c) {
  const double t = s / c;  // c >= cos(theta_limit) > 0 unless q == 0, where q t == 0 anyway
  const double two_S_s = 2.0 * k.S * std::fabs(s);
  const double qt = k.q * t;
  return {std::fma(qt, qt, (k.p - two_S_s) * (k.p + two_S_s)), 4.0 * k.S * k.q * s * t, 4.0 * k.S * k.p * s};
}

}  // namespace

double miura_theta_limit(double alpha1, double alpha2) {
  check_alpha(alpha1, "alpha1");
  check_alpha(alpha2, "alpha2");
  return theta_limit(pattern(alpha1, alpha2));
}

std::array<double, 4> miura_sectors(double alpha1, double alpha2) {
  return {alpha1, kPi - alpha1, kPi - alpha2, alpha2};
}

MiuraVertexState miura_vertex(double alpha1, double alpha2, double theta) {
  check_alpha(alpha1, "alpha1");
  check_alpha(alpha2, "alpha2");
  const Pattern k = pattern(alpha1, alpha2);
  MiuraVertexState st;
  st.theta = theta;
  st.theta_limit = theta_limit(k);
  check_theta(theta, st.theta_limit);

  const double s = std::sin(theta), c = std::cos(theta);
  const Eigen::Vector3d G = scaled_f(k, s, c);
  const double g = G.norm();
  // w = g (1 - a_x) without cancellation when a_x is close to 1 (near flat).
  const double w = G.x() > 0.0 ? (G.y() * G.y() + G.z() * G.z()) / (g + G.x()) : g - G.x();

  st.phi = std::atan2(G.z(), G.x());
  // arctan(G_y / G_x) without the division: fold the atan2 result into [-pi/2, pi/2].
  st.psi = G.x() >= 0.0 ? std::atan2(G.y(), G.x()) : std::atan2(-G.y(), -G.x());
  st.spinal_out = G / g;

  st.crease_directions[kMiuraSpinalOut] = st.spinal_out;
  st.crease_directions[kMiuraPeripheral1] = {k.c1, k.s1 * c, k.s1 * s};
  st.crease_directions[kMiuraSpinalIn] = {-1.0, 0.0, 0.0};
  st.crease_directions[kMiuraPeripheral2] = {k.c2, -k.s2 * c, k.s2 * s};

  // Fold angles of b and d: sin rho_b = a . n_bc / sin a1, 1 - cos rho_b = (1 - a_x) / sin^2 a1,
  // and the same for d with n_cd, sin a2; both scaled here by g sin^2 a (> 0). The sine is
  // 4 S sin t (p cos t -+ q sin t tan t), whose bracket is >= 0 in exact arithmetic for
  // |theta| <= theta_limit (it vanishes at the limit, where |rho| = pi); clamping it keeps
  // rho = +-pi on the side of sign(theta) instead of a rounding-driven flip to -+pi.
  const double qst = k.q * s * (s / c);
  const double sin_b = 4.0 * k.S * s * std::fmax(k.p * c - qst, 0.0) * k.s1;
  const double sin_d = 4.0 * k.S * s * std::fmax(k.p * c + qst, 0.0) * k.s2;
  st.fold_angles[kMiuraSpinalOut] = -2.0 * theta;
  st.fold_angles[kMiuraPeripheral1] = std::atan2(sin_b, k.s1 * k.s1 * g - w);
  st.fold_angles[kMiuraSpinalIn] = 2.0 * theta;
  st.fold_angles[kMiuraPeripheral2] = std::atan2(sin_d, k.s2 * k.s2 * g - w);

  st.sectors = miura_sectors(alpha1, alpha2);
  st.flat_directions = {0.0, alpha1, kPi, 2.0 * kPi - alpha2};
  return st;
}

Eigen::Matrix3d miura_vertex_rotation(double alpha1, double alpha2, double theta) {
  const MiuraVertexState st = miura_vertex(alpha1, alpha2, theta);
  const Pattern k = pattern(alpha1, alpha2);
  const Eigen::Vector3d x = st.spinal_out;
  // n_ab + n_da = a x (b / sin a1 - d / sin a2) = a x (cot a1 - cot a2, 2 cos t, 0), scaled
  // by sin a1 sin a2: a x (q, 2 S cos t, 0). Nonzero for |rho_a| < pi, and its direction
  // stays defined at the symmetric full fold (q = 0, cos t -> 0).
  const Eigen::Vector3d z = x.cross(Eigen::Vector3d(k.q, 2.0 * k.S * std::cos(theta), 0.0)).normalized();
  Eigen::Matrix3d R;
  R.col(0) = x;
  R.col(1) = z.cross(x);
  R.col(2) = z;
  return R;
}

}  // namespace rigidfold
