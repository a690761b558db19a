#pragma once
// Switching force of the symmetric waterbomb base and the stiffness that sets it (for a
// target switching force).
//
// Under force control a push F on the apex moves the base from its rest state theta0 < pi/2
// toward flat along the symmetric path while F(theta) = V'(theta) / (r sin theta)
// (waterbomb_force.hpp) keeps rising; the largest push on [theta0, pi/2] - the one-sided
// F(pi/2-) when the maximum sits at the flat corner - is the switching force: pushed beyond
// it, the base snaps through flat to the far side.
// At each theta, F is linear in (k_m, k_v), and on (theta0, pi/2) the mountain term
// n k_m (gm - gm0) gm' / (r sin theta) is >= 0 (gm rises from gm0 < 0 toward 0), so the switching
// force grows with k_m: the k_m giving a target force is bracketed and solved by TOMS 748
// (Boost.Math) to a relative 1e-13.
// Units: angles radians; r (valley crease length) in the length unit; k in energy / rad^2;
// forces in energy unit / length unit.
#include <functional>

#include "design/waterbomb/waterbomb_energy.hpp"

namespace rigidfold::waterbomb {

struct SwitchingForce {
  double force = 0.0;   // the largest push on [theta0, pi/2]
  double theta = 0.0;   // where it is reached (radians)
  bool at_flat = false; // at the flat corner (the one-sided F(pi/2-))
  // switching_force_checked only: the general model's reaction force where the maximum is
  // (1e-4 rad before the flat corner when it is there; the corner itself is singular), and its
  // gap to the closed form at that same theta.
  double general_force = 0.0;
  double general_gap = 0.0;
};

// Inputs: springs whose rest state lies before flat (theta0 in [0, pi/2)), theta0 (radians),
// r > 0. Throws InputError ("theta0", "r") otherwise.
SwitchingForce switching_force(const WaterbombSprings& springs, double theta0, double r);

// switching_force on the generated radius-1 base (r = cos(pi / n)), checked on the general
// 2n-crease model (waterbomb_loaded_path.hpp): throws NoAnswerError when the loaded
// equilibrium does not converge there or its reaction force differs from the closed form by
// more than 1e-9 relative. Inputs as springs_at_rest_theta, theta0 < pi/2.
SwitchingForce switching_force_checked(int n, double theta0, double k_m, double k_v);

// The mountain stiffness k_m (valley stiffness k_v fixed) whose switching force is `target`
// (> 0). Throws InputError for bad input and NoAnswerError when even k_m = 0 switches above
// the target (the residual is that force) or no k_m up to 1e12 k_v reaches it.
double mountain_stiffness_for_switching_force(int n, double theta0, double k_v, double target, double r);

// The search behind it, for any base whose switching force rises with k_m (the split-fold
// base's too): switching_force_of(k_m) is evaluated at 0, then at k_v, 4 k_v, ... until it
// reaches the target, and TOMS 748 solves between; the answer is checked forward to 1e-9
// relative. Same errors as above.
double mountain_stiffness_for_force(const std::function<double(double)>& switching_force_of, double k_v, double target);

}  // namespace rigidfold::waterbomb
