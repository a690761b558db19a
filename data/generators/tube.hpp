#pragma once
// Prism tubes (test patterns with one hole): n planar panels around a closed polygon,
// given directly in 3D (FOLD "foldedForm" style), no flat development.
//
// Choice: the reference state is the 3D tube itself. Faces are CCW about their OUTWARD
// normals and share the vertices of the seam, so build_topology sees one component with two
// boundary loops (bottom and top rim): holes = 1, genus 0. Sector angles are measured in 3D;
// reference_fold_angles gives the crease angles of this state (the closure rows of a hole
// use rho - rho_ref, so this state is their zero).
//
// Layout: cross-section polygon P_0..P_{n-1} (x, y; counter-clockwise seen from +z),
//   level l = 0..layers at z = l * height / layers, scaled about the origin by
//   s_l = 1 + (top_scale - 1) * l / layers (top_scale != 1: a pyramid frustum, whose
//   creases all meet at one apex, a spherical linkage).
//   vertex(k, l) = l * n + k.
//   Edges, in order: the n * layers vertical creases (k, l) -> (k, l+1) (edge l * n + k), then
//   the rings (k, l) -> (k+1, l) for l = 0..layers (edge n * layers + l * n + k); rings 0
//   and `layers` are the boundary (B), the others creases.
//   Face (k, l) = (k, l), (k+1, l), (k+1, l+1), (k, l+1) (face l * n + k), normal outward.
//   Creases are assigned V where the reference fold angle is >= 0, else M; edges_foldAngle
//   holds the reference angles (radians in memory).
//   DOF of the one-layer tube: a general prism is a planar n-bar loop, n - 3 DOF (4 panels:
//   1, 3 panels: rigid); a frustum is a spherical n-bar, also n - 3.
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct TubeParams {
  std::vector<Eigen::Vector2d> section;  // >= 3 points, CCW, simple convex polygon
  double height = 1.0;                   // > 0
  int layers = 1;                        // >= 1
  double top_scale = 1.0;                // > 0
};

// Regular n-gon of circumradius r, vertex 0 at angle phase (radians).
std::vector<Eigen::Vector2d> regular_polygon(int n, double r = 1.0, double phase = 0.0);

// Throws InputError(place = the TubeParams field name) for a bad parameter.
CreasePattern prism_tube(const TubeParams& params);

}  // namespace rigidfold::generators
