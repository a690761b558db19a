#pragma once
// Waterbomb tessellation: a multi-DOF triangulated sheet whose every interior vertex is a
// degree-6 waterbomb vertex (a horizontal crease line and two diagonals, sectors 45, 90,
// 45, 45, 90, 45 deg).
//
// Layout (seen from +z): row j (j = 0..rows) holds the nodes (2k + (j mod 2), j),
// k = 0..cols, unit spacing. Creases: the horizontal segments joining consecutive nodes of a
// row (length 2), and the diagonals joining each node to its neighbours in the rows above
// and below (length sqrt 2). Every face is a right isosceles triangle; the left and right
// sides of the sheet zig-zag.
// Vertex order: row by row, left to right (vertex(k, j) = j*(cols+1) + k). Edge order: the
// horizontal segments row by row, then the diagonals strip by strip, left to right.
// Assignment: horizontal creases M, diagonals V (the waterbomb-base letters of seed 004
// with mid-lines M), boundary B. Kawasaki holds at every vertex; the sheet is not
// flat-foldable as a whole with these letters, which does not matter for rigid motion.
//
// DOF: a triangulated disk has (interior creases) - 3 (interior vertices) = (boundary
// vertices) - 3 degrees of freedom at a generic folded state (Euler), so this pattern is
// the multi-DOF case of the benchmarks: 2 (rows + cols) - 3 DOF (2 (rows + cols) boundary
// vertices).
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct WaterbombTessellationParams {
  int rows = 4;  // strips of triangles, 1..2000
  int cols = 4;  // nodes per row minus one, 1..2000
};

// Validated pattern; throws InputError (place "rows" or "cols").
CreasePattern waterbomb_tessellation(const WaterbombTessellationParams& params);

}  // namespace rigidfold::generators
