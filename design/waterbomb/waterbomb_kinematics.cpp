#include "design/waterbomb/waterbomb_kinematics.hpp"

#include <cmath>
#include <string>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::waterbomb {

double sector_angle(int n) {
  if (n < 3 || n > 180)
    throw InputError("n", "the number of mountain (= valley) creases must be between 3 and 180, got " +
                              std::to_string(n));
  return kPi / n;
}

double theta_limit(int n) { return kPi - sector_angle(n); }

namespace {
void check_theta(int n, double theta) {
  const double limit = theta_limit(n);
  if (!std::isfinite(theta) || theta < 0.0 || theta > limit)
    throw InputError("theta", "must lie in [0, " + std::to_string(to_degrees(limit)) +
                                  "] deg (valley creases reach 180 deg at the upper end, mountains at 0), got " +
                                  std::to_string(to_degrees(theta)) + " deg");
}
}  // namespace

FoldPair waterbomb_fold_angles(int n, double theta) {
  check_theta(n, theta);
  const double a = sector_angle(n);
  const double c = std::cos(theta), s = std::sin(theta);
  const double psi = std::atan2(std::cos(a), std::sin(a) * c);
  const double omega = std::atan2(std::fabs(c), std::cos(a) * s);
  // |pi - 2 theta| is exact in floating point up to one rounding (no cancellation in a cosine).
  // 0.0 - |.| so that flat gives +0, not -0.
  return {0.0 - std::fabs(kPi - 2.0 * theta), 2.0 * (psi + omega) - kPi};
}

FoldPair waterbomb_fold_angle_derivatives(int n, double theta, int side) {
  check_theta(n, theta);
  const double a = sector_angle(n);
  const double ca = std::cos(a), sa = std::sin(a);
  const double c = std::cos(theta), s = std::sin(theta);
  // Side of the flat state: +1 below (range a), -1 above (range b); at flat the caller's side.
  const double sgn = theta < kPi / 2 ? 1.0 : (theta > kPi / 2 ? -1.0 : (side > 0 ? -1.0 : 1.0));
  const double dpsi = ca * sa * s / (ca * ca + sa * sa * c * c);
  const double domega = -sgn * ca / (ca * ca * s * s + c * c);
  return {2.0 * sgn, 2.0 * (dpsi + domega)};
}

FoldPair seed_traditional_fold_angles(double theta) {
  const double deg90 = kPi / 2;
  const double c = std::acos(std::cos(theta) * std::cos(theta));                         // (2.1)
  const double gm = std::acos(2.0 * std::cos(theta) * std::cos(theta) - 1.0) - kPi;        // (2.6)
  double gv;
  if (theta <= deg90)
    gv = 2.0 * (std::asin(std::sin(theta) / std::sin(c)) + std::acos(std::sin(c) / (std::cos(c) + 1.0)) - deg90);  // (2.7)
  else
    gv = 2.0 * (std::acos(1.0 / std::sin(c) - 1.0 / std::tan(c)) - std::asin(std::sin(theta) / std::sin(c)) + deg90);  // (2.8)
  return {gm, gv};
}

FoldPair seed_general_fold_angles(int n, double theta) {
  const double a = kPi / n, b = 2.0 * kPi / n;
  const double ct = std::cos(theta), st = std::sin(theta);
  const double d = std::acos(ct * ct + st * st * std::cos(b));                                       // (3.6)
  const double gm = -kPi + std::acos(1.0 + (std::cos(d) - 1.0) / (std::sin(a) * std::sin(a)));        // (3.4)
  const double base = 2.0 * std::acos(std::tan(d / 2) / std::tan(a));
  double gv;
  if (theta <= kPi / 2)
    gv = -kPi + base + 2.0 * std::acos(std::tan(d / 2) / std::tan(theta));                          // (3.5) a
  else
    gv = kPi - 2.0 * std::acos((std::cos(d) - 1.0) / std::tan(theta) / std::sin(d)) + base;          // (3.5) b
  return {gm, gv};
}

double seed_gamma_v_derivative(int n, double theta) {
  const double a = kPi / n, b = 2.0 * kPi / n;
  const double ct = std::cos(theta), st = std::sin(theta);
  const double d = std::acos(ct * ct + st * st * std::cos(b));
  const double dd = std::sin(2.0 * theta) * (1.0 - std::cos(b)) / std::sin(d);  // (3.12)
  const double cot_a = 1.0 / std::tan(a), cot_t = 1.0 / std::tan(theta), t2 = std::tan(d / 2);
  const double csc_d = 1.0 / std::sin(d), csc_t = 1.0 / st;
  // (3.11) as printed.
  return 2.0 * csc_d * (std::cos(d) - 1.0) *
         (cot_a * csc_d * dd / std::sqrt(1.0 - cot_a * cot_a * t2 * t2) +
          (cot_t * csc_d * dd - csc_t * csc_t) / std::sqrt(1.0 - cot_t * cot_t * t2 * t2));
}

double theta_on_path(int n, double gamma_m, double gamma_v, double* gamma_v_gap) {
  const double limit = theta_limit(n);
  double best = kPi / 2, gap = INFINITY;
  for (double theta : {(kPi + gamma_m) / 2, (kPi - gamma_m) / 2}) {
    if (!(theta >= 0.0 && theta <= limit)) continue;
    const double g = std::fabs(waterbomb_fold_angles(n, theta).gamma_v - gamma_v);
    if (g < gap) {
      gap = g;
      best = theta;
    }
  }
  if (gamma_v_gap) *gamma_v_gap = gap;
  return best;
}

Eigen::VectorXd waterbomb_edge_angles(const CreasePattern& base, FoldPair angles) {
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(base.num_edges());
  for (int e = 0; e < base.num_edges(); ++e) {
    if (base.assignments[e] == Assignment::Mountain) rho[e] = angles.gamma_m;
    if (base.assignments[e] == Assignment::Valley) rho[e] = angles.gamma_v;
  }
  return rho;
}

}  // namespace rigidfold::waterbomb
