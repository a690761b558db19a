#pragma once
// The box each vertex of a flat crease pattern may lie in, as the verdicts read the input's
// precision (coordinate_precision.hpp): what an interval proof over "every pattern the file
// may stand for" ranges over (interval_loop_gain.hpp).
//
// Source, in this order: the user's stated tolerance t (x +- t, y +- t); an SVG's drawn-point
// bounds (CreasePattern::position_bounds, not centred on the vertex); the rounding of the
// coordinates' digits when they are rounded; otherwise zero width (exact data). Each end is
// one floating-point step outward of x - d or x + d, so the box holds the intended one.
// Units: the pattern's length unit. A bound the reader could not give stays infinite.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

struct VertexBoxes {
  std::vector<Eigen::Vector2d> lo, hi;  // one per vertex (x, y)
  bool exact = false;                   // zero width: the numbers are taken as they are
};

VertexBoxes vertex_boxes(const CreasePattern& pattern, std::optional<double> stated_tolerance);

}  // namespace rigidfold
