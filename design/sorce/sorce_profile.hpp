#pragma once
// Rolling-contact (SORCE) profile pair of one fold, seed 002 sections 4, 9, 10.
//
// Frame (digest section 1): the fold's normal plane; the zero-thickness fold at the origin;
// the left panel along -x, the right panel along +x at t = 0; y the facet normal. Poses:
//   left  p -> p + (0, z_l(t)),
//   right p -> R(gamma(t)) (p + (0, z_r(t))) + d(t)   (eq 55; d = 0 unless the fold is split).
// s_l(t), s_r(t) are the points, in each panel's own t = 0 coordinates, that touch at t: the
// instantaneous centre of the relative motion (the moving and fixed centrodes). They satisfy
//   rolling  s_l' = R(gamma) s_r'                       (eq 11, primes restored)
//   contact  s_l + (0, z_l) = R(gamma) (s_r + (0, z_r)) + d   (eq 14 with the split term)
// and are (eqs 56, 57; eqs 18, 19 when d = 0), u(a) = (cos a, sin a), J = R(pi/2):
//   s_l = [z_r' u(pi + gamma) + z_l' u(0) + J d'] / gamma' - z_l e_y + d
//   s_r = [z_l' u(-gamma) + z_r' u(pi) + R(pi/2 - gamma) d'] / gamma' - z_r e_y
// The digest restores the OCR's dropped primes and minus signs; the forms are re-derived in
// sorce_profile.cpp from the general planar centrode (eq 54) and checked against it in the
// tests. The slab of a panel of thickness h occupies local y in [-h/2, h/2].
//
// Units: lengths in the caller's unit, angles radians (gamma > 0 valley), t in [0, 1].
#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/sorce/sorce_function.hpp"

namespace rigidfold::sorce {

using Vec2 = Eigen::Vector2d;

// One fold's relative motion. gamma, z_left, z_right required; d empty = not split.
struct FoldMotion {
  ScalarFunction gamma;    // fold angle (radians)
  ScalarFunction z_left;   // left panel offset along its own normal
  ScalarFunction z_right;  // right panel offset along its own normal
  VectorFunction d;        // split offset in the normal plane, in the left panel's frame
  double thickness_left = 0.0;   // slab thicknesses, for protrusion (0: not reported)
  double thickness_right = 0.0;
};

// A fold with a name for drawings (SVG label, DXF layer prefix), e.g. "fold 2" or "E17".
struct NamedFold {
  std::string name;
  FoldMotion motion;
};

// The profile pair at one t with its first two derivatives in t, its signed curvature
// (eq 32, > 0 turning left; +-infinity where |s'| = 0) and convexity toward the mate
// (eq 33 with the digest's sign for c_r: c_l = sgn kappa_l, c_r = -sgn kappa_r, sgn the
// fold's valley/mountain sign: sign(gamma), or sign(gamma') where gamma = 0).
struct ProfilePoint {
  double t = 0.0;
  double gamma = 0.0, dgamma = 0.0;
  Vec2 s_left = Vec2::Zero(), ds_left = Vec2::Zero(), dds_left = Vec2::Zero();
  Vec2 s_right = Vec2::Zero(), ds_right = Vec2::Zero(), dds_right = Vec2::Zero();
  double curvature_left = 0.0, curvature_right = 0.0;
  double convexity_left = 0.0, convexity_right = 0.0;
};

// Eqs 56/57 at t (exact derivatives, no differencing). Where gamma'(t) = 0 the profile is
// undefined: throws InputError("t") (see fold_report's ill-behaved points).
ProfilePoint profile_point(const FoldMotion& motion, double t);

// The profile pair at `samples` evenly spaced t in [0, 1], both ends included: the ends from
// their analytic limits (end_points), the interior by profile_point; an interior t where
// gamma' = 0 (undefined there; fold_report lists it) is skipped, so `t` may hold fewer points.
// For drawings, solids and the Python binding. Throws InputError("samples") if samples < 2,
// and passes on end_points' errors.
struct SampledProfiles {
  std::vector<double> t;
  std::vector<Vec2> left, right;
};
SampledProfiles sample_profiles(const FoldMotion& motion, int samples);

// eq 20: s0 = [z_l'(0) - z_r'(0)] / gamma'(0), the lateral offset of the initial contact.
double initial_contact_offset(const FoldMotion& motion);

// End points by their analytic limits (eqs 29-31, extended by the split terms of 56/57):
//   t = 0 (gamma = 0, z = 0, d = 0):  s_l = s_r = ((z_l' - z_r') e_x + J d') / gamma'
//   t = 1 with gamma(1) = +-pi:  s_l = ((z_l' + z_r') e_x + J d') / gamma' - z_l e_y + d,
//                                s_r = (-(z_l' + z_r') e_x - J d') / gamma' - z_r e_y
// `flat_folded_end` is false (and the t = 1 points come from eqs 56/57 directly) when
// |gamma(1)| differs from pi by more than 1e-12. Throws InputError("t") if gamma'(0) or
// gamma'(1) is 0, InputError("motion") if gamma, z or d is non-zero at t = 0 (beyond 1e-12).
struct FoldEndPoints {
  Vec2 left0 = Vec2::Zero(), right0 = Vec2::Zero();
  Vec2 left1 = Vec2::Zero(), right1 = Vec2::Zero();
  bool flat_folded_end = false;
};
FoldEndPoints end_points(const FoldMotion& motion);

// General planar motion of two bodies, p -> R(theta_i) p + r_i (eq 40), with derivatives.
struct PlanarPose {
  double theta = 0.0, dtheta = 0.0;
  Vec2 r = Vec2::Zero(), dr = Vec2::Zero();
};
// Their centrode points (eq 54): s_ij in body i's coordinates and s_ji in body j's,
//   s_ij = R(-theta_i) [theta_j' (r_i - r_j) + J (r_i - r_j)'] / (theta_i' - theta_j').
// Throws InputError("dtheta") if theta_i' = theta_j' (no relative rotation: ill-behaved).
struct CentrodePair {
  Vec2 s_ij = Vec2::Zero(), s_ji = Vec2::Zero();
};
CentrodePair planar_centrodes(const PlanarPose& i, const PlanarPose& j);

// The fold's two panel poses at t (eq 55), for planar_centrodes.
struct FoldPoses {
  PlanarPose left, right;
};
FoldPoses fold_poses(const FoldMotion& motion, double t);

// Residuals of the rolling and contact conditions at t (absolute, length units):
//   rolling = |s_l' - R(gamma) s_r'|,  contact = |s_l + (0, z_l) - R(gamma)(s_r + (0, z_r)) - d|.
struct RollingResidual {
  double rolling = 0.0, contact = 0.0;
};
RollingResidual rolling_residual(const FoldMotion& motion, double t);

}  // namespace rigidfold::sorce
