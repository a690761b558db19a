#pragma once
// Square-twist tessellation: a rows x cols grid of square twists joined by pleats,
// every interior vertex a flat-foldable degree-4 vertex, with M-V letters that make the whole
// sheet rigidly foldable with 1 DOF (layouts Type4, Type3Rows) or not foldable at all
// (AllType1, AllType2: the "same size, not foldable" benchmark case).
//
// Geometry (seen from +z; lengths in the unit of `side` and `spacing`; twist t in radians).
//   - Twist (i, j), i = 0..cols-1 along x, j = 0..rows-1 along y, is centred at
//     (i spacing, j spacing_y) (spacing_y = spacing unless given: rectangular cells). Twists with i + j even are the square twist of square_twist.hpp
//     (central square A B C D, side `side`, A the lowest vertex, outer creases axis-parallel,
//     A's o_b along +x); twists with i + j odd are its mirror image in the vertical line
//     through their centre (A B C D then run clockwise). Mirroring the neighbours is what
//     lets pleats meet: a twist's right pleat leaves at heights {y_A, y_B}, its left pleat
//     at {-y_A, -y_B}, so a same-handed neighbour would not line up.
//   - Each outer crease runs to the vertex of the neighbouring twist on the same line (a
//     pleat crease), or to the sheet's edge. Crease o_b meets the neighbour's o_b and o_a
//     meets o_a. The sheet is the rectangle of the twists' spacing x spacing cells,
//     [-spacing/2, (cols - 1/2) spacing] x [-spacing_y/2, (rows - 1/2) spacing_y].
//   - Panels: the central squares; an isosceles trapezoid per pleat between two twists
//     (a quadrilateral cut by the sheet's edge for the outward pleats); one rectangle per
//     grid corner between four twists (cut by the edge on the border); every vertex has
//     the sectors pi/2, pi - t, pi/2, t of the single twist, so Kawasaki holds exactly.
//   - Requires spacing > side (sin t + cos t) (square_twist_tessellation_min_spacing): the
//     twists' extent, so every crease has positive length.
//   Counts: V = 4 rows cols + 4 (rows + cols) + 4, E = 8 rows cols + 6 (rows + cols) + 4,
//   F = 4 rows cols + 2 (rows + cols) + 1. 1 x 1 is the square twist of square_twist.hpp in a
//   square sheet (same twist vertices, same interior edge order).
//
// Ordering.
//   Vertices: 4 (j cols + i) + k is vertex k (A, B, C, D) of twist (i, j); then the boundary
//     vertices counter-clockwise from the lower-left corner (corners included).
//   Edges: 4 (j cols + i) + k is side k (k -> k+1: AB, BC, CD, DA) of twist (i, j); then the
//     outer creases, twist by twist, vertex by vertex, o_a then o_b, a crease shared with an
//     earlier twist not repeated; then the boundary edges counter-clockwise (B).
//
// Assignment rule. Each twist gets four side letters; its outer creases then follow the
// single-twist rule (square_twist_assignment; mirroring keeps which creases bound the sector
// t): at vertex k with previous side P and twist side S, o_a = P, and o_b = P if P != S
// (the odd crease is the side S) else o_b = -P (the odd crease is o_b). A pleat crease gets a
// letter from both of its twists; they must agree (else InputError "sides").
//
// Why the rigid layouts fold (the exact multiplier model, multiplier_propagation.hpp). With
// mu = tan(pi/4 - t/2) = (1 - sin t) / cos t < 1, a vertex v whose odd crease is a side
// (s_v = 1) has |tan(rho/2)| = T_v on (previous side, o_b) and mu T_v on (twist side, o_a);
// one with its odd crease on o_b (s_v = 0) has T_v on (twist side, o_a) and mu T_v on
// (previous side, o_b). Writing T_v = mu^{l_v}, the ties of one crease are linear in l:
//   side k -> k+1:  l_{k+1} = l_k + s_k + s_{k+1} - 1;
//   o_a meets o_a:  l_u + s_u = l_w + s_w;        o_b meets o_b:  l_u - s_u = l_w - s_w.
// The sheet is a disk, so the loop gain is 1 around every cycle iff it is 1 around every face
// whose corners are all twist vertices; summing the ties around each face:
//   central square:            s_A + s_B + s_C + s_D = 2 (each twist Type 3 or Type 4);
//   pleat trapezoid:           s_u1 + s_u2 = s_w1 + s_w2 (the two corners on each twist);
//   rectangle c1 c2 c3 c4:     s_c1 + s_c3 = s_c2 + s_c4 (c1 -o_a- c2 -o_b- c3 -o_a- c4 -o_b- c1).
// Horizontal pleats join like-named vertices (A-A, B-B; C-C, D-D) and vertical ones B-D, C-A.
//   Type4      every twist sides V M M M (Type 4, odd side AB): s = (1, 1, 0, 0) for
//              A, B, C, D. Sum 2; horizontal pleats and rectangles join equal s; vertical
//              pleats s_B + s_C = 1 = s_D + s_A. Letters agree across vertical pleats because
//              BC = DA and o_b(B) = o_b(D) = V.
//   Type3Rows  rows j even: V M M V, rows j odd: M V V M (both Type 3): s = (0, 1, 0, 1) in
//              every twist, so all face sums agree as above; the letters meet (o_a: BC of
//              the lower twist = DA of the upper; o_b(B) below = o_b(D) above).
// All ties form one connected graph, so both layouts fold with exactly 1 DOF (checked by
// the multiplier verdict and the general solver in tests/data/square_twist_tessellation_test.cpp).
// Enumerating all 2^16 side letters of a 2 x 2 sheet with the multiplier verdict gives 4096
// consistent assignments, 60 of them rigid (all 1 DOF) at any t tried (15..75 deg); these
// two layouts are the ones among them that repeat to any size with one rule per row.
//   AllType1   every twist M M M M; AllType2 every twist V M V M. The letters are consistent,
//              but each central square has loop gain mu^{-4} (Type 1) or mu^{4} (Type 2),
//              not 1: no twist can fold, so the sheet has 0 DOF (verdict: not rigidly foldable).
#include <array>
#include <numbers>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

enum class SquareTwistTessellationLayout { Type4, Type3Rows, AllType1, AllType2 };

struct SquareTwistTessellationParams {
  int rows = 2;                                     // twists along y, 1..500
  int cols = 2;                                     // twists along x, 1..500
  double twist = std::numbers::pi / 6;              // t, radians, in (0, pi/2)
  double side = 1.0;                                // side of every central square (> 0)
  double spacing = 2.5;                             // twist centre to centre; > side (sin t + cos t)
  double spacing_y = 0.0;                           // along y when > 0 (same bound); 0: `spacing`
  SquareTwistTessellationLayout layout = SquareTwistTessellationLayout::Type4;
};

// side * (sin t + cos t): the width of one twist's vertices, the least valid spacing.
double square_twist_tessellation_min_spacing(double twist, double side);

// DOF of the layout's rigid folding: 1 (Type4, Type3Rows) or 0 (AllType1, AllType2).
int square_twist_tessellation_dof(SquareTwistTessellationLayout layout);

// Side letters AB, BC, CD, DA of a twist in row j of the layout.
std::array<Assignment, 4> square_twist_tessellation_twist_sides(SquareTwistTessellationLayout layout, int j);
// Per twist (index j cols + i) for params.layout. Throws InputError as the generator does.
std::vector<std::array<Assignment, 4>> square_twist_tessellation_sides(const SquareTwistTessellationParams& params);

// Validated pattern with params.layout. Throws InputError (place "rows", "cols", "twist",
// "side", "spacing" or "spacing_y").
CreasePattern square_twist_tessellation(const SquareTwistTessellationParams& params);
// Validated pattern with explicit side letters per twist (rows * cols entries, each M or V;
// params.layout is ignored). Throws InputError("sides", ...) for a wrong count, a letter
// other than M/V, or two twists giving a pleat crease different letters.
CreasePattern square_twist_tessellation(const SquareTwistTessellationParams& params,
                                        const std::vector<std::array<Assignment, 4>>& sides);

const char* to_string(SquareTwistTessellationLayout layout);  // "type4", "type3-rows", "type1", "type2"
// Inverse of to_string; throws InputError("layout", ...) for another name.
SquareTwistTessellationLayout square_twist_tessellation_layout_from_string(const std::string& name);

}  // namespace rigidfold::generators
