#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/vertex/vertex_closure.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
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
// S = sin a1 sin a2, each divided by m = max(sin a1, sin a2). Every formula below is
// homogeneous of degree 0 or 2 in (p, q, S), so the division changes nothing in exact
// arithmetic; it keeps the products away from underflow when an alpha is tiny (alpha1 =
// 1e-170 deg left sin a1 sin^2 a1 = 0 and rho_b off by 80 deg). p as s1 c2 + c1 s2 (two
// positive terms, no rounding of a1 + a2 near pi); q from a2 - a1 itself, so it is exactly
// 0 for a symmetric vertex and accurate when the alphas are close.
struct Pattern {
  double s1, c1, s2, c2;
  double r1, r2;  // sin a1 / m, sin a2 / m, in (0, 1], one of them 1
  double p, q, S;  // scaled by 1 / m
};

Pattern pattern(double alpha1, double alpha2) {
  Pattern k;
  k.s1 = std::sin(alpha1);
  k.c1 = std::cos(alpha1);
  k.s2 = std::sin(alpha2);
  k.c2 = std::cos(alpha2);
  const double m = std::fmax(k.s1, k.s2);
  k.r1 = k.s1 / m;
  k.r2 = k.s2 / m;
  k.p = k.r1 * k.c2 + k.c1 * k.r2;
  k.q = std::sin(alpha2 - alpha1) / m;
  k.S = k.r1 * k.s2;
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

// The seed's f scaled by 4 S^2 sin^2 theta / m^2 (> 0, so the direction is unchanged); see the header.
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

  st.phi = std::atan2(G.z(), G.x());
  // arctan(G_y / G_x) without the division: fold the atan2 result into [-pi/2, pi/2].
  st.psi = G.x() >= 0.0 ? std::atan2(G.y(), G.x()) : std::atan2(-G.y(), -G.x());
  st.spinal_out = G / g;

  st.crease_directions[kMiuraSpinalOut] = st.spinal_out;
  st.crease_directions[kMiuraPeripheral1] = {k.c1, k.s1 * c, k.s1 * s};
  st.crease_directions[kMiuraSpinalIn] = {-1.0, 0.0, 0.0};
  st.crease_directions[kMiuraPeripheral2] = {k.c2, -k.s2 * c, k.s2 * s};

  // Fold angles of b and d: sin rho_b = a . n_bc / sin a1, 1 - cos rho_b = (1 - a_x) / sin^2 a1,
  // and the same for d with n_cd, sin a2. With G = (G_x, G_y, G_z) as scaled here,
  //   g sin rho_b       = 4 r2 sin t (p cos t - q sin t tan t),
  //   g (1 - cos rho_b) = 16 r2^2 sin^2 t (q^2 tan^2 t + p^2) / (g + G_x)     (G_x > 0),
  // (r2 = sin a2 / m; for d swap r1 and r2 and the sign of q): the factor sin^2 a1 of
  // 1 - a_x cancels analytically instead of in floating point, so a tiny alpha costs no
  // digits. G_x <= 0 only when 2 S |sin t| >= p, i.e. neither alpha is small, and then
  // g (1 - a_x) = g - G_x has no cancellation. The sine's bracket is >= 0 in exact
  // arithmetic for |theta| <= theta_limit (it vanishes at the limit, where |rho| = pi);
  // clamping it keeps rho = +-pi on the side of sign(theta) instead of a rounding flip.
  const double qst = k.q * s * (s / c);
  const double sin_b = 4.0 * k.r2 * s * std::fmax(k.p * c - qst, 0.0);
  const double sin_d = 4.0 * k.r1 * s * std::fmax(k.p * c + qst, 0.0);
  double cos_b, cos_d;
  if (G.x() > 0.0) {
    const double qt = k.q * (s / c);
    const double h = 16.0 * s * s * std::fma(qt, qt, k.p * k.p) / (g + G.x());  // times r^2 below
    cos_b = g - k.r2 * k.r2 * h;
    cos_d = g - k.r1 * k.r1 * h;
  } else {
    cos_b = g - (g - G.x()) / (k.s1 * k.s1);
    cos_d = g - (g - G.x()) / (k.s2 * k.s2);
  }
  st.fold_angles[kMiuraSpinalOut] = -2.0 * theta;
  st.fold_angles[kMiuraPeripheral1] = std::atan2(sin_b, cos_b);
  st.fold_angles[kMiuraSpinalIn] = 2.0 * theta;
  st.fold_angles[kMiuraPeripheral2] = std::atan2(sin_d, cos_d);

  st.sectors = miura_sectors(alpha1, alpha2);
  st.flat_directions = {0.0, alpha1, kPi, 2.0 * kPi - alpha2};
  return st;
}

MiuraVertexCheck check_miura_vertex(const MiuraVertexState& st) {
  MiuraVertexCheck out;
  const double r = vertex_closure_residual(std::span<const double>(st.sectors.data(), 4),
                                           std::span<const double>(st.fold_angles.data(), 4))
                       .norm();
  out.closure_residual = std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
  const double sign = (st.theta > 0) - (st.theta < 0);
  for (int i : {kMiuraPeripheral1, kMiuraPeripheral2}) {
    const double rho = st.fold_angles[i];
    const bool same_sign = sign == 0 ? rho == 0.0 : rho * sign >= 0.0;
    if (!(std::fabs(rho) <= kPi) || !same_sign) out.signs_ok = false;
  }
  if (st.fold_angles[kMiuraSpinalOut] != -2.0 * st.theta || st.fold_angles[kMiuraSpinalIn] != 2.0 * st.theta) out.signs_ok = false;
  return out;
}

MiuraVertexState miura_vertex_checked(double alpha1, double alpha2, double theta) {
  const MiuraVertexState st = miura_vertex(alpha1, alpha2, theta);
  const MiuraVertexCheck chk = check_miura_vertex(st);
  if (!chk.passed()) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "Miura vertex at alpha1 = %.17g, alpha2 = %.17g, theta = %.17g rad: closure residual %.3e rad "
                  "(tolerance %.0e)%s",
                  alpha1, alpha2, theta, chk.closure_residual, kMiuraClosureTolerance,
                  chk.signs_ok ? "" : ", fold-angle signs contradict the closed form");
    throw NoAnswerError(text, chk.closure_residual);
  }
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
