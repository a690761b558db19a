#include "design/waterbomb/waterbomb_curve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "design/waterbomb/waterbomb_loaded_path.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::waterbomb {

WaterbombCurve waterbomb_curve(int n, double theta0, double k_m, double k_v, int samples,
                               const LoadedPathOptions& options) {
  if (samples < 3 || samples > 2001)
    throw InputError("samples", "must be between 3 and 2001, got " + std::to_string(samples));
  const WaterbombSprings springs = springs_at_rest_theta(n, theta0, k_m, k_v);
  const double limit = theta_limit(n);
  const double margin = 1e-3 * limit;
  std::vector<double> thetas;
  for (int i = 0; i < samples; ++i) {
    double th = margin + (limit - 2 * margin) * i / (samples - 1);
    // The flat state is a corner of the path (the force jumps there): sample either side.
    if (std::fabs(th - kPi / 2) < margin) th = th < kPi / 2 ? kPi / 2 - margin : kPi / 2 + margin;
    thetas.push_back(th);
  }
  thetas.erase(std::unique(thetas.begin(), thetas.end()), thetas.end());
  const LoadedPath loaded = waterbomb_loaded_path(n, theta0, k_m, k_v, thetas, options);

  WaterbombCurve out;
  out.flat_crossing = loaded.flat_crossing;
  out.stopped_at_flat = loaded.stopped_at_flat;
  out.stop_message = loaded.stop_message;
  for (const LoadedPoint& q : loaded.points) {
    CurveSample s;
    s.theta = q.theta;
    s.checked = q.converged && q.fold_angle_gap <= WaterbombCurve::kFoldAngleAgreement &&
                std::fabs(q.force - q.force_closed_form) <=
                    WaterbombCurve::kForceAgreement * std::max(1.0, std::fabs(q.force_closed_form));
    if (s.checked) {
      s.angles = waterbomb_fold_angles(n, q.theta);
      s.energy = waterbomb_energy(springs, q.theta);
      s.height = q.height;
      s.deflection = q.deflection;
      s.force = q.force;
      s.force_closed_form = q.force_closed_form;
      s.min_eigenvalue = q.min_eigenvalue;
      s.stable = q.stable;
    } else {
      ++out.unchecked;
    }
    out.samples.push_back(s);
  }
  return out;
}

}  // namespace rigidfold::waterbomb
