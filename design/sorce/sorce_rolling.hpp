#pragma once
// Forward-rolling reconstruction (verification, seed 002 digest section 4): roll two given
// planar profile curves against each other without slip and recover the relative motion
// they produce. It sees only the curves (points and derivatives in each panel's own
// coordinates, in their own parameters) and the left panel's pose; it never uses the fold
// angle, the offsets or the profile formulas, so agreement with the generator's gamma(t)
// and panel poses checks eqs 56/57 along an independent path.
//
// Rolling without slip by matched arc length: the right curve's contact parameter u_r at
// left parameter u_l solves sigma_r(u_r) = sigma_l(u_l) (arc lengths from the start,
// adaptive Gauss-Kronrod; root by TOMS 748). The right panel's rotation gamma is the angle
// turning the right curve's unit tangent at u_r into the left one's at u_l (tangency), and
// its translation c follows from the contact point: R(gamma) s_r(u_r) + c equals the left
// contact point in the world, s_l(u_l) + left_translation. Where a curve's speed vanishes
// at an end (a pivot), its tangent is the limit direction -s'' (end) or +s'' (start).
// Units: as the curves'; angles radians.
#include <functional>
#include <vector>

#include "design/sorce/sorce_profile.hpp"

namespace rigidfold::sorce {

// A planar curve on u in [0, 1]: point c(u), c'(u), c''(u).
struct CurvePoint {
  Vec2 p = Vec2::Zero(), d1 = Vec2::Zero(), d2 = Vec2::Zero();
};
using PlanarCurve = std::function<CurvePoint(double u)>;

struct RolledPose {
  double u_left = 0.0, u_right = 0.0;
  double arc_length = 0.0;                   // sigma_l(u_left)
  double gamma = 0.0;                        // right panel's rotation (unwrapped along the samples)
  Vec2 right_translation = Vec2::Zero();     // c: right panel maps p -> R(gamma) p + c
};

// Rolls `right` on `left` at the increasing parameters u_left (in [0, 1], first 0);
// left_translation(u) is the left panel's translation (its rotation is the identity).
// gamma is unwrapped from gamma = angle at the first sample, taken in (-pi, pi].
// Throws InputError("u_left") if the samples are not increasing in [0, 1].
std::vector<RolledPose> roll_profiles(const PlanarCurve& left, const PlanarCurve& right,
                                      const std::function<Vec2(double)>& left_translation,
                                      const std::vector<double>& u_left);

// The fold's generated profiles as curves in t (for roll_profiles).
PlanarCurve left_profile_curve(const FoldMotion& motion);
PlanarCurve right_profile_curve(const FoldMotion& motion);

// The reconstruction compared with the fold's own motion (fold_poses) at parameters t:
// largest |gamma_rolled - gamma| (radians), |c_rolled - c| (length) and |u_right - t|.
struct RollingRecovery {
  double gamma = 0.0, translation = 0.0, parameter = 0.0;
};
// Rolls `right` (a curve in t, normally right_profile_curve(motion)) on the motion's left
// profile at the increasing t in [0, 1] (first 0), the left panel at (0, z_l(t)).
RollingRecovery rolling_recovery(const FoldMotion& motion, const PlanarCurve& right, const std::vector<double>& t);
// The motion's own profiles at `samples` evenly spaced t (>= 2; InputError("samples")).
RollingRecovery rolling_recovery(const FoldMotion& motion, int samples);

}  // namespace rigidfold::sorce
