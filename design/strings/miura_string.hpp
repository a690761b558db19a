#pragma once
// MiuraString: an origami string, a strip of N asymmetric Miura vertices along a straight
// spine (seed 000, refs [5, 6]), and its crease pattern.
//
// Flat layout (seen from +z, lengths in the user's units, angles in radians):
//   spine along +x from S = (0, 0): lead-in segment lengths[0], then the vertices
//   V_0 .. V_{N-1} at x_i = lengths[0] + ... + lengths[i], then the lead-out segment
//   lengths[N] to E = (x_{N-1} + lengths[N], 0). lengths has N + 1 entries.
//   The strip spans y in [-width/2, width/2]. At V_i the top peripheral crease b_i runs to
//   (x_i + (width/2) cot alpha1_i, width/2), the bottom one d_i to
//   (x_i + (width/2) cot alpha2_i, -width/2): both lean forward (toward +x, the outgoing
//   spinal crease a), alpha in (0, pi/2). Peripheral creases of neighbouring vertices must
//   not cross and must end inside the strip (checked).
//
// Crease pattern (build_string_pattern), numbering that the rest of design/strings uses:
//   vertices: S, V_0..V_{N-1}, E (spine, ids 0..N+1); then T_0..T_{N-1} (top ends of b);
//             then B_0..B_{N-1} (bottom ends of d); then TL, TR, BL, BR (corners).
//   edges:    spinal creases s_0..s_N first (s_k runs +x: s_0 = S->V_0, s_k = V_{k-1}->V_k,
//             s_N = V_{N-1}->E), then b_i = V_i->T_i, then d_i = V_i->B_i, then the
//             boundary (B). Spinal crease s_i is crease c of vertex i and a of vertex i-1.
//   faces:    top faces 0..N (face k between s_k and the top boundary), then bottom faces
//             N+1..2N+1. Face 0 (top lead-in) is the root that face placement holds fixed.
//   Assignments M/V from the signs of the given fold angles (V where the angle is >= 0).
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::design {

struct MiuraString {
  std::vector<double> alpha1;   // per vertex, radians, (0, pi/2), top side
  std::vector<double> alpha2;   // per vertex, radians, (0, pi/2), bottom side
  std::vector<double> lengths;  // N + 1 spine segment lengths (> 0): lead-in, between vertices, lead-out
  double width = 1.0;           // strip width (> 0)

  int size() const { return static_cast<int>(alpha1.size()); }
};

// Index helpers of the pattern built by build_string_pattern (see the numbering above).
struct StringPatternIndex {
  int n = 0;
  int spine_vertex(int k) const { return k; }  // k = 0: S, 1..N: V_{k-1}, N+1: E
  int vertex_of(int i) const { return 1 + i; }  // V_i
  int spinal_edge(int k) const { return k; }    // s_k, k = 0..N
  int top_edge(int i) const { return n + 1 + i; }
  int bottom_edge(int i) const { return 2 * n + 1 + i; }
};

// Checks sizes, finiteness and ranges, and (check_width) that the peripheral creases
// neither cross nor leave the strip. The kinematics does not depend on the width and
// checks without it. Throws std::invalid_argument with the first problem (field[index]).
void validate_string(const MiuraString& s, bool check_width = true);

// The largest strip width for which the peripheral creases of `s` do not cross or leave
// the strip (the pattern is valid for any width strictly below it).
double max_string_width(const MiuraString& s);

// A random string for tests and benchmarks: n vertices with alpha1, alpha2 uniform in
// [alpha_min, alpha_max] (radians, inside (0, pi/2)), segment lengths uniform in [0.8, 1.2],
// width = width_fraction * max_string_width (width_fraction in (0, 1)). The same seed gives
// the same string on every platform (a portable stream, not std distributions).
MiuraString random_miura_string(int n, std::uint64_t seed, double alpha_min, double alpha_max, double width_fraction);

// Flat crease pattern (numbering above). edge_fold_angles: one per edge (radians) to
// store as edges_foldAngle and to take the M/V assignment from; empty = all valley,
// no angles stored. Validated with the kernel's complete_and_validate.
CreasePattern build_string_pattern(const MiuraString& s, const Eigen::VectorXd& edge_fold_angles = {});

// SVG for cutting: boundary black, mountain red, valley blue (dashed for mountains), in
// the pattern's length units scaled by `scale` px per unit, y up.
std::string string_pattern_svg(const CreasePattern& pattern, double scale = 100.0);

}  // namespace rigidfold::design
