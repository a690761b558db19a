#pragma once
// Rigid-foldability verdict by the general loop-closure solver (docs/DESIGN.md, "Foldability
// verdict"): works for any pattern without holes (any vertex degree, non-flat-foldable
// vertices), unlike the exact multiplier model (multiplier_propagation.hpp), which it is
// tested against where both apply.
//
// Method.
//  1. Search for a folded point near flat. For each of a few driving creases (creases shared
//     by two interior vertices first, spread over the pattern) and a few deterministic
//     pseudo-random starts x0 (|x0_i| in [start_min, start_max] radians, the sign of every
//     M/V crease following its assignment, U creases either sign), hold the driving crease
//     at +-held_value (the assigned sign; + for U) and Newton-project the rest
//     (newton_project, minimum-norm Gauss-Newton). A converged point (||r||_inf <=
//     tolerances.residual) is a CANDIDATE when no M/V crease has the wrong sign. Choice
//     made here: a crease that stays flat (|rho| <= tolerances.sign_threshold) does NOT
//     violate its letter; a crease of the wrong sign beyond it does.
//  2. DOF at the candidate: jacobian_rank of the full Jacobian (no crease held), cut at
//     tolerances.rank_cut.
//  3. Trace. A candidate that leaves some M/V creases flat (|rho| <= flat_fraction x its
//     largest fold; a weakly folded point) is first pushed off them: those creases are held
//     at 1e-2 (then 1e-3) x the largest fold on their letter's side and the rest is
//     Newton-projected; a point that closes with every M/V crease folded its own way is a
//     strict candidate, traced before the weak one. DOF 1: continue_one_dof
//     (pseudo-arclength) in the direction that increases the fold (tangent . x > 0).
//     DOF > 1: by the fold's size (norm_continuation.hpp: ||x||_2 stepped geometrically,
//     each point the least-distance projection of the scaled previous one), first toward flat
//     to 1/100 of the candidate's size (the points there must keep their letters), then out;
//     if that certifies nothing, by projected driving: the driving crease is stepped by
//     driven_step and the rest Newton-projected (minimum-norm) from the previous point.
//     The trace is watched by PathWatch (path_watch.hpp) and stops when
//       - some crease reaches +-tolerances.fold_limit() (~180 deg: local facet
//         interference), kFoldLimit;
//       - an M/V crease turns against its letter, kSignSwitch (the crossing is recorded);
//       - (DOF 1) the bordered determinant det[J_S; t^T] changes sign between consecutive
//         points (bordered_determinant.hpp: J_S the rows of J along the left singular
//         vectors of the earlier point, t the tangent oriented along the path): a candidate
//         bifurcation, kSingularPoint, located by linear interpolation between the two
//         points (not refined);
//       - continuation fails (kContinuationFailed with its reason), or max_path_points.
//     Every sign change of a crease (PathWatch's semantics: relative to its last sign) is
//     recorded in sign_switches with the driving crease's value at the crossing.
//  4. Verdict kRigidlyFoldable if the trace reaches max |rho| >= certificate_fold with
//     every M/V sign respected (by the fold's size: also back toward flat to 1/100 of the
//     candidate's size), and face placement (place_faces) of the last valid point has
//     relative mismatch <= tolerances.placement_mismatch. The certificate is that point.
//  5. No candidate: the evidence search. At each amplitude eps of evidence_amplitudes
//     (largest first) and each driving crease, sign-respecting least squares (projected
//     Gauss-Newton, NewtonOptions::sign_bounds: a valley stays >= 0, a mountain <= 0) from
//     the first start scaled to eps, the driving crease held at +-eps. A converged point is
//     a candidate (traced as in 3-4). Then, at the same amplitude, the norm search
//     (amplitude_search: ||x||_2 = eps over all unknowns, letters as bounds, no crease held)
//     from norm_search_starts starts; a converged point with its letters kept is a candidate
//     too. Both searches can stop just short of the tolerance at a point where no bound is
//     active, or with creases on their bound (Resch's triangle tessellation: 2.9e-11 rad at 0.1 rad after the norm search's
//     iterations); so the best point of the amplitude, when its residual is at most
//     polish_residual, is polished by Newton projection (minimum-norm steps, which move it
//     by about residual / sigma_min; the creases it left on their bound held flat, so the
//     polished point is then a weakly folded state), and it is a candidate when it converges
//     with its letters kept and at least half its size (eps / 2: on a rigid pattern Newton
//     may slide back to the flat state, which breaks no letter).
//     Otherwise the least residual per amplitude (both searches) is the evidence, and
//       - kNotRigidlyFoldable (numerical evidence, is_proof false) only when the least
//         residual at the largest amplitude is at least tolerances.evidence_floor AND it
//         grows with the amplitude like an obstruction, residual ~ eps^p with
//         p >= min_growth_exponent between the two largest amplitudes (a closure gap forced
//         by the geometry scales with the fold; a search that stalled does not) AND the
//         rounding of the file's coordinates does not explain the least residual at either
//         of those two amplitudes (rounding_residual_bound.hpp at the best state: a float32 file's 1e-6 rad
//         sector errors leave ~1e-8 x eps of closure gap, which also grows with eps);
//       - kUndecided otherwise: a least residual near the floor, or one that does not grow
//         with the fold, is a search that stopped, not evidence of rigidity.
//     The obstruction reported: the least residual (largest amplitude) and the interior
//     vertices with the largest residual blocks there; the starts that converged only
//     against the assignment, their count and a crease.
//     kUndecided also if candidates exist but no trace reached certificate_fold.
//
// Units: radians; fold angles per edge with the FOLD sign (valley > 0, mountain < 0).
// Limits: sheets with holes are rejected by ClosureSystem (std::runtime_error propagates);
//   bifurcation detection only for DOF 1 and num_unknowns <= singular_detection_limit
//   (dense determinants); singular points are located only to the path's step.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kernel/analysis/multiplier_propagation.hpp"  // Verdict
#include "kernel/analysis/progress.hpp"
#include "kernel/analysis/tolerances.hpp"
#include "kernel/analysis/traced_branch.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/continuation.hpp"

namespace rigidfold {

struct GeneralVerdictOptions {
  bool use_assignment = true;        // false: every crease may fold either way (letters ignored)
  Tolerances tolerances = kDefaultTolerances;  // residual, sign threshold, fold limit, placement mismatch, rank cut
  int max_driving_creases = 4;       // driving creases tried
  int starts_per_crease = 4;         // pseudo-random starts per driving crease
  std::uint64_t seed = 1;            // of the starts (own generator: same starts everywhere)
  double start_min = 0.05;           // |x0_i| range of the starts (radians)
  double start_max = 0.2;
  double held_value = 0.1;           // |driving crease| during the search (radians)
  double certificate_fold = 0.5235987755982988;  // 30 deg: max |rho| a certificate must reach
  int max_candidates_traced = 3;     // candidates traced before giving up (kUndecided)
  int max_path_points = 4000;
  double driven_step = 0.05;         // DOF > 1: step of the driving crease (radians)
  int least_squares_iterations = 60; // Gauss-Newton steps of the obstruction search
  int least_squares_stall_window = 5;  // ... ended early on a plateau (NewtonOptions::stall_window)
  int singular_detection_limit = 600;  // bordered-determinant test only up to this many unknowns
  // Evidence search (step 5): amplitudes (radians, largest first) and the least growth
  // exponent of the least residual between the two largest that counts as an obstruction.
  std::vector<double> evidence_amplitudes{0.1, 0.01, 0.001};
  double min_growth_exponent = 0.5;
  // ... and at each amplitude this many starts of the norm search (amplitude_search.hpp:
  // ||x||_2 = eps over all unknowns, letters as bounds), which finds motions that leave the
  // driving creases flat.
  int norm_search_starts = 2;
  int norm_search_iterations = 80;
  // ... and, when no amplitude gave a candidate, the norm search once more at the pattern's
  // own scale, ||x||_2 = scaled_norm_rms x sqrt(unknowns) (only where that exceeds the largest
  // amplitude), from this many starts, its lettered creases stepped in log|rho|
  // (AmplitudeSearchOptions::logarithmic); it adds candidates, never evidence. Near flat a
  // large pattern's motion is ill-conditioned (its Jacobian's second-smallest singular value
  // shrinks with the fold), so searches at 0.1 rad spread over hundreds of creases stall.
  // Run up to scaled_norm_max_unknowns unknowns (each start is up to 200 sparse LM steps:
  // ~0.6 s a start on 4,000 creases, 2-core VM).
  double scaled_norm_rms = 0.025;
  int scaled_norm_search_starts = 4;
  int scaled_norm_search_iterations = 200;
  int scaled_norm_max_unknowns = 1000;
  // ... and the best point of an amplitude, when its closure residual is at most this
  // (radians), is polished by Newton projection without bounds (header, step 5).
  double polish_residual = 1e-6;
  int polish_iterations = 20;
  // The user's bound on each coordinate (input_precision; nullopt: read off the digits),
  // for the rounding test of step 5.
  std::optional<double> coordinate_tolerance;
  // DOF-1 tracing: steps of at most 0.1 rad in any crease (a fixed arclength of 0.25 took
  // ~5,000 points, 23 s, on a 50 x 50 Miura); on small patterns this is about the old step.
  ContinuationOptions continuation = [] {
    ContinuationOptions c;
    c.max_angle_step = 0.1;
    return c;
  }();
  ProgressSink progress;  // each start of the search and of the evidence search, each traced point
};

// A candidate bifurcation on a DOF-1 trace (bordered determinant changed sign).
struct SingularPoint {
  Eigen::VectorXd angles;       // per-edge fold angles, linearly interpolated (radians)
  double driving_value = 0.0;   // driving crease's angle there (radians)
  double max_fold = 0.0;        // max |rho| there (radians)
};

// The norm search at the pattern's own scale (step 5): a source of candidates, never evidence.
struct ScaledNormSearch {
  double amplitude = 0.0;        // ||x||_2 sought (radians; 0: not run)
  int starts = 0;                // starts run
  double least_residual = -1.0;  // least ||r||_inf over them (radians; -1: not run)
};

// The least sign-respecting closure residual found at one fold amplitude (step 5).
struct AmplitudeEvidence {
  double amplitude = 0.0;       // |driving crease| held, and ||x||_2 of the norm search (radians)
  double least_residual = 0.0;  // least ||r||_inf over both searches at this amplitude (radians)
  int driving_edge = -1;        // where it was reached (-1: by the norm search)
  double norm_search_residual = -1.0;  // least ||r||_inf of the norm search alone (-1: not run)
  // The rounding of the file's coordinates can explain the least residual: at the best state
  // found, every vertex's gap is within what its sectors' rounding can cause there
  // (rounding_residual_bound.hpp).
  bool explained_by_rounding = false;
  double rounding_ratio = -1.0;  // max over vertices of gap / that bound (<= 1: explained)
  bool polished = false;         // the best point was polished by Newton projection (step 5)
  bool polish_converged = false; // ... and closed with its letters kept: a candidate
  std::string polish_outcome;    // what the polish ended with, in words (empty: not polished)
};

// Which lettered creases a certificate leaves flat: strict foldability folds every one of
// them; weak foldability lets some stay flat (|rho| <= flat_fraction x the largest fold).
struct StrictnessReport {
  bool strict = false;               // every M/V crease folds at the certificate
  std::vector<int> flat_lettered;    // M/V creases that stay flat there (edge indices)
  double flat_fraction = 1e-6;
  // Interior degree-4 vertices where two straight crease lines cross with all four creases
  // lettered: no motion from flat folds all four (straight_line_folds.hpp), a proof that the
  // pattern is not strictly foldable.
  std::vector<int> strict_obstruction_vertices;
};

struct GeneralVerdict {
  Verdict verdict = Verdict::kUndecided;
  const char* model = "general-loop-closure";
  std::string reason;           // one line for the user; says when a "no" is numerical evidence
  // A yes is certified by its traced path (true); a no is numerical evidence (false), except
  // for a pattern with no foldable crease (true).
  bool is_proof = false;
  int num_unknowns = 0;
  // Search.
  int starts_tried = 0, starts_converged = 0, starts_wrong_sign = 0;
  int wrong_sign_crease = -1;   // a crease of the wrong sign at a converged start (if any)
  // Candidate and trace: driving_edge, path, max_fold (over the valid part), max_residual,
  // stopped_by (kFoldLimit, kSignSwitch, kSingularPoint, kMaxPoints, kCorrectorFailed,
  // kContinuationFailed), stop_crease, sign_switches; dof_at_departure is the first-order DOF
  // at the candidate (jacobian_rank, tolerances.rank_cut).
  TracedBranch trace;
  // DOF > 1: how the trace was followed (empty for DOF 1): by the fold's size, with the
  // size it reached back toward flat (radians; -1: not traced that way), or by a driving crease.
  std::string trace_method;
  double traced_toward_flat_to = -1.0;
  std::vector<SingularPoint> singular_points;
  Eigen::VectorXd certificate_angles;  // last valid point of the path (kRigidlyFoldable)
  double certificate_mismatch = -1.0;  // place_faces relative mismatch there
  // Strict or weak (kRigidlyFoldable): the lettered creases the certificate leaves flat.
  StrictnessReport strictness;
  // Evidence search (step 5; empty when a candidate came from the first search).
  std::vector<AmplitudeEvidence> evidence;
  double growth_exponent = 0.0;        // of the least residual between the two largest amplitudes
  ScaledNormSearch scaled_norm_search;  // the search at the pattern's scale
  // Obstruction (kNotRigidlyFoldable, or kUndecided from the evidence search).
  double least_residual = -1.0;        // least ||r||_inf by Gauss-Newton with the driving crease held
  std::vector<std::pair<int, double>> worst_vertices;  // (pattern vertex, ||r_v||_2), largest first, at most 5
  double seconds = 0.0;
};

// The strict question on its own, in words: certified (strict), disproved (crossing lettered
// lines), or undecided (a weak certificate only).
const char* strict_verdict(const StrictnessReport& strictness);

// The strictness of a folded state rho (per-edge fold angles, radians): the M/V creases of
// the pattern (by letter, whether or not the verdict used the letters) that stay flat.
StrictnessReport strictness_at(const CreasePattern& pattern, const Eigen::VectorXd& rho);

// Inputs: a validated pattern and its topology (flat reference sheet, no holes).
// Throws std::runtime_error for a sheet with holes (from ClosureSystem).
GeneralVerdict general_verdict(const CreasePattern& pattern, const Topology& topology,
                               const GeneralVerdictOptions& options = {});

}  // namespace rigidfold
