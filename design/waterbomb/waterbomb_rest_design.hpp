#pragma once
// Inverse design of the waterbomb base's rest angle (the rest angle theta0
// for a target second stable state): the theta0 whose spring energy has its second stable
// state at a chosen theta2 past flat, for given stiffnesses.
//
// On the symmetric path (waterbomb_energy.hpp) dV/dtheta = 0 at theta2 reads
//     G(theta0) = k_m (gm2 - gm(theta0)) gm2' + k_v (gv2 - gv(theta0)) gv2' = 0
// (gm2, gv2 and their theta-derivatives at theta2). On [0, pi/2) gm(theta0) = -(pi - 2 theta0)
// rises and gv(theta0) falls as theta0 grows, and gm2' = -2 < 0, gv2' > 0 past flat, so G is
// strictly increasing in theta0 (when k_m + k_v > 0): at most one root, no closed form in
// general (gv is not invertible in elementary terms), so it is bracketed on [0, pi/2] and
// solved by TOMS 748 (Boost.Math) to adjacent doubles. The design holds only if theta2 is a
// minimum there (d2V/dtheta2 > 0 by a central difference of the analytic slope).
// Units: angles radians; k_m, k_v energy / rad^2 (only their ratio matters).
namespace rigidfold::waterbomb {

struct RestAngleDesign {
  double theta0 = 0.0;          // the designed rest angle (radians, in [0, pi/2))
  double slope_residual = 0.0;  // |dV/dtheta| at theta2 with the designed springs (energy / rad)
  double curvature = 0.0;       // d2V/dtheta2 at theta2 (energy / rad^2), > 0
};

// Inputs: n >= 3; theta2 (radians) in (pi/2, theta_limit(n)); k_m, k_v >= 0, not both 0.
// Throws InputError ("n", "theta2", "k_m", "k_v") for bad input and NoAnswerError when no
// rest angle in [0, pi/2) makes theta2 stationary (G(0) > 0: the residual is G(0)) or the
// stationary theta2 is not a minimum (the residual is the curvature).
RestAngleDesign rest_angle_for_state2(int n, double theta2, double k_m, double k_v);

// The rest angle theta0 in [0, pi/2) whose switching force (waterbomb_switching.hpp: the
// largest push on [theta0, pi/2]) is `target`, for stiffnesses k_m, k_v and valley crease
// length r. At every theta below flat the push F(theta) = n [k_m (gm - gm0) gm' + k_v (gv - gv0)
// gv'] / (r sin theta) falls as theta0 grows (gm0 rises with gm' = 2 > 0, gv0 falls with gv' < 0)
// and the interval [theta0, pi/2] shrinks, so the switching force is strictly decreasing in
// theta0: bracketed on [0, pi/2) and solved by TOMS 748 to adjacent doubles, then checked:
// its switching force within 1e-9 x target.
// Throws InputError ("target" not finite or <= 0; "n", "k_m", "k_v", "r" as elsewhere) and
// NoAnswerError when the target is above the switching force at theta0 = 0 (the residual is
// that force) or below what the solver can resolve next to flat.
double rest_angle_for_switching_force(int n, double target, double k_m, double k_v, double r);

}  // namespace rigidfold::waterbomb
