#pragma once
// Closed-form kinematics of the symmetric waterbomb base (seed 004 ch. 2 and 3): one vertex
// of 2n creases, n mountain and n valley alternating, all sectors alpha = pi/n, folded with
// every mountain at gamma_m and every valley at gamma_v (1 DOF).
//
// Input theta (radians): the angle between any valley crease and the symmetry axis through
//   the vertex, measured toward the supports (the outer ends of the valley creases).
//   theta < pi/2: vertex up (state-1 side); theta = pi/2: flat; theta > pi/2: the vertex
//   pushed through the plane of the supports (state-2 side), M stays M and V stays V.
// Outputs gamma_m <= 0, gamma_v >= 0 (radians): the FOLD fold angles of the mountain and
//   valley creases (seed 004's valley-positive sign is the FOLD sign; no adapter needed).
//
// Validity: 0 <= theta <= pi - alpha (seed eq. 3.3). At theta = 0 the mountains reach -pi
//   (adjacent facets flat on each other); at theta = pi - alpha the valleys reach +pi.
//   Outside that range the formulas describe no physical state: the checked functions
//   throw InputError("theta", ...) instead of extrapolating.
//
// Written stably (no acos of arguments near +-1, no cancellation near flat):
//   gamma_m = -|pi - 2 theta|                                       (seed 2.6 / 3.4 simplified)
//   gamma_v = 2 (psi + omega) - pi,   psi   = atan2(cos a, sin a cos theta),
//                                     omega = atan2(|cos theta|, cos a sin theta)
// where psi = acos[cot theta tan(d/2)] and omega = acos[cot a tan(d/2)] of seed eq. 3.5 with
// sin(d/2) = sin theta sin a (eq. 3.6 with beta = 2a), one formula on both sides of flat.
#include <Eigen/Core>
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::waterbomb {

struct FoldPair {
  double gamma_m = 0.0;  // mountain creases (radians, or radians per radian for derivatives)
  double gamma_v = 0.0;  // valley creases
};

// pi / n, the sector angle. Throws InputError("n") unless n >= 3 (n = 2 does not fold
// rigidly) and n <= 180.
double sector_angle(int n);
// pi - pi/n: the largest theta (valley creases at +pi).
double theta_limit(int n);

// (gamma_m, gamma_v) at theta. Throws InputError("theta") outside [0, theta_limit(n)] or
// for a non-finite theta, InputError("n") as sector_angle.
FoldPair waterbomb_fold_angles(int n, double theta);

// d(gamma_m, gamma_v)/d theta. The path has a corner at theta = pi/2 (the flat state is a
// bifurcation point): side = -1 gives the limit from below, +1 from above; elsewhere side is
// ignored. Same throws as waterbomb_fold_angles.
FoldPair waterbomb_fold_angle_derivatives(int n, double theta, int side = 0);

// A symmetric state as one fold angle per edge of a waterbomb base pattern (e.g.
// data/generators/waterbomb.hpp): gamma_m on its M creases, gamma_v on its V creases, 0 on
// every other edge (radians).
Eigen::VectorXd waterbomb_edge_angles(const CreasePattern& base, FoldPair angles);

// Seed 004 as printed, for cross-checks (tests): the traditional n = 4 forms (2.1)-(2.8)
// (range a for theta <= pi/2 by eq. 2.7, range b by eq. 2.8), the general forms
// (3.4)-(3.6), and the printed derivative (3.11) with (3.12). These use acos/asin of
// arguments near +-1 and lose digits near flat and near theta = 0; the stable forms above
// are the ones to use.
FoldPair seed_traditional_fold_angles(double theta);
FoldPair seed_general_fold_angles(int n, double theta);
double seed_gamma_v_derivative(int n, double theta);

// The theta on the path of (gamma_m, gamma_v): theta = (pi + gamma_m)/2 or (pi - gamma_m)/2,
// whichever side's gamma_v is nearer the given one. Inputs radians. For reading a general
// (unsymmetric-solver) state back onto the path; returns the distance of gamma_v from the
// path in *gamma_v_gap (radians) when not null.
double theta_on_path(int n, double gamma_m, double gamma_v, double* gamma_v_gap = nullptr);

}  // namespace rigidfold::waterbomb
