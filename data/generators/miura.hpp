#pragma once
// Miura-ori crease pattern, its standard rigid-folding mode in closed form, and a randomly
// perturbed (generally not flat-foldable) variant.
//
// Layout (seen from +z; `rows` x `cols` parallelogram panels):
//   node (i, j), i = 0..cols, j = 0..rows, at
//       x = i*b + (j odd ? a*cos(alpha) : 0),   y = j*a*sin(alpha)
//   - STRAIGHT creases: the i-edges (i, j) -> (i+1, j), length b, along +x. For each j they
//     lie on one straight line y = const.
//   - ZIG-ZAG creases: the j-edges (i, j) -> (i, j+1), length a, direction alpha (j even) or
//     pi - alpha (j odd). For each i they form one zig-zag polyline running up the sheet.
//   Panels are parallelograms with sides a, b and acute angle alpha. The edges j = 0,
//   j = rows (straight) and i = 0, i = cols (zig-zag) are the boundary (B).
//   Vertex and edge numbering follow ParallelogramLattice (i-edges first, then j-edges):
//     vertex(i, j) = j*(cols+1) + i;  straight edge (i, j) = j*cols + i;
//     zig-zag edge (i, j) = cols*(rows+1) + j*(cols+1) + i.
//   Every interior node is a degree-4 vertex with sectors, counter-clockwise from +x,
//     alpha, pi-alpha, pi-alpha, alpha   (j even: the acute sectors touch the +x crease)
//     pi-alpha, alpha, alpha, pi-alpha   (j odd:  the acute sectors touch the -x crease).
//
// Assignment of the standard rigid mode (the one tested by miura_fold_angles):
//   - zig-zag line i (0 < i < cols) is M for even i, V for odd i (whole line alike);
//   - straight crease (i, j) (0 < j < rows) takes the assignment of zig-zag line i when j
//     is odd and the opposite one when j is even, so straight creases alternate along each
//     line and from line to line.
//   At every interior vertex the odd crease (Maekawa 3:1) is the straight crease between
//   the two acute sectors (Big-Little-Big).
//
// Closed form (derived from the flat-foldable degree-4 multipliers, seed 003 eq. (3-3)):
// in this mode the two zig-zag creases of a vertex fold alike (rho_z), the two straight
// creases by equal and opposite amounts (+-rho_s), and
//       tan(|rho_s| / 2) = cos(alpha) * tan(|rho_z| / 2).
// So the straight creases lag the zig-zag ones; both reach pi together (flat-folded).
#include <cstdint>
#include <optional>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct MiuraParams {
  int rows = 4;              // panels along y (zig-zag direction), >= 1
  int cols = 4;              // panels along x (straight direction), >= 1
  double alpha = 1.0471975511965976;  // acute panel angle, radians, in (0, pi/2); default 60 deg
  double a = 1.0;            // zig-zag segment length (> 0)
  double b = 1.0;            // straight segment length (> 0)
  // Random perturbation of the INTERIOR vertex positions: each of x and y moves by an
  // independent uniform amount in [-perturbation, +perturbation] (length units).
  // 0 = the exact Miura-ori. At most 0.2 * min(a, b) * sin(alpha), which keeps every panel
  // a simple quadrilateral. A perturbed Miura is generally not flat-foldable (Kawasaki fails
  // at its interior vertices): a non-foldable test case. Assignments are kept.
  double perturbation = 0.0;
  std::uint64_t seed = 1;    // seeds std::mt19937_64; the same seed gives the same file everywhere
};

// The crease pattern, validated, assignments as above, fold angles unset, FOLD titles set.
// Throws InputError(place = the MiuraParams field name) for a bad parameter.
CreasePattern miura_ori(const MiuraParams& params);

enum class MiuraCrease { Boundary, Straight, ZigZag };
// Kind of every edge of miura_ori(params), in its edge order.
std::vector<MiuraCrease> miura_crease_kinds(const MiuraParams& params);

// |rho_z| from |rho_s| (radians, in [0, pi]): 2*atan(tan(|rho_s|/2) / cos(alpha)).
double miura_zigzag_fold_angle(double alpha, double rho_straight);

// Fold angles (radians, FOLD sign) of every edge of the standard rigid mode of an
// UNPERTURBED Miura-ori with the assignment above, parameterised by the fold angle of the
// straight creases:
//   rho_straight in [-pi, pi]; |rho_straight| is the fold magnitude of every straight crease;
//   rho_straight > 0 folds every crease the way it is assigned (V > 0, M < 0), < 0 folds the
//   mirror state (every sign reversed). Zig-zag creases get miura_zigzag_fold_angle().
// Boundary edges get nullopt. Throws std::invalid_argument if `pattern` is not
// miura_ori(params) (vertex count or edge endpoints differ) or params.perturbation != 0.
std::vector<std::optional<double>> miura_fold_angles(const CreasePattern& pattern, const MiuraParams& params,
                                                     double rho_straight);

}  // namespace rigidfold::generators
