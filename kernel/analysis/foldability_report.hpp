#pragma once
// check_foldability: the front door of the kernel. One call from a pattern to its
// rigid-foldability report; `rigidfold check`, `rigidfold report` and `rigidfold trace` (via
// choose_model) go through it, and no caller decides a verdict of its own.
//
// Model choice (docs/DESIGN.md, "Model only what a scene needs"), in this order:
//   1. a sheet with holes (tubes), or a folded form (3D given state) whose vertices are not
//      developable (so the flat state is no configuration of its sectors): given-state
//      mobility (reference_mobility.hpp; one SE(3) closure per hole): DOF 0 is a proof of
//      rigidity, a traced branch a yes. A given state that does not close exactly is
//      judged against the input's precision (rounding_witness.hpp);
//   2. every interior vertex a flat-foldable degree-4 vertex: multiplier propagation
//      (multiplier_propagation.hpp), exact both ways, O(creases); the fold family is sampled
//      from flat to the fold limit, one branch per family component. A flat pattern whose
//      degree-4 vertices miss Kawasaki only by the rounding of its coordinates (an SVG
//      written with 3 decimals) gets the same model on a witness within that rounding
//      (flat_foldable_witness.hpp): "foldable within the input's precision" when the witness
//      folds, "undecided" when it does not (a proof for the witness only: the witness aims at
//      Kawasaki, not at the loop gains);
//   3. otherwise (or force_general): the general loop-closure verdict (general_verdict.hpp),
//      and, where the pattern has at most BranchExplorerOptions::max_unknowns free creases,
//      the branch explorer (branch_explorer.hpp). The explorer's branches are evidence the
//      search may lack: a branch leaving the flat state with DOF 1, every letter kept (or
//      letters ignored), no face crossing before it reaches certificate_fold, and residual at
//      most tolerances.certificate_residual all along, is a certified folding motion and
//      makes the verdict "foldable" even when the search found none.
//
// The question answered: with M/V letters given (and used), "foldable" means that a rigid
// motion from flat folds every lettered crease with its letter (the strict question). A
// certified motion that keeps every letter but leaves some lettered creases flat answers only
// the weak question: the verdict is then kFoldableInPart, or kNotFoldableProof where crossing
// straight lettered lines rule out every strict motion; `folds_in_part` and `strictness` keep
// the weak motion (which creases stay flat) in both cases. With letters ignored, any motion
// from flat is "foldable".
//
// Verdict classes (docs/DESIGN.md, "Verdict classes and tolerance"):
//   kFoldable                 a certified path (traced branch or exact family), every lettered
//                             crease folding with its letter where letters are used;
//   kFoldableInPart           a certified path that keeps every letter but leaves some lettered
//                             creases flat, and no motion folding them all was found or ruled out;
//   kFoldableWithinTolerance  a folded form whose closure gap the input's rounding explains:
//                             a pattern within the file's precision (the rounding witness)
//                             has the given state as an exact configuration and folds from it;
//   kNotFoldableProof         loop gain != 1, a pin, no mode matching the letters, DOF 0
//                             at a regular given state, no foldable crease, or straight
//                             lettered lines crossing (no motion folds every lettered crease);
//   kNotFoldableEvidence      the general search found no folded point near flat and its
//                             least residual is above the evidence floor and grows with the
//                             fold amplitude: numerical evidence, not a proof (is_proof false);
//   kUndecided                the models available did not decide (a search whose least
//                             residual sits near its floor, or does not grow with the fold).
//
// Units: radians, per-edge fold angles with the FOLD sign (valley > 0, mountain < 0);
// residuals ||r||_inf in radians; mismatches relative to the pattern's size.
// Throws: nothing for a valid pattern (a solver that cannot handle a pattern gives
// kUndecided with the reason); std::bad_alloc.
// Cost: O(creases) on the multiplier path; the general path is a few sparse Newton
// projections and one continuation, the explorer dense SVDs (<= 400 free creases).
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kernel/analysis/branch_explorer.hpp"
#include "kernel/analysis/foldability_class.hpp"
#include "kernel/analysis/flat_foldable_witness.hpp"
#include "kernel/analysis/general_verdict.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/analysis/progress.hpp"
#include "kernel/analysis/tolerances.hpp"
#include "kernel/analysis/traced_branch.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {


enum class FoldabilityModel { kMultiplierPropagation, kGeneralLoopClosure, kGivenStateHoleClosure, kNone };
const char* to_string(FoldabilityModel m);

struct FoldabilityOptions {
  bool use_assignment = true;   // false: every crease may fold either way (letters ignored)
  bool force_general = false;   // skip multiplier propagation (cross-checks)
  bool explore_branches = true; // run the branch explorer where it applies (general model)
  // Not run either when the verdict is already a certified motion whose DOF at the flat state is
  // above this: its max_branches departures would be an arbitrary sample of a cone of that
  // dimension, and its dense second-order work grows with it (a Resch triangle tessellation of
  // 376 creases, DOF 52: 30 of its 31 s in the explorer, for no change to the verdict).
  int max_explored_dof = 16;
  Tolerances tolerances = kDefaultTolerances;
  int family_samples = 64;      // multiplier model: points sampled along each family component
  // How far each coordinate may lie from the true one (the file's length unit; 0: exact data);
  // nullopt: read off the input (coordinate_precision.hpp). `check --tolerance`.
  std::optional<double> coordinate_tolerance;
  ProgressSink progress;        // the stage running, and the general model's and explorer's units of work
};

// Why a pattern does not fold (or the search's evidence that it does not).
struct FoldabilityObstruction {
  std::string kind;     // "loop gain", "pin", "vertex assignment", "sign" (multiplier model),
                        // "crossing lettered lines" (no strict motion; strict_obstruction_vertices),
                        // "no folded point found near flat" (general), "first-order rigid" (given state)
  std::string message;
  std::optional<Obstruction> exact;                   // the multiplier model's obstruction
  double least_residual = -1.0;                       // general / given state (radians)
  std::vector<std::pair<int, double>> worst_vertices; // general: (vertex, ||r_v||), largest first
  int crease_against_assignment = -1;                 // general: a start converged against this letter
  int starts_tried = -1, starts_converged_against_assignment = -1;  // general search
};

struct FoldabilityReport {
  FoldabilityClass verdict = FoldabilityClass::kUndecided;
  bool is_proof = false;            // a certificate or a proof (false: evidence, or undecided)
  FoldabilityModel model = FoldabilityModel::kNone;
  std::string model_name;           // the solver's own name ("multiplier-propagation", ...)
  std::string model_choice;         // why this model
  std::string reason;               // one line for the user
  bool assignment_used = true;
  Tolerances tolerances;            // the values used
  int dof = 0;                      // DOF at the certified motion (0 when there is none)
  std::string dof_basis;            // how the DOF was counted (rank cut, or family components)
  std::vector<TracedBranch> branches;
  // Points where branches meet. Multiplier model: the flat state. General model with the
  // explorer: every point it found (flat, located bifurcations, fold-limit ends).
  std::vector<BranchPoint> points;
  // General model without the explorer: bordered-determinant sign changes, not refined.
  std::vector<SingularPoint> unrefined_singular_points;
  bool branches_explored = false;   // the branch explorer ran
  std::string exploration_note;     // why it did not, when it did not
  double exploration_seconds = 0.0;
  bool exploration_budget_exhausted = false;  // BranchExplorerOptions::max_dense_work ran out
  std::vector<SignSwitch> sign_switches;  // general model: along the search's certificate trace
  // General model, a certified motion: strict (every M/V crease folds) or weak (the listed
  // lettered creases stay flat). Empty on other models and where no motion was certified.
  std::optional<StrictnessReport> strictness;
  // With letters: the certified motion leaves some lettered creases flat (strictness lists
  // them); the verdict is then kFoldableInPart or kNotFoldableProof, never kFoldable.
  bool folds_in_part = false;
  // General model, foldable: up to 6 states of the certifying path (per-edge fold angles,
  // radians; its first and last valid points included), for replay by other tools. Empty on
  // other models and verdicts.
  std::vector<Eigen::VectorXd> certificate_samples;
  // General model, no folded point found: the least sign-respecting closure residual at
  // each fold amplitude and its growth exponent (general_verdict.hpp, step 5) - the
  // evidence behind "not foldable (evidence)" or "undecided".
  std::vector<AmplitudeEvidence> search_evidence;
  double residual_growth_exponent = 0.0;
  // ... and the norm search at the pattern's own scale (not evidence).
  ScaledNormSearch scaled_norm_search;
  std::optional<FoldabilityObstruction> obstruction;  // when not foldable
  double max_residual = 0.0;        // largest closure residual along the reported branches (rad)
  std::optional<double> certificate_mismatch;     // face placement of the certificate (relative)
  std::optional<double> certificate_max_fold;     // multiplier: largest |rho| at the certificate (rad)
  std::optional<double> max_loop_gain_defect;     // multiplier: over the independent cycles
  // A folded form whose given state does not close exactly (rounded coordinates): the
  // rounding witness (rounding_witness.hpp) and the verdict of the exact data beside it.
  struct InputPrecision {
    // "sectors": a folded form's sectors moved to close its given state (rounding_witness);
    // "coordinates": a flat pattern's coordinates moved to make every vertex flat-foldable
    // (flat_foldable_witness; given_residual is then the largest Kawasaki defect as read);
    // "drawn points": the same, with the bounds of an SVG's drawn points (svg_reader.hpp).
    std::string witness_kind = "sectors";
    double max_coordinate_move = 0.0;   // "coordinates": largest move (length unit)
    int decimal_places = 0, significant_digits = 0;
    double coordinate_rounding = 0.0;   // largest bound on a coordinate's rounding (length unit)
    double given_residual = 0.0;        // closure gap of the given state as read (radians)
    double max_sector_bound = 0.0;      // largest sector error the rounding can cause (radians)
    double max_sector_change = 0.0;     // largest change the witness needed (radians)
    double max_change_ratio = 0.0;      // <= 1: the gap is explained by the rounding
    bool explained = false;
    std::string exact_data_verdict;     // what the exact data gives
    // Where the witness fails a loop gain: the enclosure of that cycle's gain over every
    // pattern within the boxes (interval_loop_gain.hpp), and why it is not a proof if not.
    std::optional<std::array<double, 2>> loop_gain_enclosure;
    std::string loop_gain_proof_note;
  };
  std::optional<InputPrecision> input_precision;
  // The precision the verdict assumed of the coordinates, whatever its source
  // (describe_input_precision): stated, an SVG's drawn points, the digits, or exact.
  std::string coordinate_precision;
  // Given-state model (sheets with holes).
  int holes_closed = 0;
  double reference_residual = 0.0;
  double sigma_kept = 0.0, sigma_dropped = 0.0;   // either side of the rank cut
  std::string interference_checked; // which interference tests the branches went through
  // A sheet of several pieces (faces joined across creases; pattern_components.hpp): each
  // piece checked on its own, in the order of Topology::components. The pieces move
  // independently, so the sheet folds when some piece folds (the others held flat) and its
  // DOF is the sum over the pieces that fold; the verdict above is the whole sheet's own
  // check, and check_foldability states in `reason` where the two disagree. Empty for one piece.
  struct PieceVerdict {
    int faces = 0, creases = 0, interior_vertices = 0;
    FoldabilityClass verdict = FoldabilityClass::kUndecided;
    bool is_proof = false;
    int dof = 0;
    std::string model_name, reason;
  };
  std::vector<PieceVerdict> pieces;
  double seconds = 0.0;

  bool foldable() const {
    return verdict == FoldabilityClass::kFoldable || verdict == FoldabilityClass::kFoldableWithinTolerance;
  }
  bool not_foldable() const {
    return verdict == FoldabilityClass::kNotFoldableProof || verdict == FoldabilityClass::kNotFoldableEvidence;
  }
};

FoldabilityReport check_foldability(const CreasePattern& pattern, const Topology& topology,
                                    const FoldabilityOptions& options = {});

// The model choice of check_foldability (steps 1-3 above), for callers that run the model
// themselves (trace_motion): the one place that picks a model. On the multiplier model it
// carries that model's verdict (computed to decide applicability; exact and cheap).
struct ModelChoice {
  FoldabilityModel model = FoldabilityModel::kNone;
  std::string why;
  int holes = 0;
  std::optional<FoldabilityVerdict> multiplier;  // kMultiplierPropagation only
  // A flat pattern whose degree-4 vertices miss Kawasaki only by the rounding of its
  // coordinates: the multiplier model runs on this witness (flat_foldable_witness.hpp), whose
  // edges and faces are the pattern's, and the verdict holds "within the input's precision".
  std::optional<FlatFoldableWitness> flat_witness;
};
ModelChoice choose_model(const CreasePattern& pattern, const Topology& topology, const FoldabilityOptions& options);

// Number of holes over the sheet's components (topology.components[*].holes).
int count_holes(const Topology& topology);

}  // namespace rigidfold
