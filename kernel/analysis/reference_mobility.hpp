#pragma once
// Mobility of a sheet from its own (3D) reference state: the verdict for sheets that are not
// disks (tubes, frames: docs/DESIGN.md, "one SE(3) closure per hole"), whose given state is the
// only known configuration (a bonded tube has no flat development).
//
// Method.
//  1. Closure system with the SE(3) hole rows (ClosureOptions::close_holes); its zero is the
//     reference state x0 = reference_fold_angles. DOF = n - rank J(x0) (jacobian_rank, cut
//     stated in RankResult). DOF 0 is a proof of rigidity (first-order rigid => rigid).
//  2. DOF 1: pseudo-arclength continuation (continue_one_dof) from x0 both ways.
//     DOF > 1: projected driving, both ways: the crease with the largest component in the
//     first null vector is stepped by `driven_step` and the rest Newton-projected
//     (minimum-norm) from the previous point.
//     The branch is watched by PathWatch (path_watch.hpp). It stops at a fold limit (some
//     crease reaching +-fold_limit(): local interference; the end point is then solved with
//     the first crease to cross held at +-pi, solve_fold_limit_end),
//     at a sign switch against a letter (when use_assignment), when faces cross (global
//     interference, facet_interference.hpp, checked at every point), when the path returns
//     to x0 (a closed loop of motion), when continuation fails, or at max_points.
//  3. Verdict: rigidly foldable when DOF >= 1 and a branch moves its driving crease by at
//     least min_motion within its valid points (every letter kept, if used, from the given
//     state on; no face crossing; no fold past the limit); not foldable when DOF = 0;
//     otherwise undecided.
//
// Units: radians; fold angles per edge, FOLD sign (valley > 0).
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "kernel/analysis/multiplier_propagation.hpp"  // Verdict
#include "kernel/analysis/tolerances.hpp"
#include "kernel/analysis/traced_branch.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct ReferenceMobilityOptions {
  bool use_assignment = true;
  // fold_limit() ends a branch (the end is then solved at +-pi), residual (corrector stop),
  // sign_threshold, rank_cut (DOF at the given state).
  Tolerances tolerances = kDefaultTolerances;
  double min_motion = 0.1;                       // radians of driving crease for a "yes"
  double max_step = 0.05;                        // continuation arclength step cap (radians)
  double driven_step = 0.02;                     // DOF > 1: driving crease step (radians)
  int max_points = 4000;                         // per branch
};

struct ReferenceMobility {
  Verdict verdict = Verdict::kUndecided;
  int dof = 0;                     // at the reference state
  std::string dof_method;          // RankResult::method that counted it
  int holes = 0;                   // SE(3) hole closures used
  double reference_residual = 0;   // ||r(x0)||_inf
  double sigma_kept = 0, sigma_dropped = 0;  // singular values either side of the rank cut
  // sense +-1; valid_points: leading points that are a valid motion (every letter kept,
  // when used, from the given state on; no face crossing; no fold past the limit).
  std::vector<TracedBranch> branches;
  double max_residual = 0;
  std::string reason;
  double seconds = 0;
};

// Inputs: a validated pattern and its topology (any sheet; holes are closed).
// Throws std::runtime_error for a handle (genus > 0), as ClosureSystem does.
ReferenceMobility reference_mobility(const CreasePattern& pattern, const Topology& topology,
                                     const ReferenceMobilityOptions& options = {});

}  // namespace rigidfold
