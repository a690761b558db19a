#include "design/waterbomb/waterbomb_design.hpp"

#include <cmath>
#include <string>

#include "design/waterbomb/waterbomb_energy.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold::waterbomb {

double stiffness_ratio_for_state2(int n, double theta0, double theta2) {
  const double limit = theta_limit(n);  // checks n
  if (!std::isfinite(theta0) || theta0 < 0.0 || !(theta0 < kPi / 2))
    throw InputError("theta0", "the rest state must lie on the near side of flat, [0, 90) deg");
  if (!std::isfinite(theta2) || !(theta2 > kPi / 2) || !(theta2 < limit))
    throw InputError("theta2", "the second stable state must lie in (90, " + std::to_string(to_degrees(limit)) + ") deg");
  const FoldPair rest = waterbomb_fold_angles(n, theta0);
  const FoldPair g = waterbomb_fold_angles(n, theta2);
  const FoldPair d = waterbomb_fold_angle_derivatives(n, theta2);
  const double mountain_term = (g.gamma_m - rest.gamma_m) * d.gamma_m;
  const double valley_term = (g.gamma_v - rest.gamma_v) * d.gamma_v;
  if (mountain_term == 0.0) throw NoAnswerError("the mountain springs exert no moment at theta2: no ratio sets the slope to 0");
  const double ratio = -valley_term / mountain_term;
  if (!(ratio >= 0.0) || !std::isfinite(ratio))
    throw NoAnswerError("no non-negative stiffness ratio puts a stable state at theta2 (k_m / k_v)", ratio);
  const WaterbombSprings s{n, ratio, 1.0, rest};
  const double h = 1e-5;
  const double curvature = (waterbomb_energy_slope(s, theta2 + h) - waterbomb_energy_slope(s, theta2 - h)) / (2 * h);
  if (!(curvature > 0.0))
    throw NoAnswerError("theta2 is not a minimum for the stiffness ratio that makes it stationary (d2V/dtheta2)", curvature);
  return ratio;
}

}  // namespace rigidfold::waterbomb
