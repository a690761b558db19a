#pragma once
// repair_pattern: the least move of a flat pattern's vertices that makes it rigidly foldable
// from flat with its M/V letters (docs/repair.md).
//
// Applies to flat patterns whose interior vertices all have four creases, none flat (F) or
// joined (J), on sheets without holes: the multiplier model (multiplier_propagation.hpp) is
// then exact, and the pattern folds with its letters exactly when
//   - every interior vertex is flat-foldable (Kawasaki: alpha_0 + alpha_2 = pi), and
//   - in the vertex modes the letters choose, every independent cycle of ties has loop
//     gain 1 (flat_fold_constraints.hpp),
// (and the signs agree, which the letters guarantee for M/V creases). Those are smooth
// equations c(x) = 0 in the coordinates x, with exact Jacobian J. The repair solves
//     minimise |x - x0|^2 over the free coordinates subject to c(x) = 0
// by Gauss-Newton SQP: each step is the least-norm displacement from x0 that meets the
// linearised constraints, e' = J^T (J J^T)^-1 (J e - c), e = x - x0 (columns of fixed
// vertices removed); at its fixed point c = 0 and x - x0 = J^T lambda (first-order
// optimality: the move is a combination of constraint normals). The lambdas say which
// constraints cost the move (RepairSummary::costliest).
//
// The vertex modes: at each interior vertex the mode whose multiplier signs match the
// letters at x0 (mode_sign_matching_letters); where both do (U creases), the mode in which
// every crease folds, else kEqual13, and the summary counts those vertices. The move keeps
// the modes, so it cannot change which crease of a vertex is odd (Maekawa).
//
// The repaired pattern is written as FOLD text and read back, and check_foldability judges
// it from scratch with its numbers taken as exact (RepairSummary::after): "repaired" means
// that check says "foldable" with its certificate. The input is checked first (before); a
// pattern already foldable is left as it is.
//
// Limits: the least move is a local minimum of the SQP from x0 (the nearest pattern for small
// defects; a far one might be nearer through other modes). With max_move, a least move above
// it is reported as kBeyondMaxMove with the violation left at the largest allowed step along
// it: evidence that no repair within the bound exists, not a proof.
// Units: lengths in the pattern's unit; Kawasaki rows in radians; gain rows |log gain|.
#include <optional>
#include <string>
#include <vector>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"

namespace rigidfold {

struct RepairOptions {
  bool keep_boundary = false;          // vertices on the sheet's boundary stay where they are
  std::vector<int> fixed_vertices;     // and these too
  std::optional<double> max_move;      // largest distance any vertex may move (length unit)
  // false (--letters free): the letters are ignored; each vertex takes its less degenerate
  // mode, and the checks ignore the letters too ("foldable" then means: with some letters).
  bool use_letters = true;
  int max_iterations = 60;
  double kawasaki_tolerance = 1e-13;   // radians, largest |alpha_0 + alpha_2 - pi| accepted
  double gain_tolerance = 1e-12;       // largest |log loop gain| accepted
  FoldabilityOptions check;            // for the checks before and after (use_assignment: use_letters)

  // False, with the reason, for a negative or non-finite bound or tolerance, a fixed vertex
  // out of range (num_vertices: the pattern's), or max_iterations < 1.
  bool IsValid(int num_vertices, std::string* error) const;
};

enum class RepairTermination {
  kAlreadyFoldable,      // the input folds with its letters; nothing moved
  kRepaired,             // constraints met, and the repaired pattern's check says foldable
  kCheckDisagrees,       // constraints met, but the check of the repaired pattern does not say foldable
  kBeyondMaxMove,        // the least move takes some vertex further than max_move
  kNoConvergence,        // the SQP did not meet the constraints (max_iterations, or no step)
  kInvalidPattern,       // the constraints hold where creases cross or a vertex lies on a crease
  kNotRepairable,        // no move of the free vertices in these modes can (message says why)
};
const char* to_string(RepairTermination t);
// Exit-status meaning: true for kAlreadyFoldable and kRepaired (a pattern that folds).
bool succeeded(RepairTermination t);

// One constraint and its Lagrange multiplier at the repair.
struct RepairConstraint {
  std::string kind;          // "kawasaki" or "loop gain"
  std::vector<int> vertices; // the vertex (kawasaki) or the cycle's vertices (loop gain)
  double before = 0.0;       // its value at the input (radians, or log gain)
  double lambda = 0.0;       // the move it costs: x - x0 = J^T lambda
};

struct RepairSummary {
  RepairTermination termination = RepairTermination::kNotRepairable;
  std::string message;                  // one line for the user
  FoldabilityReport before;             // the input's check
  std::optional<FoldabilityReport> after;  // the repaired pattern's check, from its FOLD text
  bool letters_used = true;             // RepairOptions::use_letters
  std::vector<FlatFoldMode> modes;      // per interior vertex (topology order)
  std::vector<int> interior_vertices;
  int modes_chosen_without_letters = 0; // vertices where the letters allowed both modes
  int kawasaki_rows = 0, gain_rows = 0;
  int free_coordinates = 0, fixed_vertex_count = 0;
  double kawasaki_before = 0.0, gain_before = 0.0;  // largest |row| at the input
  double kawasaki_after = 0.0, gain_after = 0.0;    // at the repair (or at the least violation reached)
  int iterations = 0;
  // The SQP's steps ended within max_iterations. When false but the constraints hold, the
  // pattern is still a repair (kRepaired), perhaps not the least: stationarity says how far.
  bool least_move_converged = false;
  double stationarity = 0.0;            // |(x - x0) - J^T lambda| / |x - x0| at the repair
  std::vector<double> vertex_move;      // distance each vertex moved (length unit)
  int worst_vertex = -1;
  double max_move = 0.0, rms_move = 0.0;    // over all vertices (length unit)
  double pattern_size = 0.0;            // bounding-box diagonal (length unit)
  std::vector<RepairConstraint> costliest;  // up to 8 constraints with the largest |lambda|
  CreasePattern repaired;               // the moved pattern (the input when not repaired)
  double seconds = 0.0;
};

// Throws InputError, naming the vertex or the edge, when the pattern is outside the repair's
// model: not flat, a sheet with a hole, an interior vertex without four creases that fold.
void require_repair_scope(const CreasePattern& pattern, const Topology& topology);

// The vertex modes the repair keeps (see above), one per interior vertex in topology order;
// empty, with refusal set, when some vertex's letters match neither mode.
// chosen_without_letters: the vertices where the letters allowed both.
// use_letters false: every vertex takes its less degenerate mode, letters ignored.
std::vector<FlatFoldMode> repair_modes(const CreasePattern& pattern, const Topology& topology, int& chosen_without_letters,
                                       std::string& refusal, bool use_letters = true);

// Throws InputError (naming the vertex or the place) when the pattern is outside the
// repair's scope (see above) or the options are invalid.
RepairSummary repair_pattern(const CreasePattern& pattern, const Topology& topology, const RepairOptions& options = {});

}  // namespace rigidfold
