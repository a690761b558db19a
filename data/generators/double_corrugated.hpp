#pragma once
// Units P and Q of the double-corrugated pattern (seed 003 §3.2), each a 3x3-panel
// (Kokotsakis) crease pattern with four interior degree-4 vertices.
//
// Sectors: alpha, beta, gamma = pi - alpha, delta = pi - beta (flat-foldable), gamma the
// smallest: alpha in (pi/2, pi), beta in (pi - alpha, alpha). Seed 003's example is
// alpha = 3pi/4, beta = pi/3, gamma = pi/4, delta = 2pi/3 (the defaults).
// Vertex types (seed 003 §3.2.1), joints numbered counter-clockwise:
//   type I  (A, C, E): sector j1-j2 = alpha, j2-j3 = beta,  j3-j4 = gamma, j4-j1 = delta
//   type II (B, D, F): sector j1-j2 = alpha, j2-j3 = delta, j3-j4 = gamma, j4-j1 = beta
//   (type II is type I read clockwise: its mirror image).
// Shared creases (seed 003 eqs. (3-17)-(3-23)):
//   P = A B C D: a2 = b3, b4 = c1, c2 = d3, d4 = a1; central panel A-D-C-B (angles alpha at
//     A and C, gamma at B and D).
//   Q = A B E F: b3 = a2, e3 = b2, f3 = e2, a3 = f2; central panel F-A-B-E (angles beta at
//     A and E, delta at B and F).
//
// CONSTRUCTION (the thesis's figures are lost; this is our explicit choice). The sheet is a
// parallelogram mesh (see parallelogram_lattice.hpp) whose edge directions zig-zag in both
// directions, hence "double corrugated":
//   i-edges alternate between direction 0 and alpha + beta + pi (length a),
//   j-edges alternate between direction beta and alpha (length b),
// with type I and type II vertices in a checkerboard. Units P and Q are 4x4-node windows of
// that mesh sharing the crease AB (P on one side, Q on the other), both with mirror-free
// 2-fold rotational symmetry about their centre:
//   P: u = (alpha+beta+pi, 0, alpha+beta+pi), v = (beta, alpha, beta);
//      A = node(1,1), B = node(1,2), C = node(2,2), D = node(2,1).
//   Q: u = (0, alpha+beta+pi, 0), v = (beta, alpha, beta);
//      F = node(1,1), A = node(2,1), B = node(2,2), E = node(1,2).
// All nine panels are parallelograms; with beta = pi/2 unit Q is a square twist (seed 003:
// "the square-twist pattern is a special case of unit Q").
// This construction reproduces the thesis's counts: 10 flat-foldable M-V assignments of P
// (4 rigid) and 6 of Q (4 rigid), up to global M/V flip and the unit's 2-fold symmetry.
//
// Interior creases (the order of every assignment vector here, 12 letters):
//   P: sides AB, BC, CD, DA, then a3 a4, b1 b2, c3 c4, d1 d2
//   Q: sides AB, BE, EF, FA, then a4 a1, b4 b1, e4 e1, f4 f1
// (the outer creases of each vertex in counter-clockwise order after the central panel).
//
// Flat-foldable assignments: gamma lies between joints 3 and 4 of every vertex, so the odd
// crease (Maekawa 3:1, Big-Little-Big) of a vertex is joint 3 or joint 4. Rigidity (tan-half
// multiplier loop gain = 1, see seed 003 §3.2.2):
//   P is rigid iff #{A, C odd at joint 3} = #{B, D odd at joint 4};
//   Q is valid iff an even number of vertices are odd at joint 3, rigid iff exactly two are.
#include <array>
#include <numbers>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

enum class CorrugatedUnit { P, Q };

struct CorrugatedParams {
  double alpha = 3 * std::numbers::pi / 4;  // radians, in (pi/2, pi)
  double beta = std::numbers::pi / 3;       // radians, in (pi - alpha, alpha)
  double a = 1.0;                           // length of the i-edges (> 0)
  double b = 1.0;                           // length of the j-edges (> 0)
};

// One interior vertex of a unit: its name, vertex index, type and creases (edge indices)
// for joints j1..j4 (counter-clockwise, seed 003 numbering).
struct CorrugatedVertex {
  char name = '?';
  int vertex = -1;
  bool type_one = true;  // type I (A, C, E) or type II (B, D, F)
  std::array<int, 4> joints{};
};
// The four vertices in the unit's order: P: A B C D; Q: A B E F.
std::array<CorrugatedVertex, 4> corrugated_vertices(CorrugatedUnit unit);
// The 12 interior crease edge indices, in the assignment order above.
std::array<int, 12> corrugated_interior_edges(CorrugatedUnit unit);

// The flat-foldable assignment in which vertex k (unit order) has its odd crease at joint
// odd_joint[k] (3 or 4) and vertex A's non-odd creases are `sigma` (M or V).
// Throws InputError("odd_joint", ...) when the choice is inconsistent (Q with an odd number
// of joint-3 vertices) or a joint is not 3 or 4.
std::vector<Assignment> corrugated_assignment(CorrugatedUnit unit, const std::array<int, 4>& odd_joint,
                                              Assignment sigma = Assignment::Mountain);
// Every flat-foldable assignment with crease AB = M (one per global-flip class): 16 for P,
// 8 for Q. Each entry: the odd joints and the assignment.
struct CorrugatedChoice {
  std::array<int, 4> odd_joint{};
  std::vector<Assignment> assignment;
  bool rigid = false;  // by the loop-gain rule above
};
std::vector<CorrugatedChoice> corrugated_flat_foldable_assignments(CorrugatedUnit unit);
// The rigid assignment used by bundled_examples():
//   P: odd joints (4, 3, 4, 3) -> MVVM MV VV VM MM (all four vertices alike up to
//      orientation, like the thesis's P1);
//   Q: odd joints (3, 4, 3, 4) -> MMVV MM VM VV MV.
std::vector<Assignment> corrugated_rigid_assignment(CorrugatedUnit unit);

// The unit's crease pattern with the given 12 interior letters (M, V, F or U; not checked for
// flat foldability). Throws InputError (place "alpha", "beta", "a", "b" or "assignment").
CreasePattern corrugated_unit(CorrugatedUnit unit, const CorrugatedParams& params,
                              const std::vector<Assignment>& interior);

const char* to_string(CorrugatedUnit unit);  // "P", "Q"

}  // namespace rigidfold::generators
