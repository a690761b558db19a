#pragma once
// Graded Miura-ori: a generic (non-Miura) rigidly foldable, 1-DOF quad mesh of flat-foldable
// degree-4 vertices whose sector angles vary from one zig-zag line to the next.
//
// Layout (seen from +z; `rows` x `cols` trapezoidal panels), numbering as miura_ori:
//   - STRAIGHT creases: node (i, j) -> (i+1, j); row line j lies on y = j*h.
//   - ZIG-ZAG line i (i = 0..cols) has its own angle theta_i in (0, pi/2): its segment j runs
//     from (i, j) to (i, j+1) in direction theta_i (j even) or pi - theta_i (j odd), so
//         x(i, j) = X_i + (j odd ? h*cot(theta_i) : 0),   X_i = i*b.
//   Panels are trapezoids (two horizontal sides), not parallelograms, unless all theta_i
//   agree (then this is miura_ori with alpha = theta, a = h/sin(theta)).
//   vertex(i, j) = j*(cols+1) + i; straight edge (i, j) = j*cols + i;
//   zig-zag edge (i, j) = cols*(rows+1) + j*(cols+1) + i. Outer edges are B.
// Each interior vertex on line i has the Miura sectors for alpha = theta_i (theta, pi-theta,
// pi-theta, theta or its mirror), so it is flat-foldable, and the Miura assignment rule is
// kept (zig-zag line i M for even i, V for odd; straight creases alternate).
//
// Why it folds with one DOF: opposite creases of a flat-foldable degree-4 vertex fold by
// equal magnitudes, so every straight row line folds by one |rho_s| and every zig-zag line i
// by one |rho_i|; at a vertex of line i, tan(|rho_s|/2) = cos(theta_i) tan(|rho_i|/2). One
// |rho_s| shared by all rows is consistent with every line i, hence the closed form
//       tan(|rho_i| / 2) = tan(|rho_s| / 2) / cos(theta_i)
// (every loop gain is 1; the multiplier verdict confirms it, tests/data).
#include <optional>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct GradedMiuraParams {
  int rows = 4;                    // panels along y, 1..2000
  int cols = 4;                    // panels along x, 1..2000
  double theta_min = 0.8;          // radians: line angles theta_i vary smoothly between these,
  double theta_max = 1.2;          //   theta_i = theta_min + (theta_max - theta_min) * (1 - cos(2 pi i / cols)) / 2
  double h = 1.0;                  // row height (> 0)
  double b = 1.0;                  // spacing of the zig-zag lines along x (> 0); must exceed
                                   //   h * max_i |cot(theta_i) - cot(theta_{i+1})| * 1.25
};

// Zig-zag line angles theta_0..theta_cols (radians) of the pattern.
std::vector<double> graded_miura_line_angles(const GradedMiuraParams& params);

// Validated pattern; throws InputError (place = the field name) for a bad parameter.
CreasePattern graded_miura(const GradedMiuraParams& params);

// Fold angles (radians, FOLD sign) of the rigid mode of graded_miura(params) with every
// straight crease at |rho_straight| (sign convention as miura_fold_angles). Boundary edges
// get nullopt. Throws std::invalid_argument if |rho_straight| > pi.
std::vector<std::optional<double>> graded_miura_fold_angles(const GradedMiuraParams& params, double rho_straight);

}  // namespace rigidfold::generators
