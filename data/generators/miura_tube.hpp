#pragma once
// Miura tube: two Miura-ori strips, mirror images of each other, bonded along their outer
// zig-zag lines (the "rigid-foldable tube" of Tachi 2009 and the single cell of the zipper
// tubes of Filipov, Tachi and Paulino 2015). Its known mobility is 1 DOF: both strips follow
// the Miura-ori's own rigid mode with one parameter, so the bonds stay in the mirror plane.
// A test pattern for the SE(3) hole closure (kernel/closure/hole_closure.hpp): the sheet is
// an annulus, so vertex closures alone leave it with more freedom than it has.
//
// Construction (given directly in 3D, FOLD "foldedForm"; no flat development exists: a bond
// vertex has 4 sectors of the same strip side, summing to 4*alpha or 4*(pi - alpha)):
//   - strip A = miura_ori({rows, cols = 2, alpha, a, b}) folded by its standard mode
//     (miura_fold_angles) to the straight-crease angle `fold` and placed by place_faces;
//     its zig-zag lines 0 and 2 are at the same height (zig-zag lines alternate between two
//     parallel planes), so they lie in one plane Pi;
//   - strip B = the reflection of A in Pi: zig-zag lines 0 and 2 are shared (the bonds), and
//     B's middle zig-zag line is the mirror of A's.
// Numbering:
//   vertex(i, j) of A as in miura_ori (j * 3 + i, i = 0..2, j = 0..rows); B's middle line
//   vertex j is 3 * (rows + 1) + j.
//   Edges: A's edges in miura_ori's order (its zig-zag lines 0 and 2 become the bond creases),
//   then B's straight edges (0, j) -> B(j), B(j) -> (2, j) for j = 0..rows, then B's
//   zig-zag edges B(j) -> B(j + 1). The straight edges at j = 0 and j = rows are the two rims
//   (B); every other edge is a crease.
//   Faces: A's faces, then B's (reflected, vertex order reversed, so the surface is
//   consistently oriented).
// Creases are assigned V where the reference fold angle is >= 0, else M; edges_foldAngle holds
// the reference angles. Lengths in the units of a and b; angles in radians.
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct MiuraTubeParams {
  int rows = 4;                        // panels along the tube (zig-zag direction), 1..2000
  double alpha = 1.0471975511965976;   // acute panel angle, in (0, pi/2); default 60 deg
  double a = 1.0;                      // zig-zag segment length (> 0)
  double b = 1.0;                      // straight segment length (> 0)
  double fold = 1.5707963267948966;    // straight-crease fold magnitude of the reference state, in (0, pi)
};

// Throws InputError(place = the MiuraTubeParams field name) for a bad parameter.
CreasePattern miura_tube(const MiuraTubeParams& params);

// Edge index of A's straight crease (i, j) (i = 0, 1) and of A's zig-zag edge (i, j)
// (i = 0..2), as in miura_ori with cols = 2; B's counterparts: straight (side s = 0: from line
// 0, 1: to line 2) and B's zig-zag edge j.
int miura_tube_a_straight(const MiuraTubeParams& params, int i, int j);
int miura_tube_a_zigzag(const MiuraTubeParams& params, int i, int j);
int miura_tube_b_straight(const MiuraTubeParams& params, int side, int j);
int miura_tube_b_zigzag(const MiuraTubeParams& params, int j);

}  // namespace rigidfold::generators
