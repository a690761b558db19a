#pragma once
// Traditional waterbomb pattern (seed 003 §4.4.2, Fig. 4-13): six-crease waterbomb bases in
// rows, every other row shifted by half a base, with two kinds of six-crease vertices:
//   D (a base's centre; the diamond vertex with a = pi/4: sectors 45, 90, 45, 45, 90, 45 deg
//     from its midline crease), and
//   W (where bases meet; sectors 90, 45, 45, 45, 45, 90 deg from its crease towards a D).
//
// Layout (seen from +z, unit = half a base): base (i, r), i = 0..cols-1, r = 0..rows-1, is
// the square of side 2 centred at c = (2i + (r mod 2), 2r). Its creases: the two half
// diagonals of each diagonal from c to the corners, the vertical midline from c to the
// midpoints (c.x, c.y +- 1) of its top and bottom sides, the top and bottom sides (two
// pieces of length 1, split at those midpoints) and the left and right sides (one piece of
// length 2 each: the point (c.x +- 1, c.y) is on no other crease, so it is no vertex).
// The sheet is the union of the squares (a ragged-sided polygon); a side shared by two
// squares is a crease, a side of one square is boundary.
// Assignment: D midline V, diagonals M, shared sides V, others B: at every D and W the
// letters of the modelled branches of kernel/thick/thick_vertex_models.hpp (the diamond as
// modelled; the waterbomb vertex seen from the other side, its lines V and diagonals M).
// Vertex order: by (y, x) of the integer lattice points used. Edge order: sorted by
// (smaller vertex, larger vertex). Faces: derived (right isosceles triangles).
//
// Units: pattern units (half a base side).
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct TraditionalWaterbombParams {
  int rows = 3;  // rows of bases, 1..200
  int cols = 3;  // bases per row, 1..200
};

// Validated pattern; throws InputError (place "rows" or "cols").
CreasePattern traditional_waterbomb(const TraditionalWaterbombParams& params);

}  // namespace rigidfold::generators
