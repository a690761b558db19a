#pragma once
// The square-twist metamaterial unit of seed 003 §3.3.2 (eqs. 3-29 ... 3-32): unit-cell
// dimensions L, S, H along the 1-DOF motion of the rigid T1 tessellation, their derivatives,
// the in-plane and out-of-plane Poisson's ratios, and the height maximum.
//
// Geometry (seed 003 Fig. 3-18, the T1 tessellation = Type 3 of data/generators/square_twist.hpp,
// layout Type3Rows of square_twist_tessellation.hpp). Every vertex has the sectors
// alpha, pi/2, pi - alpha, pi/2 (3-29) with pi/2 < alpha < pi; the generators' twist angle is
// t = pi - alpha. The corner rectangles stay parallel; they are joined by pleats, each a pair
// of parallel creases folded by equal and opposite angles around a panel of width a sin(alpha)
// (a: side of the central square). The pleats whose creases run along the S direction fold by
// theta, those along the L direction by phi, so that
//   L = 2c + a (cos(alpha) + sin(alpha) cos(theta))      (3-30)
//   S = 2b + a (cos(alpha) + sin(alpha) cos(phi))
//   H = a sin(alpha) (sin(theta) + sin(phi))
// where 2c + a (cos alpha + sin alpha) and 2b + a (cos alpha + sin alpha) are the unit's flat
// dimensions (for the generator's sheet: both equal its twist spacing, so b = c).
// theta, phi in [0, pi] are fold-angle MAGNITUDES (0 flat, pi folded onto itself); the seed's
// sign convention (mountain > 0) does not enter because both pleat creases of one pleat fold
// by the same magnitude with opposite letters. In the docs/DESIGN.md convention, theta = |rho| of
// any crease of a pleat that runs along S (e.g. A's outer crease o_b of a generator twist),
// phi = |rho| of any crease of a pleat along L (e.g. B's o_b).
//
// Constraint (3-31): -cos(a) cos(theta) + cos(a) cos(phi) - sin(a) sin(theta) sin(phi) = 0
// (a = alpha), which for theta, phi in [0, pi] is tan(theta/2) = mu tan(phi/2) with
// mu = (sin(alpha) - 1) / cos(alpha) in (0, 1): the other root of its tan-half quadratic,
// -(1 + sin alpha) / cos alpha, is negative. Hence theta <= phi, both reach pi together.
//
// Poisson's ratios (Poisson ratio of strain x under strain y: nu_xy = -(dx/x)/(dy/y)):
//   nu_SL = -(dL/L)/(dS/S) = -(S/L) dL/dS                       (3-32a, as printed)
//   nu_HL = -(dH/H)/(dL/L) = -(L/H) dH/dL                       (3-32b)
// Seed error: (3-32b) prints the definition as "-(dH/L)/(dL/H)", which is not a ratio of
// strains (it equals -(H/L) dH/dL). The expression printed after it is -(L/H) dH/dL, i.e. the
// corrected definition; this is what nu_HL returns. Checked in
// tests/metamaterial/square_twist_unit_test.cpp against finite differences of (3-30) along
// (3-31) and, independently, against the traced tessellation
// (tests/metamaterial/square_twist_tessellation_test.cpp).
// nu_SL < 0 on all of (0, pi); nu_HL > 0 while H grows and < 0 after the height maximum
// (dL/dtheta < 0, so sign(nu_HL) = sign(dH/dtheta)).
//
// Validity: L and S are lengths only while positive; over the whole motion that needs
// 2c > a (sin alpha - cos alpha) and 2b > a (sin alpha - cos alpha) (theta, phi -> pi). The
// functions do not reject other b, c (the formulas still evaluate).
//
// Units: angles in radians; a, b, c, L, S, H in one length unit; Poisson's ratios
// dimensionless; derivatives per radian of theta.
#include <vector>

namespace rigidfold::metamaterial {

struct SquareTwistUnitParams {
  double alpha = 5.0 * 3.14159265358979323846 / 6.0;  // sector alpha (radians), in (pi/2, pi)
  double a = 1.0;  // side of the central square (> 0)
  double b = 1.0;  // S offset: flat S = 2b + a (cos alpha + sin alpha); any real with S > 0
  double c = 1.0;  // L offset: flat L = 2c + a (cos alpha + sin alpha); any real with L > 0
};

// mu = (sin alpha - 1) / cos alpha = tan(theta/2) / tan(phi/2). Throws std::invalid_argument
// for alpha outside (pi/2, pi).
double square_twist_mu(double alpha);

// phi in [0, pi] from theta in [0, pi] by (3-31) (tan(phi/2) = tan(theta/2) / mu).
// Throws std::invalid_argument for theta outside [0, pi] or a bad alpha.
double square_twist_phi(double alpha, double theta);
// theta in [0, pi] from phi in [0, pi].
double square_twist_theta(double alpha, double phi);

struct SquareTwistUnitState {
  double theta = 0.0, phi = 0.0;  // radians
  double dphi_dtheta = 0.0;       // along (3-31)
  double L = 0.0, S = 0.0, H = 0.0;
  double dL = 0.0, dS = 0.0, dH = 0.0;  // d/dtheta along (3-31), analytic
  double nu_SL = 0.0, nu_HL = 0.0;      // from the analytic derivatives; NaN at theta = 0 or pi
};

// The unit at fold angle theta in [0, pi]. Throws std::invalid_argument for bad parameters
// (alpha, a <= 0, non-finite b or c, theta outside [0, pi]).
SquareTwistUnitState square_twist_unit(const SquareTwistUnitParams& params, double theta);

// The seed's printed closed forms, evaluated literally at (theta, phi) (phi need not satisfy
// (3-31); on (3-31) they equal the state's nu_SL and nu_HL):
double square_twist_nu_SL_printed(const SquareTwistUnitParams& params, double theta, double phi);  // (3-32a)
double square_twist_nu_HL_printed(const SquareTwistUnitParams& params, double theta, double phi);  // (3-32b), right side

// dphi/dtheta by implicit differentiation of (3-31) as printed:
// -F_theta / F_phi = (cos a sin theta - sin a cos theta sin phi) / (cos a sin phi + sin a sin theta cos phi).
double square_twist_dphi_dtheta_implicit(double alpha, double theta, double phi);

// Stationary points of the height, dH/dtheta = 0 on (0, pi): dH/dtheta > 0 at 0+ and < 0 at
// pi-, so there is an odd number of them; for most alpha one (the maximum), but not always:
// at alpha = 105 deg (twist 75 deg) H has a maximum, a minimum and a second, higher maximum
// (the traced tessellation shows the same three; square_twist_tessellation_test.cpp).
// Found by scanning `intervals` equal steps of theta for sign changes of the analytic
// dH/dtheta and refining each by TOMS 748 (Boost.Math) to round-off; two roots closer than
// pi / intervals could be missed.
struct SquareTwistStationaryPoint {
  double theta = 0.0, phi = 0.0;  // radians
  double height = 0.0;            // H there
  bool maximum = false;           // dH/dtheta goes from > 0 to < 0 (else a minimum)
};
std::vector<SquareTwistStationaryPoint> square_twist_height_stationary_points(const SquareTwistUnitParams& params,
                                                                             int intervals = 4096);

// The global height maximum (the highest of the stationary maxima). The seed's "nu_HL changes
// sign at the height maximum" holds at every stationary point (nu_HL has the sign of
// dH/dtheta).
struct SquareTwistHeightMaximum {
  double theta = 0.0, phi = 0.0;  // radians
  double height = 0.0;            // H there
  int stationary_points = 0;      // how many stationary points H has on (0, pi)
};
SquareTwistHeightMaximum square_twist_height_maximum(const SquareTwistUnitParams& params);

}  // namespace rigidfold::metamaterial
