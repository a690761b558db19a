#pragma once
// "Foldable within the precision of your file" for flat crease patterns:
// a Miura-ori or square twist exported with 3 decimals (Origami Simulator's SVGs) has degree-4
// vertices that miss Kawasaki's condition by ~1e-5 rad, so the exact multiplier model does
// not apply and the general model, judging the rounded numbers exactly, finds them rigid or
// cannot decide. The file is nonetheless consistent with a flat-foldable design.
//
// The witness: the file's vertices moved, each coordinate c by at most its rounding u(c)
// (coordinate_precision.hpp, or the reader's bounds: see below), so that every interior vertex meets Kawasaki exactly
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
// SVG's vertices are computed by the reader (the mean of near-coincident drawn ends, or where
// lines cross), so their digits say nothing: there the reader's own bounds are used
// (CreasePattern::position_bounds), from the digits of the SVG's numbers. Each coordinate may
// then move by a different amount down and up (the box need not be centred on the vertex).
// Loop gains: the least move aims at Kawasaki only unless gain_modes are given (below): a
// rounded Miura's Kawasaki-only witness misses gain 1 by about the rounding.
// Units: radians; lengths in the pattern's unit.
#include <optional>

#include "kernel/pattern/coordinate_precision.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"

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
  // True when the bounds came from the reader (CreasePattern::position_bounds: an SVG's drawn
  // points, each vertex within the box of the points drawn for it grown by their rounding),
  // false when read off the digits of the coordinates (coordinate_precision).
  bool drawn_point_bounds = false;
  // With gain_modes: the independent cycles of ties whose log |loop gain| was driven to 0 too,
  // and the largest |log gain| left at the last solve.
  int loop_gain_rows = 0;
  double max_log_gain = 0.0;
  // The box each vertex of the file may lie in (x, y; length unit): the coordinates minus
  // and plus the moves allowed down and up. The witness lies in them, and so do the file's
  // own vertices.
  std::vector<Eigen::Vector2d> box_lo, box_hi;
  CreasePattern witness;              // the file's pattern with the moved coordinates
  Topology witness_topology;
};

// gain_modes (optional, one mode per interior vertex in topology order, e.g. the only modes
// the letters allow): the least move also closes every cycle of the multiplier model in
// those modes (loop gain 1, rows solved with the Kawasaki rows; flat_fold_constraints.hpp,
// exact Jacobian). Then a pattern already flat-foldable as read is moved too. nullopt when the
// modes leave a tie with a zero multiplier, a cycle with a negative gain, or no cycle.
// stated_tolerance: the user's bound on each coordinate (input_precision), used instead of
// the reader's boxes and the digits; 0 (exact data): no witness.
std::optional<FlatFoldableWitness> flat_foldable_witness(const CreasePattern& pattern, const Topology& topology,
                                                         double kawasaki_tolerance,
                                                         const std::vector<FlatFoldMode>* gain_modes = nullptr,
                                                         std::optional<double> stated_tolerance = std::nullopt);

}  // namespace rigidfold
