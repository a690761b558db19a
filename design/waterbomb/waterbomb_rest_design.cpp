#include "design/waterbomb/waterbomb_rest_design.hpp"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "design/waterbomb/waterbomb_energy.hpp"
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

}  // namespace rigidfold::waterbomb
