#pragma once
// Square-twist crease pattern (seed 001 §2, seed 003 §3.3) with any M-V assignment, and the
// modified patterns with a diagonal crease in the central square (seed 001 §3-4, Types 1M
// and 2M).
//
// Geometry (seen from +z), twist angle t in (0, pi/2) = seed 001's alpha = seed 003's
// gamma = pi - (seed 003's alpha):
//   - a central square A B C D (vertices 0..3, counter-clockwise), side `side`;
//   - at each square vertex two outer creases of length `pleat`, at right angles to each
//     other, all parallel to x or y (seed 003 Fig. 3-13: "the other creases are horizontal
//     or vertical"); vertex A is the lowest one, its outer creases point along +x and -y;
//   - four parallelogram panels on the square's sides (angles t and pi - t) and four
//     pleat x pleat rectangles at the corners; 9 panels, 16 vertices.
//   Each square vertex has sectors, counter-clockwise from the side to the next vertex:
//       pi/2 (square), pi - t, pi/2 (rectangle), t (the twist sector).
//   The twist sector t lies between the side to the NEXT vertex (A's: AB) and the outer
//   crease "o_b"; the other outer crease is "o_a". So side AB is A's "twist side", as in
//   seed 001 (joint a2 = b1 borders alpha_23 = alpha). Seed 001 numbers a vertex's joints
//   1 = side to the previous vertex, 2 = twist side, 3 = o_b, 4 = o_a, which runs clockwise
//   in this picture; the sector order is then seed 001 eq. (4): pi/2, alpha, pi/2, pi - alpha.
//
// Edge order (the "interior crease" vectors below use the first 12 or 13):
//   0..3   sides AB, BC, CD, DA
//   4..11  outer creases o_a, o_b of A, then of B, C, D (o_a, o_b counter-clockwise)
//   12     the diagonal, if any
//   then the boundary edges (B).
//
// Flat-foldable assignments. The smallest sector t lies between the twist side and o_b, so
// by Maekawa and Big-Little-Big the odd crease of a vertex is either
//   - o_b (seed 001 eq. (5a); theta_1, theta_3 of opposite sign): the two sides agree, or
//   - its twist side (eq. (5b); theta_1, theta_3 alike): the two sides differ.
// Hence the four side letters fix the whole assignment, and all 2^4 = 16 side patterns are
// valid (seed 001: "16 types"). Up to rotation and global M/V flip there are four types,
// named as in seed 001 §2:
//   Type1  sides M M M M (all alike)         every vertex (5a)            NOT rigid
//   Type2  sides V M V M (alternating)       every vertex (5b)            NOT rigid
//   Type3  sides M V V M (two and two)       (5a) at A, C; (5b) at B, D   rigid
//   Type4  sides V V V M (three and one)     (5b) at A, D; (5a) at B, C   rigid
// (Loop gain of the tan-half multipliers: k^4 for Types 1, 2 with k = cos t/(1 -+ sin t),
// and 1 for Types 3, 4: rigid iff exactly two vertices have their odd crease on a side.)
// Seed 003 labels the four types T1..T4 in a lost figure, with T1, T2 rigid and T3, T4 not:
// T1/T2 are Types 3/4 and T3/T4 are Types 1/2. Its only textual hint, "the rectangle panels
// in T1 are all parallel to each other", is a property of Type 3 (checked in
// tests/data/square_twist_test.cpp), so T1 = Type3, T2 = Type4. Which of T3/T4 is Type 1 and
// which Type 2 cannot be recovered from the text.
//
// Modified patterns (seed 001 §3-4, eqs. (11), (15), (17), (19), (21)): the diagonal BD of
// the central square is added, making B and D 5-crease vertices with sectors
// pi/4, pi/4, t, pi/2, pi - t (eq. (11)):
//   Type1M  Type 1 sides (all M), diagonal BD V (opposite to the sides)
//   Type2M  Type 2 sides (AB V, BC M, CD V, DA M), diagonal BD V (the sign of the outer
//           creases at B and D)
// A degree-5 vertex cannot satisfy Kawasaki; these patterns are rigid with 1 DOF and bifurcate.
#include <array>
#include <numbers>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

enum class SquareTwistType { Type1, Type2, Type3, Type4 };
enum class SquareTwistModifiedType { Type1M, Type2M };
enum class SquareTwistDiagonal { None, BD, AC };

struct SquareTwistParams {
  double twist = std::numbers::pi / 6;  // t, radians, in (0, pi/2)
  double side = 1.0;                    // side of the central square (> 0)
  double pleat = 1.0;                   // length of the outer creases (> 0)
  SquareTwistDiagonal diagonal = SquareTwistDiagonal::None;
};

// Sides AB, BC, CD, DA of each type (as in the table above).
std::array<Assignment, 4> square_twist_sides(SquareTwistType type);
// The flat-foldable 12-crease assignment (edge order above) fixed by the four side letters
// (each M or V). Throws InputError("sides", ...) for another letter.
std::vector<Assignment> square_twist_assignment(const std::array<Assignment, 4>& sides);
std::vector<Assignment> square_twist_assignment(SquareTwistType type);
// The 13-crease assignment of Type1M / Type2M (diagonal BD last).
std::vector<Assignment> square_twist_modified_assignment(SquareTwistModifiedType type);

// Square twist with an explicit assignment of its interior creases: 12 letters in the edge
// order above, 13 when params.diagonal != None (each M, V, F or U). Not checked for flat
// foldability. Throws InputError (place "twist", "side", "pleat" or "assignment").
CreasePattern square_twist(const SquareTwistParams& params, const std::vector<Assignment>& interior);
// One of the four types (params.diagonal must be None).
CreasePattern square_twist(const SquareTwistParams& params, SquareTwistType type);
// Type 1M or 2M (the diagonal BD is added; params.diagonal is ignored).
CreasePattern square_twist_modified(const SquareTwistParams& params, SquareTwistModifiedType type);

const char* to_string(SquareTwistType type);          // "type1" ...
const char* to_string(SquareTwistModifiedType type);  // "type1m", "type2m"

}  // namespace rigidfold::generators
