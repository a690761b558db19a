#pragma once
// Ron Resch's triangle tessellation: a triangular grid of side `side` in which every third
// down-pointing triangle (those whose centroids form the sqrt(3) x sqrt(3) sub-lattice) is a
// "star". A star loses its three edges; three mountain spokes join its centroid to its corners,
// and three valley creases join its centroid, across each lost edge, to the apex of the
// up-pointing triangle beyond it. Every up-pointing triangle is so merged with its one star
// neighbour into kites; the other down-pointing triangles stay whole, bounded by mountains.
// Every interior vertex has degree 6 and meets Kawasaki's condition (not Maekawa's: the
// pattern does not fold flat). Origami Simulator's `reschTriTessellation.svg` is this pattern.
//
// Geometry (seen from +z): grid vertex (i, j) at i (side, 0) + j (side/2, side sqrt(3)/2); the
// sheet is every face whose centroid lies in [0, cols side] x [0, rows side sqrt(3)/2], so its
// outline follows the faces (jagged where a kite or triangle straddles the rectangle).
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct ReschTriangleParams {
  int rows = 6;        // grid rows of the rectangle, 1..400
  int cols = 6;        // grid edges along x of the rectangle, 1..400
  double side = 1.0;   // grid triangle side (> 0)
};

// Validated pattern; throws InputError (place "rows", "cols" or "side").
CreasePattern resch_triangle(const ReschTriangleParams& params);

}  // namespace rigidfold::generators
