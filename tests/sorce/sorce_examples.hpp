#pragma once
// The seed 002 example vertices used by the tests/sorce suites (not a test file itself).
#include <cmath>

#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::sorce::testing {

// Vertex A (seed section 5): alpha = 120, 80, 60, 100 deg.
inline VertexSectors vertex_a_sectors() { return {to_radians(120), to_radians(80), to_radians(60), to_radians(100)}; }

// Vertex A with eqs 24-25 and the linear offsets of eq 27 (panel thickness d): z1 = z4 =
// -3/2 d t, z2 = z3 = d t / 2.
inline SorceVertex vertex_a_linear(double d) {
  const VertexSectors a = vertex_a_sectors();
  const auto gamma = vertex_fold_angles(a, VertexParameterization::kMajorLinear);
  const ScalarFunction outer = power_function(-1.5 * d, 1), inner = power_function(0.5 * d, 1);
  return sorce_vertex(a, gamma, {outer, inner, inner, outer}, {d, d, d, d});
}

// Bird's-foot vertex B (seed section 10): 135, 45, 45, 135 deg.
inline VertexSectors vertex_b_sectors() { return {to_radians(135), to_radians(45), to_radians(45), to_radians(135)}; }

// Vertex B split along folds 1, 3 with eq 60 (power 1: d = 0.4 t) or eq 61 (power 2:
// d = 0.4 t^2); every z_i = -0.1 t (digest sign), thickness 0.2, eq 35 fold angles.
inline SorceVertex vertex_b_split(int power) {
  const VertexSectors b = vertex_b_sectors();
  const auto gamma = vertex_fold_angles(b, VertexParameterization::kSymmetric);
  const ScalarFunction z = power_function(-0.1, 1);
  return sorce_vertex(b, gamma, {z, z, z, z}, {0.2, 0.2, 0.2, 0.2}, collinear_split(b, gamma, power_function(0.4, power)));
}

}  // namespace rigidfold::sorce::testing
