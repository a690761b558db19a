#pragma once
// One front door to the metamaterial units of seed 003 (§3.2.3 elements, §3.3.2 square twist):
// the motion sampled from flat to the fold limit, every sampled row checked before it is
// returned, the height maximum and where each Poisson's ratio changes sign.
//
// Units (closed forms in corrugated_elements.hpp and square_twist_unit.hpp):
//   - kSquareTwist: fold = theta (magnitude of the S-direction pleat folds, 0 flat, pi folded
//     onto itself), second_angle = phi by (3-31); dims (x, y, H) = (L, S, H) (3-30);
//     ratios (nu_in, nu_out) = (nu_SL, nu_HL) (3-32, corrected definition).
//   - kElement1/2/3 (the double-corrugated P/Q tessellations' basic elements 1-3, Fig 3-11):
//     fold = rho = pi - phi, phi the dihedral of crease A2B2 (the seed's input); second_angle
//     = phi (elements 1, 2) or the dihedral theta of B4B5 by (3-26) (element 3);
//     dims (x, y, H) = (W, L, H); ratios nu_in = -(dL/L)/(dW/W), nu_out = -(dH/H)/(dW/W) (3-28).
// Samples: fold = k pi / (samples + 1), k = 1..samples (the open interval: ratios are 0/0 at
// flat and at the fold limit).
// Checks on every row (else NoAnswerError, nothing returned):
//   - every number finite;
//   - constraint residual <= kConstraintTolerance: square twist |(3-31)| at (theta, phi);
//     element 3 |sin(theta/2) cos(phi/2) cos((beta-alpha)/2) - sin(phi/2) cos(theta/2)
//     cos((beta+alpha)/2)| ((3-26) times cos(theta/2) cos(phi/2));
//     elements 1, 2 have no constraint (residual 0);
//   - derivatives d(x, y, H)/dfold (analytic: square twist by implicit differentiation,
//     elements by automatic differentiation) against a 5-point central difference of the
//     dimensions, |d - fd| <= kDerivativeTolerance * max(1, |d|) for step h = min(1e-4,
//     distance to the ends / 4) or h / 4 (steep near the ends: truncation vs round-off);
//   - square twist: nu_SL, nu_HL against the seed's printed closed forms (3-32) to
//     kDerivativeTolerance * max(1, |nu|).
// Sign changes: between consecutive rows whose ratio changes sign, the zero of the ratio's
// numerator derivative (kind "zero") or of its denominator derivative (kind "pole") is
// refined by TOMS 748 to round-off (kind "corner" when the numerator derivative jumps there
// instead of passing through 0: a dimension taken as |.| at 0); otherwise the sign change
// is bisected on the ratio itself (kind "dimension"). Roots closer than one sample spacing
// may be missed.
// Height maximum: the highest stationary maximum of H among the refined zeros of dH/dfold
// (maxima of equal height to 1e-12 relative keep the smaller fold: the square twist at
// alpha = 95 or 105 deg has two, mirror images theta <-> 90 deg - theta); for the square
// twist, square_twist_height_maximum's theta must be one of the table's stationary points to
// 1e-9 rad and its height the table's to 1e-12 relative (else NoAnswerError: sample more
// finely). None when H has no interior stationary maximum.
// Computed and checked at a = 1 (l = 1) and scaled back: the closed forms are homogeneous of
// degree 1 in the lengths. Angles in radians, lengths in the unit of a (square twist) or l
// (elements).
#include <string>
#include <vector>

#include "design/metamaterial/corrugated_elements.hpp"
#include "design/metamaterial/square_twist_unit.hpp"

namespace rigidfold::metamaterial {

enum class MetamaterialUnit { kSquareTwist, kElement1, kElement2, kElement3 };

inline constexpr double kConstraintTolerance = 1e-12;
inline constexpr double kDerivativeTolerance = 1e-6;

struct MetamaterialParams {
  MetamaterialUnit unit = MetamaterialUnit::kSquareTwist;
  SquareTwistUnitParams square_twist;  // used for kSquareTwist
  CorrugatedElementParams element;     // used for kElement1..3
  int samples = 181;                   // 3..100000
};

struct MetamaterialRow {
  double fold = 0.0;          // radians (see above)
  double second_angle = 0.0;  // radians
  double x = 0.0, y = 0.0, H = 0.0;     // square twist L, S, H; elements W, L, H
  double dx = 0.0, dy = 0.0, dH = 0.0;  // d/dfold, per radian
  double nu_in = 0.0, nu_out = 0.0;     // square twist nu_SL, nu_HL; elements nu_in, nu_out
  double constraint_residual = 0.0;     // radians-free residual of the unit's constraint
  double derivative_error = 0.0;        // max over x, y, H of |d - fd| / max(1, |d|)
};

struct MetamaterialSignChange {
  std::string ratio;  // "nu_in" or "nu_out"
  std::string kind;   // "zero", "corner", "pole" or "dimension"
  double fold = 0.0;  // radians
  bool negative_after = false;  // the ratio's sign just after the change (larger fold)
};

struct MetamaterialTable {
  MetamaterialParams params;
  std::vector<MetamaterialRow> rows;
  bool has_height_maximum = false;
  double height_maximum_fold = 0.0;  // radians
  double height_maximum = 0.0;
  int height_stationary_points = 0;  // refined zeros of dH/dfold
  // False when a dimension the ratio is built on stays within 1e-12 of the largest dimension
  // (element 1 or 2 with alpha = beta: L = 0 throughout): that ratio is NaN in every row.
  bool nu_in_defined = true, nu_out_defined = true;
  std::vector<MetamaterialSignChange> sign_changes;  // ordered by fold
  double max_constraint_residual = 0.0;
  double max_derivative_error = 0.0;
};

// Names for output: "square-twist", "element1", ...; the dimension names ("L", "S", "H" or
// "W", "L", "H") and ratio names ("nu_SL", "nu_HL" or "nu_in", "nu_out").
std::string unit_name(MetamaterialUnit unit);
std::vector<std::string> dimension_names(MetamaterialUnit unit);
std::vector<std::string> ratio_names(MetamaterialUnit unit);

// Throws std::invalid_argument for bad parameters (those of the closed forms, samples outside
// [3, 100000], element 3 locked by alpha + beta = pi) and NoAnswerError when a row fails
// its checks.
MetamaterialTable metamaterial_table(const MetamaterialParams& params);

// CSV of the table: header fold_deg,second_angle_deg,<dims>,<d dims per rad>,<ratios>,
// constraint_residual,derivative_error; numbers with 17 significant digits.
std::string metamaterial_csv(const MetamaterialTable& table);

// SVG plots (line_plot_svg.hpp) against the fold angle in degrees: the three dimensions, and
// the two Poisson's ratios (y range clipped to the 2%-98% quantiles widened by half, so that
// a pole does not flatten the curves; the CSV has every value).
std::string metamaterial_dimensions_svg(const MetamaterialTable& table);
std::string metamaterial_ratios_svg(const MetamaterialTable& table);

}  // namespace rigidfold::metamaterial
