#pragma once
// "Foldable within the precision of your file" for flat crease patterns (issue 12, item 3):
// a Miura-ori or square twist exported with 3 decimals (Origami Simulator's SVGs) has degree-4
// vertices that miss Kawasaki's condition by ~1e-5 rad, so the exact multiplier model does
// not apply and the general model, judging the rounded numbers exactly, finds them rigid or
// cannot decide. The file is nonetheless consistent with a flat-foldable design.
//
// The witness: the file's vertices moved, each coordinate c by at most its rounding u(c)
// (coordinate_precision.hpp), so that every interior vertex meets Kawasaki exactly
// (alternate sectors sum to pi; sector sums stay 2 pi in the plane). Gauss-Newton on the
// Kawasaki defects g_v(x) = theta_2 - theta_1 + theta_4 - theta_3 - pi (theta_i: directions of
// the vertex's creases in counter-clockwise order) with steps of least u-weighted norm,
//     dx = W J^T (J W J^T)^-1 (-g),  W = diag(u_c^2),
// until |g|_inf <= 1e-14 rad; then up to 11 more solves from the file's coordinates with the
// weights of the coordinates that moved furthest (relative to u) lowered, keeping the solve
// whose largest |move| / u is least. If every coordinate moved by at most its rounding, the witness
// is a crease pattern the file could have been written from: its exact verdict (the
// multiplier model's, check_foldability) is the verdict "within the input's precision". The
// witness's Kawasaki defects are measured again from its own topology (build_topology), not
// from g, before it is used.
//
// Applies to: a 2D pattern (every z = 0) whose interior vertices all have degree 4, written
// with rounded coordinates (CoordinatePrecision::rounded), at least one vertex missing
// Kawasaki by more than `kawasaki_tolerance`. Otherwise std::nullopt.
// Limit: the least weighted move is one witness, not the designer's pattern; when it moves
// some coordinate further than its rounding (explained = false) another witness might
// still exist, so that says "not explained by this witness", not "no witness".
// Limit: the witness aims at Kawasaki only, not at the loop gains of the multiplier model, so
// a pattern with cycles of vertices (a Miura larger than a strip) gets a witness whose gains
// miss 1 by about the rounding: check_foldability then says "undecided", never "no". And an
// SVG whose vertices were made by the reader where lines cross carries computed coordinates
// (-606.6436666666667), which coordinate_precision does not read as rounded: no witness.
// Next: loop-gain rows in the same least-move solve, and bounds from the SVG's own numbers.
// Units: radians; lengths in the pattern's unit.
#include <optional>

#include "kernel/pattern/coordinate_precision.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct FlatFoldableWitness {
  CoordinatePrecision precision;
  double max_kawasaki_defect = 0.0;   // of the file, over interior vertices (radians)
  int worst_defect_vertex = -1;
  double max_move = 0.0;              // largest coordinate move (length unit)
  double max_move_ratio = 0.0;        // largest |move| / u(c) (<= 1: within the rounding)
  int worst_move_vertex = -1;
  double witness_kawasaki = 0.0;      // largest defect of the witness, from its own topology
  int iterations = 0;
  bool explained = false;             // every move within its rounding, witness flat-foldable
  CreasePattern witness;              // the file's pattern with the moved coordinates
  Topology witness_topology;
};

std::optional<FlatFoldableWitness> flat_foldable_witness(const CreasePattern& pattern, const Topology& topology,
                                                         double kawasaki_tolerance);

}  // namespace rigidfold
