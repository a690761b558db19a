#pragma once
// The pass/fail bounds of a pattern's SORCE joints (the one place for them): a command
// reports joints only when every built-in verification of sorce_pattern.hpp is within its
// bound. Measured on the tests' patterns (vertex A, Miura, square twist) these figures are
// round-off, 1e-16 .. 1e-12; the bounds leave two to three orders of magnitude above that:
//   consistency   <= 1e-9  (relative: the solver's closure at the path's knots)
//   pitch         <= 1e-9  (relative to the pattern size)
//   closure_knots <= 1e-9  (relative)
//   contact (3D)  <= 1e-9 x pattern size   (the two faces' images of the contact point)
//   rolling, contact residuals (planar) <= 1e-9 x pattern size
//   forward rolling: gamma back to <= 1e-8 rad, the right panel's translation to <= 1e-8 x
//   pattern size (arc lengths by quadrature and a root per sample: measured 7e-13 rad and
//   1e-13 on the bundled 4x4 Miura)
// Not a pass/fail figure: closure_samples (between knots it measures the spline's own error,
// reported beside the others), stacking and slab interference (properties of the design the
// user chose, reported).
#include <string>
#include <utility>
#include <vector>

#include "design/sorce/sorce_pattern.hpp"

namespace rigidfold::sorce {

struct SorceCheckVerdict {
  bool passed = true;
  std::string failure;  // the first figure over its bound, with both numbers
  double worst = 0.0;   // that figure
  std::vector<std::pair<std::string, double>> bounds;  // name -> bound, as applied (lengths absolute)
};

SorceCheckVerdict check_sorce(const CreasePattern& pattern, const PatternSorce& sorce);

}  // namespace rigidfold::sorce
