#pragma once
// Scale-free geometry: the crease pattern's coordinates normalised by a power of two.
//
// normalise_length_scale: when the largest side of the pattern's bounding box lies outside
// [2^-20, 2^20] (file units), divides every vertex by 2^e, e = the binary exponent of that
// side (so the side becomes [1, 2)), and adds e to pattern.length_exponent. The division is
// exact (no rounding; a coordinate more than ~2^1000 times smaller than the pattern may go
// subnormal, far below the pattern's own resolution). Within the band nothing changes, so
// every tolerance that is relative to the pattern's size behaves the same at every scale,
// and lengths squared (edge norms, areas) never underflow or overflow in the kernel.
// Writers multiply back by 2^length_exponent (to_file_units).
// Inputs: a pattern with finite coordinates. Idempotent.
#include <Eigen/Core>
#include <cmath>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// Band of extents (file units) left as they are.
inline constexpr int kMinUnscaledExponent = -20;
inline constexpr int kMaxUnscaledExponent = 20;

void normalise_length_scale(CreasePattern& pattern);

// A point or length of the kernel (normalised) in the file's units: x * 2^length_exponent.
inline Eigen::Vector3d to_file_units(const CreasePattern& pattern, const Eigen::Vector3d& x) {
  return pattern.length_exponent == 0 ? x
                                      : Eigen::Vector3d(std::ldexp(x[0], pattern.length_exponent), std::ldexp(x[1], pattern.length_exponent),
                                                        std::ldexp(x[2], pattern.length_exponent));
}
inline double to_file_units(const CreasePattern& pattern, double length) { return std::ldexp(length, pattern.length_exponent); }

}  // namespace rigidfold
