#pragma once
// Hexagonal box of six five-crease vertices (seed 003 §4.3, Fig. 4-8: "six five-crease
// vertices arranged in rotational symmetry", sectors pi/6, pi/2, 2pi/3, pi/2, pi/6): a
// regular hexagonal bottom, a rectangular wall on each side and at each corner a 60-degree
// gusset split by a radial crease, so that the walls stand up while each gusset folds in two.
//
// Geometry (seen from +z): hexagon corners P_i = side * (cos 60i, sin 60i), i = 0..5; wall i
// on side P_i P_{i+1} with outward normal n_i (angle 60i + 30 deg) and height `height`; the
// gusset at P_i is the two right triangles between the wall edges P_i + height n_{i-1},
// P_i + height n_i and the tip G_i = P_i + height / cos 30 (cos 60i, sin 60i).
// At P_i the creases, counter-clockwise from the radial one, are: c0 radial (to G_i), c1
// along wall i's edge (n_i), c2 to P_{i+1}, c3 to P_{i-1}, c4 along wall i-1's edge (n_{i-1});
// sectors 30, 90, 120, 90, 30 deg: the Myard vertex with a = pi/6
// (kernel/thick/thick_vertex_models.hpp), whose letters are used: c0 V, the others M.
// Vertex order: P_0..P_5, then per corner i: P_i + height n_i, P_i + height n_{i-1}, G_i.
// Edge order: per corner i the creases c0, c1, c4, the side P_i P_{i+1}; then the boundary.
// Faces: derived (hexagon, six rectangles, twelve right triangles).
//
// Units: pattern units.
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct HexagonalBoxParams {
  double side = 1.0;    // hexagon side (> 0)
  double height = 0.5;  // wall height (> 0)
};

// Validated pattern; throws InputError (place "side" or "height").
CreasePattern hexagonal_box(const HexagonalBoxParams& params);

}  // namespace rigidfold::generators
