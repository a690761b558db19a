#include "design/waterbomb/waterbomb_force.hpp"

#include <cmath>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::waterbomb {

ForcePoint waterbomb_force(const WaterbombSprings& s, double theta0, double r, double theta, int side) {
  if (!std::isfinite(r) || !(r > 0.0)) throw InputError("r", "the support distance must be a finite number > 0");
  if (!(theta > 0.0)) throw InputError("theta", "the force is undefined at theta = 0 (the height does not change there)");
  ForcePoint p;
  p.theta = theta;
  p.height = r * std::cos(theta);
  p.deflection = r * (std::cos(theta0) - std::cos(theta));
  p.force = waterbomb_energy_slope(s, theta, side) / (r * std::sin(theta));
  return p;
}

}  // namespace rigidfold::waterbomb
