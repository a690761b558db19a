#pragma once
// Rigid-foldability verdict by the general loop-closure solver (DESIGN.md, "Foldability
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
//     residual_tolerance) is a CANDIDATE when no M/V crease has the wrong sign. Choice made
//     here: a crease that stays flat (|rho| <= zero_tolerance) does NOT violate its letter;
//     a crease of the wrong sign beyond zero_tolerance does.
//  2. DOF at the candidate: jacobian_rank of the full Jacobian (no crease held).
//  3. Trace. DOF 1: continue_one_dof (pseudo-arclength) in the direction that increases the
//     fold (tangent . x > 0). DOF > 1: projected driving: the driving crease is stepped by
//     driven_step and the rest Newton-projected (minimum-norm) from the previous point.
//     The trace stops when
//       - some crease reaches +-fold_limit (~180 deg: local facet interference), "fold limit";
//       - an M/V crease turns against its letter, "sign switch" (the crossing is recorded);
//       - (DOF 1) the bordered determinant det[J_S; t^T] changes sign between consecutive
//         points (J_S: n-1 rows of J chosen afresh at the earlier point by column-pivoted QR
//         of J^T, t the tangent oriented along the path): a candidate bifurcation, "singular
//         point", located by linear interpolation between the two points (not refined);
//       - continuation fails ("step too small", "not 1 DOF"), or max_path_points.
//     Every sign change of a crease relative to the start (M/V switch, any letter) is
//     recorded in sign_switches with the driving crease's value at the crossing.
//  4. Verdict kRigidlyFoldable if the trace reaches max |rho| >= certificate_fold with
//     every M/V sign respected, and face placement (place_faces) of the last valid point has
//     relative mismatch <= mismatch_tolerance. The certificate is that point.
//     kNotRigidlyFoldable if no start produced a candidate. This "no" is NUMERICAL EVIDENCE
//     within the search (finitely many starts near flat), not a proof (unlike the
//     multiplier model's loop-gain obstruction). The obstruction reported: the least
//     residual ||r||_inf reached by Gauss-Newton least squares with the driving crease held
//     at +-held_value, and the interior vertices with the largest residual blocks there;
//     or, if starts converged but only against the assignment, the count and a crease.
//     kUndecided if candidates exist but no trace reached certificate_fold.
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
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/continuation.hpp"

namespace rigidfold {

struct GeneralVerdictOptions {
  bool use_assignment = true;        // false: every crease may fold either way (letters ignored)
  int max_driving_creases = 4;       // driving creases tried
  int starts_per_crease = 4;         // pseudo-random starts per driving crease
  std::uint64_t seed = 1;            // of the starts (own generator: same starts everywhere)
  double start_min = 0.05;           // |x0_i| range of the starts (radians)
  double start_max = 0.2;
  double held_value = 0.1;           // |driving crease| during the search (radians)
  double residual_tolerance = 1e-12; // ||r||_inf of a converged point (radians)
  double zero_tolerance = 1e-10;     // |rho| at most this counts as flat (never a wrong sign)
  double certificate_fold = 0.5235987755982988;  // 30 deg: max |rho| a certificate must reach
  double fold_limit = 3.1405926535897932;        // pi - 1e-3: a crease at +-180 deg stops the trace
  double mismatch_tolerance = 1e-10; // place_faces relative mismatch of the certificate
  int max_candidates_traced = 3;     // candidates traced before giving up (kUndecided)
  int max_path_points = 4000;
  double driven_step = 0.05;         // DOF > 1: step of the driving crease (radians)
  int least_squares_iterations = 60; // Gauss-Newton steps of the obstruction search
  int singular_detection_limit = 600;  // bordered-determinant test only up to this many unknowns
  ContinuationOptions continuation;  // DOF-1 tracing
};

// A crease changed sign along the trace (an M/V switch relative to the start).
struct SignSwitch {
  int crease = -1;
  double driving_value = 0.0;   // driving crease's fold angle at the crossing (interpolated, radians)
  bool against_assignment = false;  // the new sign contradicts the crease's M/V letter
};

// A candidate bifurcation on a DOF-1 trace (bordered determinant changed sign).
struct SingularPoint {
  Eigen::VectorXd angles;       // per-edge fold angles, linearly interpolated (radians)
  double driving_value = 0.0;   // driving crease's angle there (radians)
  double max_fold = 0.0;        // max |rho| there (radians)
};

struct GeneralVerdict {
  Verdict verdict = Verdict::kUndecided;
  const char* model = "general-loop-closure";
  std::string reason;           // one line for the user; says when a "no" is numerical evidence
  bool is_proof = false;        // never true for kNotRigidlyFoldable (numerical evidence only)
  int num_unknowns = 0;
  // Search.
  int starts_tried = 0, starts_converged = 0, starts_wrong_sign = 0;
  int wrong_sign_crease = -1;   // a crease of the wrong sign at a converged start (if any)
  // Candidate and trace.
  int driving_crease = -1;      // edge held / stepped
  int dof = -1;                 // first-order DOF at the candidate (jacobian_rank)
  std::vector<Eigen::VectorXd> path;  // per-edge fold angles at every accepted trace point (radians)
  double max_fold = 0.0;        // max |rho| over the valid part of the path (radians)
  double max_residual = 0.0;    // max ||r||_inf over the path (radians)
  std::string stopped_by;       // "fold limit", "sign switch", "singular point", "step too small", ...
  int stop_crease = -1;         // fold limit / sign switch: the crease
  std::vector<SignSwitch> sign_switches;
  std::vector<SingularPoint> singular_points;
  Eigen::VectorXd certificate_angles;  // last valid point of the path (kRigidlyFoldable)
  double certificate_mismatch = -1.0;  // place_faces relative mismatch there
  // Obstruction (kNotRigidlyFoldable).
  double least_residual = -1.0;        // least ||r||_inf by Gauss-Newton with the driving crease held
  std::vector<std::pair<int, double>> worst_vertices;  // (pattern vertex, ||r_v||_2), largest first, at most 5
  double seconds = 0.0;
};

// Inputs: a validated pattern and its topology (flat reference sheet, no holes).
// Throws std::runtime_error for a sheet with holes (from ClosureSystem).
GeneralVerdict general_verdict(const CreasePattern& pattern, const Topology& topology,
                               const GeneralVerdictOptions& options = {});

}  // namespace rigidfold
