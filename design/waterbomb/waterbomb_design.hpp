#pragma once
// Inverse design of the waterbomb base (closed-form part): the stiffness
// ratio k_m / k_v that puts the second stable state at a chosen theta.
//
// On the symmetric path dV/dtheta = n [k_m (gm - gm0) gm' + k_v (gv - gv0) gv'] = 0 at
// theta2 gives, in closed form,
//     k_m / k_v = -(gv - gv0) gv' / ((gm - gm0) gm')      (all at theta2, rest at theta0)
// which is a design only if it is >= 0 and theta2 is a minimum (d2V/dtheta2 > 0, checked by
// a central difference of the analytic slope).
namespace rigidfold::waterbomb {

// Inputs: n >= 3; theta0 (rest, radians) in [0, pi/2); theta2 (radians) in (pi/2,
// theta_limit(n)). Output: k_m / k_v >= 0.
// Throws InputError ("n", "theta0", "theta2") for bad input and NoAnswerError when no
// non-negative ratio makes theta2 a minimum (with the ratio or the curvature as residual).
double stiffness_ratio_for_state2(int n, double theta0, double theta2);

}  // namespace rigidfold::waterbomb
