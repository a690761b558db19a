#pragma once
// trace_motion: the folding motion of a pattern, sampled at steps, with every fold angle,
// the closure residual, the face placement and events per step. `rigidfold trace` calls it;
// the model is the one check_foldability picks (choose_model).
//
// Models:
//   - multiplier propagation, foldable: the fold family tan(rho_e/2) = m_e * t_c, one
//     branch per family component c (exact), at steps equally spaced in the driving crease;
//   - the general loop-closure solver (multiplier model not applicable or undecided, or
//     force_general): a start by Newton projection from a small fold of the driving crease
//     (held; the initial guess folds every M/V crease a little its letter's way so the
//     projection lands on the branch the letters select), the first-order DOF there (must be
//     1), pseudo-arclength continuation to the target or to the fold limit (the end then
//     solved with the crossing crease held at +-pi, solve_fold_limit_end), then a Newton
//     projection with the drive held at every step. One branch, id 0.
//     With a branch request (`branch` or `all_branches`): the branch explorer's branches
//     (branch_explorer.hpp), each at its continuation points; drive/to/steps do not apply.
//   - a sheet with holes: the two branches through the given 3D state (reference_mobility,
//     via check_foldability); the given state is the first step; drive/to/steps do not apply.
//   - multiplier model, not foldable: nothing to trace; `note` says why.
// Events per step (PathWatch, letters seeded from the letters so that a crease that starts
// against its letter is an event at step 1): kAt180 (a crease reaches +-180 deg), kMvSwitch
// (an M/V crease changes sign: against its letter, or back to it), kSignChange (a crease
// without a letter changes sign).
//
// Units: radians; TraceRequest::to is the driving crease's final fold angle (radians).
// Throws InputError with place "drive", "branch" or "to" for a request that does not fit the
// pattern (the CLI adds its "--"); std::runtime_error never (a solver that cannot run leaves
// the branch untraced with its message).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/tolerances.hpp"
#include "kernel/analysis/traced_branch.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/continuation.hpp"

namespace rigidfold {

struct TraceRequest {
  bool use_assignment = true;
  bool force_general = false;
  std::optional<int> branch;     // one branch id
  bool all_branches = false;     // every branch
  std::optional<int> drive;      // driving crease (edge index); default per model
  std::optional<double> to;      // final fold of the driving crease (radians, |to| <= pi, not 0);
                                 // default 170 deg in its letter's direction (valley for U)
  int steps = 50;                // equally spaced driving angles (flat excluded)
  Tolerances tolerances = kDefaultTolerances;
  // How far each coordinate may lie from the true one (FoldabilityOptions::coordinate_tolerance;
  // `trace --tolerance`); nullopt: read off the input.
  std::optional<double> coordinate_tolerance;
  ProgressSink progress;         // each continuation point and output step (progress.hpp)
};

struct MotionEvent {
  enum class Kind { kAt180, kMvSwitch, kSignChange };
  int step = 0;                  // 1-based
  Kind kind = Kind::kAt180;
  int edge = -1;
  double drive = 0.0, angle = 0.0;  // radians
};
const char* to_string(MotionEvent::Kind k);  // "interference", "mv_switch", "sign_change"

struct MotionStep {
  double drive = 0.0;            // driving crease's fold angle (radians)
  Eigen::VectorXd rho;           // per edge (radians)
  double residual = 0.0;         // max vertex closure residual |log R_v| (radians)
  FoldedGeometry folded;         // faces placed (spanning tree) and their closure mismatch
  std::vector<MotionEvent> events;
};

struct MotionBranch {
  int id = 0;
  int drive = -1;
  double to = 0.0;               // requested final drive (radians)
  double reached = 0.0;          // final drive actually traced (radians)
  bool traced = false;
  int dof = -1;                  // DOF at the start (-1 unknown)
  StopReason stop = StopReason::kNone;
  std::string stopped_by;        // why the trace ends where it does, for the user
  std::string message;           // why not traced, or a warning
  std::vector<MotionStep> steps;
  // The multiplier model's exact path, tan(rho_e / 2) = tan_half_ratio[e] * tan(rho_drive / 2)
  // for every edge (0: stays flat), so that a caller who analyses the path between the steps
  // (SORCE's profiles) need not interpolate them; empty for every other model.
  std::vector<double> tan_half_ratio;
  std::vector<MotionEvent> events;
  double max_residual = 0.0, max_mismatch = 0.0;
  // The general solver's continuation: its corrector's linear solver
  // (ContinuationResult::linear_solver), its work and its points; empty and zero when the
  // branch was not continued by it (multiplier model, closed forms, not traced).
  std::string linear_solver;
  ContinuationStats continuation;
  std::size_t continuation_points = 0;
};

struct MotionTrace {
  FoldabilityModel model = FoldabilityModel::kNone;
  std::string model_name;
  std::string note;
  std::string coordinate_precision;  // what the model choice assumed of the coordinates (describe_input_precision)
  std::vector<MotionBranch> branches;
};

MotionTrace trace_motion(const CreasePattern& pattern, const Topology& topology, const TraceRequest& request);

}  // namespace rigidfold
