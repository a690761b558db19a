#include "kernel/pattern/length_scale.hpp"

#include <algorithm>
#include <cmath>

namespace rigidfold {

void normalise_length_scale(CreasePattern& p) {
  if (p.vertices.empty()) return;
  Eigen::Vector3d lo = p.vertices[0], hi = p.vertices[0];
  for (const auto& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  // Half differences: hi - lo itself overflows for coordinates near +-DBL_MAX.
  double half_side = 0.0;
  for (int k = 0; k < 3; ++k) half_side = std::max(half_side, 0.5 * hi[k] - 0.5 * lo[k]);
  if (!(half_side > 0.0) || !std::isfinite(half_side)) return;  // one point: nothing to scale by
  const int e = std::ilogb(half_side) + 1;                        // the side is in [2^e, 2^(e+1))
  if (e >= kMinUnscaledExponent && e <= kMaxUnscaledExponent) return;
  for (auto& v : p.vertices)
    for (int k = 0; k < 3; ++k) v[k] = std::ldexp(v[k], -e);
  for (auto* box : {&p.position_bounds.lo, &p.position_bounds.hi})
    for (auto& v : *box)
      for (int k = 0; k < 2; ++k) v[k] = std::ldexp(v[k], -e);
  p.position_bounds.max_half_width = std::ldexp(p.position_bounds.max_half_width, -e);
  p.length_exponent += e;
}

}  // namespace rigidfold
