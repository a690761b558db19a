#include "design/metamaterial/square_twist_unit.hpp"
#include "kernel/math/angle_units.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <stdexcept>

namespace rigidfold::metamaterial {
namespace {


void check_alpha(double alpha) {
  if (!(alpha > kPi / 2 && alpha < kPi))
    throw std::invalid_argument("square twist: alpha must lie in (pi/2, pi) (seed 003 eq. 3-29b: gamma < pi/2)");
}

void check_angle(double angle, const char* name) {
  if (!(angle >= 0.0 && angle <= kPi))
    throw std::invalid_argument(std::string("square twist: ") + name + " must lie in [0, pi]");
}

void check_params(const SquareTwistUnitParams& p) {
  check_alpha(p.alpha);
  if (!(p.a > 0.0) || !std::isfinite(p.a)) throw std::invalid_argument("square twist: a must be > 0 and finite");
  if (!std::isfinite(p.b) || !std::isfinite(p.c)) throw std::invalid_argument("square twist: b and c must be finite");
}

// dphi/dtheta from tan(phi/2) = tan(theta/2) / mu, written without tangents so that it is
// smooth on all of [0, pi]: mu / (mu^2 cos^2(theta/2) + sin^2(theta/2)).
double dphi_dtheta(double mu, double theta) {
  const double c = std::cos(theta / 2), s = std::sin(theta / 2);
  return mu / (mu * mu * c * c + s * s);
}

// dH/dtheta / (a sin alpha) = cos(theta) + cos(phi) dphi/dtheta.
double height_slope(double mu, double theta) {
  const double phi = 2.0 * std::atan2(std::sin(theta / 2), mu * std::cos(theta / 2));
  return std::cos(theta) + std::cos(phi) * dphi_dtheta(mu, theta);
}

}  // namespace

double square_twist_mu(double alpha) {
  check_alpha(alpha);
  return (std::sin(alpha) - 1.0) / std::cos(alpha);
}

double square_twist_phi(double alpha, double theta) {
  check_angle(theta, "theta");
  const double mu = square_twist_mu(alpha);
  return 2.0 * std::atan2(std::sin(theta / 2), mu * std::cos(theta / 2));
}

double square_twist_theta(double alpha, double phi) {
  check_angle(phi, "phi");
  const double mu = square_twist_mu(alpha);
  return 2.0 * std::atan2(mu * std::sin(phi / 2), std::cos(phi / 2));
}

SquareTwistUnitState square_twist_unit(const SquareTwistUnitParams& p, double theta) {
  check_params(p);
  check_angle(theta, "theta");
  const double mu = square_twist_mu(p.alpha);
  const double sa = std::sin(p.alpha), ca = std::cos(p.alpha);
  SquareTwistUnitState u;
  u.theta = theta;
  u.phi = square_twist_phi(p.alpha, theta);
  u.dphi_dtheta = dphi_dtheta(mu, theta);
  u.L = 2 * p.c + p.a * (ca + sa * std::cos(u.theta));
  u.S = 2 * p.b + p.a * (ca + sa * std::cos(u.phi));
  u.H = p.a * sa * (std::sin(u.theta) + std::sin(u.phi));
  u.dL = -p.a * sa * std::sin(u.theta);
  u.dS = -p.a * sa * std::sin(u.phi) * u.dphi_dtheta;
  u.dH = p.a * sa * (std::cos(u.theta) + std::cos(u.phi) * u.dphi_dtheta);
  if (theta > 0.0 && theta < kPi) {
    // nu_SL = -(S/L) dL/dS, nu_HL = -(L/H) dH/dL (the corrected 3-32b definition).
    u.nu_SL = -(u.S / u.L) * (u.dL / u.dS);
    u.nu_HL = -(u.L / u.H) * (u.dH / u.dL);
  } else {
    u.nu_SL = u.nu_HL = std::numeric_limits<double>::quiet_NaN();
  }
  return u;
}

double square_twist_dphi_dtheta_implicit(double alpha, double theta, double phi) {
  const double sa = std::sin(alpha), ca = std::cos(alpha);
  return (ca * std::sin(theta) - sa * std::cos(theta) * std::sin(phi)) /
         (ca * std::sin(phi) + sa * std::sin(theta) * std::cos(phi));
}

double square_twist_nu_SL_printed(const SquareTwistUnitParams& p, double theta, double phi) {
  const double sa = std::sin(p.alpha), ca = std::cos(p.alpha);
  const double ratio = (2 * p.b + p.a * (ca + sa * std::cos(phi))) / (2 * p.c + p.a * (ca + sa * std::cos(theta)));
  const double num = std::sin(theta) * (ca * std::sin(phi) + sa * std::sin(theta) * std::cos(phi));
  const double den = std::sin(phi) * (ca * std::sin(theta) - sa * std::cos(theta) * std::sin(phi));
  return -ratio * num / den;
}

double square_twist_nu_HL_printed(const SquareTwistUnitParams& p, double theta, double phi) {
  const double sa = std::sin(p.alpha), ca = std::cos(p.alpha);
  const double ratio = (2 * p.c + p.a * (ca + sa * std::cos(theta))) / (p.a * sa * (std::sin(theta) + std::sin(phi)));
  const double inner = (ca * std::sin(theta) - sa * std::cos(theta) * std::sin(phi)) /
                       (ca * std::sin(phi) + sa * std::sin(theta) * std::cos(phi));
  return -ratio * (std::cos(theta) + std::cos(phi) * inner) / (-std::sin(theta));
}

std::vector<SquareTwistStationaryPoint> square_twist_height_stationary_points(const SquareTwistUnitParams& p,
                                                                             int intervals) {
  check_params(p);
  if (intervals < 2) throw std::invalid_argument("square twist: intervals must be >= 2");
  const double mu = square_twist_mu(p.alpha);
  auto f = [mu](double theta) { return height_slope(mu, theta); };
  std::vector<SquareTwistStationaryPoint> out;
  double lo = 0.0, flo = f(lo);
  for (int k = 1; k <= intervals; ++k) {
    const double hi = k == intervals ? kPi : kPi * k / intervals;
    const double fhi = f(hi);
    if (fhi == 0.0 || (flo > 0.0) != (fhi > 0.0)) {
      double theta = hi;
      if (fhi != 0.0) {
        std::uintmax_t iterations = 200;
        const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi,
                                                              boost::math::tools::eps_tolerance<double>(52), iterations);
        theta = 0.5 * (a + b);
      }
      SquareTwistStationaryPoint s;
      s.theta = theta;
      s.phi = square_twist_phi(p.alpha, theta);
      s.height = p.a * std::sin(p.alpha) * (std::sin(s.theta) + std::sin(s.phi));
      s.maximum = flo > 0.0;
      out.push_back(s);
    }
    lo = hi;
    flo = fhi;
  }
  return out;
}

SquareTwistHeightMaximum square_twist_height_maximum(const SquareTwistUnitParams& p) {
  const auto points = square_twist_height_stationary_points(p);
  SquareTwistHeightMaximum m;
  m.stationary_points = static_cast<int>(points.size());
  bool any = false;
  for (const auto& s : points)
    if (s.maximum && (!any || s.height > m.height)) {
      any = true;
      m.theta = s.theta;
      m.phi = s.phi;
      m.height = s.height;
    }
  // dH/dtheta > 0 at 0 and < 0 at pi: a maximum always exists.
  if (!any) throw std::logic_error("square twist: no height maximum found");
  return m;
}

}  // namespace rigidfold::metamaterial
