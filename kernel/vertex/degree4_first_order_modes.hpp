#pragma once
// The two first-order folding modes of a developable degree-4 vertex at its flat state,
// flat-foldable or not, with crease directions known only within boxes (interval
// arithmetic, outward_interval.hpp): what a loop-gain proof over every pattern within a
// file's rounding needs (interval_loop_gain.hpp).
//
// Why two lines: along any analytic folding motion from flat, let c be the fold rates of
// the four creases at the lowest order in which one of them moves (radians per unit of
// the path parameter; kernel convention, rho > 0 valley). The closure of the loop of
// rotations about the unit crease directions e_i (in the sheet's plane) gives, at that order,
//     sum_i c_i e_i = 0                                  (2 in-plane equations), and
//     Q(c) = sum_{i<j} c_i c_j (e_i x e_j) = 0          (the out-of-plane rotation at twice
//                                                        that order; i, j in CCW order)
// (the second-order term of a product of rotations whose first-order terms cancel is half
// the sum of the pairwise commutators; a cyclic shift of the start changes Q by a multiple
// of the first equation, so the start does not matter). The first system leaves a plane of
// rates; Q = 0 cuts it in two lines when its discriminant is positive: the two modes. On a
// flat-foldable vertex these are the rates of the tan-half multipliers
// (flat_fold_multipliers.hpp); here nothing needs Kawasaki.
//
// Inputs: the four crease vectors u_i (from the vertex to the far end of crease i, in the
// sheet's plane, CCW order as Topology's fan), each coordinate an interval (length unit).
// Output: for each mode, an enclosure of c with one crease's rate fixed at 1 (the crease
// `unit_crease`), valid for EVERY choice of the vectors within their boxes, or proven =
// false with the reason (a degenerate box: consecutive creases that may be collinear, a
// discriminant that may vanish). A rate's enclosure may hold 0: a straight crease line
// through the vertex folds alone in one mode, the other two rates 0 (or nearly, when the
// line is straight only within the boxes). Modes are in no particular order.
#include <array>
#include <string>

#include "kernel/numeric/outward_interval.hpp"

namespace rigidfold {

struct IntervalVector2 {
  OutwardInterval x, y;
};

struct Degree4FirstOrderModes {
  bool proven = false;
  std::string why_not;  // when !proven
  int unit_crease = -1;  // the crease whose rate is 1 in both modes
  std::array<std::array<OutwardInterval, 4>, 2> rates;  // rates[mode][crease]
};

Degree4FirstOrderModes degree4_first_order_modes(const std::array<IntervalVector2, 4>& crease_vectors);

}  // namespace rigidfold
