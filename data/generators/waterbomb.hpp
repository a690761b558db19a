#pragma once
// Waterbomb base (seed 004): one interior vertex with 2n creases, alternating M and V.
//
// Geometry (seen from +z): a regular n-gon sheet of circumradius `radius` centred on the
// origin, with its edge midpoints at angles 2*pi*k/n and its corners at (2k+1)*pi/n,
// k = 0..n-1 (n = 4: an axis-aligned square). Creases run from the centre to every corner and every edge
// midpoint, so all 2n sectors are pi/n. n = 4 is the traditional square base (4 diagonals
// to the corners, 4 mid-lines to the edge midpoints, 45 deg sectors); n = 3 and n = 6 are
// the triangle and hexagon bases of seed 004 ch. 3.
//
// Vertex order: 0 = centre, then the boundary points counter-clockwise from angle 0
// (midpoint 0, corner 0, midpoint 1, corner 1, ...). Edge order: the 2n creases in that
// counter-clockwise order (midpoint creases at even indices, corner creases at odd), then
// the 2n boundary edges.
//
// Assignment: by default the corner creases are M and the mid-line creases V, seen from +z:
// the base stands as a tent with its vertex up (+z), the valley creases tucked in and
// reaching lowest (seed 004 state 1: supports at the outer ends of the valley folds).
// corners_mountain = false swaps them (the base seen from the other side).
// Kawasaki holds (equal sectors); Maekawa does not (n M and n V): the waterbomb base folds
// rigidly (2n - 3 DOF; 1 DOF under seed 004's symmetry) but the alternating assignment has
// no flat-folded state.
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct WaterbombParams {
  int n = 4;                    // mountain folds = valley folds = n, n >= 3 (seed 004: n = 2 does not fold)
  double radius = 1.0;          // circumradius of the sheet (> 0)
  bool corners_mountain = true; // corner creases M and mid-lines V; false swaps
};

// Validated pattern; throws InputError (place "n" or "radius").
CreasePattern waterbomb_base(const WaterbombParams& params);

}  // namespace rigidfold::generators
