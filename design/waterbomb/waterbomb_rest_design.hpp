#pragma once
// Inverse design of the waterbomb base's rest angle (issue 14 item 5, "the rest angle theta0
// for a target second stable state"): the theta0 whose spring energy has its second stable
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

}  // namespace rigidfold::waterbomb
