#include "design/waterbomb/waterbomb_rest_design.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "design/waterbomb/waterbomb_energy.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold::waterbomb {

RestAngleDesign rest_angle_for_state2(int n, double theta2, double k_m, double k_v) {
  const double limit = theta_limit(n);  // checks n
  if (!std::isfinite(theta2) || !(theta2 > kPi / 2) || !(theta2 < limit))
    throw InputError("theta2", "the second stable state must lie in (90, " + std::to_string(to_degrees(limit)) + ") deg");
  springs_at_rest_theta(n, 0.0, k_m, k_v);  // checks k_m, k_v
  const FoldPair g = waterbomb_fold_angles(n, theta2);
  const FoldPair d = waterbomb_fold_angle_derivatives(n, theta2);
  auto G = [&](double theta0) {
    const FoldPair r = waterbomb_fold_angles(n, theta0);
    return k_m * (g.gamma_m - r.gamma_m) * d.gamma_m + k_v * (g.gamma_v - r.gamma_v) * d.gamma_v;
  };
  const double lo = 0.0, hi = kPi / 2;
  const double glo = G(lo), ghi = G(hi);
  if (!(glo <= 0.0))
    throw NoAnswerError("no rest angle in [0, 90) deg makes theta2 stationary: even theta0 = 0 pulls past it (dV/dtheta at theta2)", glo);
  if (!(ghi > 0.0))  // a flat rest state pushes toward flat from theta2 whenever k_m + k_v > 0
    throw NoAnswerError("the slope at theta2 does not change sign over theta0 in [0, 90] deg (dV/dtheta at theta2)", ghi);
  double theta0 = lo;
  if (glo < 0.0) {
    std::uintmax_t iterations = 200;
    const auto bracket = boost::math::tools::toms748_solve(
        G, lo, hi, glo, ghi, [](double x, double y) { return std::fabs(x - y) <= 2 * std::numeric_limits<double>::epsilon() * std::fmax(std::fabs(x), std::fabs(y)); },
        iterations);
    theta0 = std::fabs(G(bracket.first)) <= std::fabs(G(bracket.second)) ? bracket.first : bracket.second;
  }
  if (!(theta0 < kPi / 2)) throw NoAnswerError("the designed rest state is the flat state (not bistable)", theta0);
  const WaterbombSprings s = springs_at_rest_theta(n, theta0, k_m, k_v);
  RestAngleDesign out;
  out.theta0 = theta0;
  out.slope_residual = std::fabs(waterbomb_energy_slope(s, theta2));
  const double h = 1e-5;
  out.curvature = (waterbomb_energy_slope(s, theta2 + h) - waterbomb_energy_slope(s, theta2 - h)) / (2 * h);
  if (!(out.curvature > 0.0))
    throw NoAnswerError("theta2 is stationary for the designed rest angle but not a minimum (d2V/dtheta2)", out.curvature);
  return out;
}

double rest_angle_for_switching_force(int n, double target, double k_m, double k_v, double r) {
  theta_limit(n);  // checks n
  if (!std::isfinite(target) || !(target > 0.0)) throw InputError("target", "the switching force must be a finite number > 0");
  springs_at_rest_theta(n, 0.0, k_m, k_v);  // checks k_m, k_v
  auto f = [&](double theta0) { return switching_force(springs_at_rest_theta(n, theta0, k_m, k_v), theta0, r).force - target; };
  const double lo = 0.0, hi = std::nextafter(kPi / 2, 0.0);
  const double flo = f(lo), fhi = f(hi);
  if (!(flo >= 0.0))
    throw NoAnswerError("even the rest angle theta0 = 0 switches at " + round_trip_text(flo + target) + ", below the target " +
                            round_trip_text(target),
                        flo + target);
  if (!(fhi < 0.0))
    throw NoAnswerError("the target switching force is too small to resolve next to the flat rest state", target);
  double theta0 = lo;
  if (flo > 0.0) {
    std::uintmax_t iterations = 200;
    const auto bracket = boost::math::tools::toms748_solve(
        f, lo, hi, flo, fhi,
        [](double x, double y) { return std::fabs(x - y) <= 2 * std::numeric_limits<double>::epsilon() * std::fmax(std::fabs(x), std::fabs(y)); },
        iterations);
    theta0 = std::fabs(f(bracket.first)) <= std::fabs(f(bracket.second)) ? bracket.first : bracket.second;
  }
  const double miss = std::fabs(f(theta0));
  if (!(miss <= 1e-9 * target))
    throw NoAnswerError("the solved rest angle switches " + round_trip_text(miss) + " away from the target", miss);
  return theta0;
}

}  // namespace rigidfold::waterbomb
