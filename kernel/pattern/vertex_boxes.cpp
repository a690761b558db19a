#include "kernel/pattern/vertex_boxes.hpp"

#include <cmath>

#include "kernel/pattern/coordinate_precision.hpp"

namespace rigidfold {

VertexBoxes vertex_boxes(const CreasePattern& pattern, std::optional<double> stated_tolerance) {
  const int n = pattern.num_vertices();
  VertexBoxes b;
  b.lo.resize(n);
  b.hi.resize(n);
  const CreasePattern::PositionBounds& drawn = pattern.position_bounds;
  const bool use_drawn = !stated_tolerance && drawn.covers(n);
  const CoordinatePrecision precision = use_drawn ? CoordinatePrecision{} : input_precision(pattern, stated_tolerance);
  b.exact = !use_drawn && !precision.rounded;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) {
      const double x = pattern.vertices[i][k];
      double down = 0.0, up = 0.0;
      if (use_drawn) {
        down = std::max(x - drawn.lo[i][k], 0.0);
        up = std::max(drawn.hi[i][k] - x, 0.0);
      } else if (precision.rounded) {
        down = up = precision.vertex_rounding[i];
      }
      b.lo[i][k] = b.exact ? x : std::nextafter(x - down, -INFINITY);
      b.hi[i][k] = b.exact ? x : std::nextafter(x + up, INFINITY);
    }
  return b;
}

}  // namespace rigidfold
