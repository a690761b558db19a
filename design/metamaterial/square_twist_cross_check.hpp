#pragma once
// Independent check of the square-twist closed forms (seed 003 (3-30) ... (3-32),
// square_twist_unit.hpp) on the actual tessellation traced by the kernel's general solver
// (Poisson's ratios and maximum heights agree between the closed forms and the traced
// tessellation to <= 1e-9; nu_HL changes sign at the height maximum).
//
// The sheet: data/generators' square-twist tessellation, layout Type3Rows (every twist Type 3,
// the seed's T1), 3 x 3 twists, side 1, twist t = pi - alpha, centre spacings
//   along x: 2 b/a + cos(alpha) + sin(alpha)   (the flat S of (3-30), in units of a)
//   along y: 2 c/a + cos(alpha) + sin(alpha)   (the flat L)
// It is traced by trace_motion with force_general (pseudo-arclength continuation + Newton
// projection, no closed form, no multiplier model), driving side AB of the centre twist to
// `to` in its letter's direction. At every traced state:
//   - the closure residual (<= kCrossCheckResidual), and a 1-D null space of the closure
//     Jacobian (dense SVD: smallest singular value <= kCrossCheckNullSingular, next one >=
//     kCrossCheckNextSingular); its null vector is the path's tangent;
//   - the faces are placed from a corner rectangle with their exact velocities along that
//     tangent (folded_velocity.hpp); the unit cell is measured from the placed vertices:
//     A(i, 0) -> A(i, 2) is 2 L y, A(0, j) -> A(2, j) is 2 S x (their x/z parts, their spread
//     over i, j and the tilt of every corner rectangle are the geometry defect,
//     <= kCrossCheckGeometry), H the height range of the twist vertices;
//   - theta = |rho| of the centre twist's vertex A crease o_b (a pleat along S), phi = |rho|
//     of its o_a (a pleat along L); derivatives d/dtheta = (d/ds) / (dtheta/ds) and the
//     Poisson's ratios by implicit differentiation along the path:
//     nu_SL = -(S/L) (dL/ds)/(dS/ds), nu_HL = -(L/H) (dH/ds)/(dL/ds).
// Compared with square_twist_unit at the traced theta (states with theta <= pi - 0.05; the
// closed forms are 0/0 at the folded end): phi and L, S, H absolutely (units of a),
// derivatives and ratios relative to max(1, |closed|).
// Stationary points of H: where dH/ds changes sign between two traced steps, located by
// TOMS 748 on the driving crease's angle, every evaluation a Newton projection with the drive
// held (to 1e-14) and a fresh null vector; compared with square_twist_height_stationary_points
// in order (count, kind, theta, H); the highest traced maximum with square_twist_height_maximum.
// nu_HL at +-1e-4 rad of drive around each stationary point must have opposite signs
// (positive before a maximum, negative after).
// Every difference must be <= kCrossCheckTolerance; otherwise NoAnswerError naming the worst
// one (nothing is returned that failed its check).
//
// Inputs:  square-twist unit parameters (alpha in (pi/2, pi), a > 0, b, c > -a cos(alpha):
//          every pleat crease of the sheet has positive length); options.
// Outputs: the largest differences and the stationary points: angles in radians; the sheet
//          is built and traced at a = 1, so length differences are relative to a, and
//          heights are scaled back to the input's a.
// Throws InputError with place "alpha", "a", "b", "c", "steps" or "to_deg" for bad input;
// NoAnswerError when the trace fails or a check above fails.
#include <string>
#include <vector>

#include "design/metamaterial/square_twist_unit.hpp"

namespace rigidfold::metamaterial {

inline constexpr double kCrossCheckTolerance = 1e-9;      // closed form vs traced
inline constexpr double kCrossCheckResidual = 1e-12;      // closure residual per traced state (rad)
inline constexpr double kCrossCheckNullSingular = 1e-11;  // smallest singular value of J
// Second smallest singular value (1 DOF: a gap of 5 orders over the null threshold; it falls
// to ~1e-4 near the fold limit, alpha = 179 deg at 179 deg of drive).
inline constexpr double kCrossCheckNextSingular = 1e-6;
// Unit-cell geometry defect (relative to a): the measurement must be consistent to the
// comparison's tolerance (measured <= 1e-12 for alpha 95..179 deg, 5e-11 at 91 deg).
inline constexpr double kCrossCheckGeometry = kCrossCheckTolerance;

struct SquareTwistCrossCheckOptions {
  int steps = 40;        // traced steps, equally spaced in the drive; 10..2000
  double to_deg = 179;   // final |fold| of the driving crease, degrees in (90, 180)
};

// Least b (and c) for which the tessellation exists: -a cos(alpha) (pleat creases of positive
// length between twists). Throws std::invalid_argument for alpha outside (pi/2, pi).
double square_twist_cross_check_min_offset(double alpha, double a);

struct SquareTwistCrossCheckStationary {
  bool maximum = false;
  double theta_traced = 0.0, theta_closed = 0.0;    // radians
  double height_traced = 0.0, height_closed = 0.0;  // units of the input's a
  double nu_HL_at = 0.0;                            // traced, at the located point
  double nu_HL_before = 0.0, nu_HL_after = 0.0;     // traced, 1e-4 rad of drive either side
};

struct SquareTwistCrossCheck {
  SquareTwistUnitParams params;
  SquareTwistCrossCheckOptions options;
  int twists_per_side = 3;
  int creases = 0;             // interior creases of the traced sheet
  int traced_steps = 0;
  int compared_steps = 0;      // steps with theta <= pi - 0.05
  double theta_range_deg[2] = {0.0, 0.0};  // traced theta, first and last step
  double max_residual = 0.0;   // radians
  double max_null_singular = 0.0, min_next_singular = 0.0;
  double max_geometry_defect = 0.0;           // relative to a
  double max_phi_difference = 0.0;            // radians
  double max_dimension_difference = 0.0;      // |L|, |S|, |H| traced - closed, relative to a
  double max_derivative_difference = 0.0;     // relative, dL, dS, dH per radian of theta
  double max_ratio_difference = 0.0;          // relative, nu_SL and nu_HL
  bool nu_SL_negative = true;                 // on every traced step
  std::vector<SquareTwistCrossCheckStationary> stationary;  // in order of theta
  double max_stationary_theta_difference = 0.0;   // radians
  double max_stationary_height_difference = 0.0;  // relative to a
  double height_maximum_traced = 0.0, height_maximum_closed = 0.0;           // units of a
  double height_maximum_theta_traced = 0.0, height_maximum_theta_closed = 0.0;  // radians
  double seconds = 0.0;        // wall time of trace and measurements
};

SquareTwistCrossCheck square_twist_cross_check(const SquareTwistUnitParams& params,
                                               const SquareTwistCrossCheckOptions& options = {});

}  // namespace rigidfold::metamaterial
