#pragma once
// One traced folding branch, the type every tracer returns (branch explorer, given-state
// mobility, the general verdict's certificate, the multiplier family, trace_motion), and the
// words a branch is described with: why it stopped, what kind of point it joins, where a
// crease changed sign.
//
// Units: radians; fold angles per edge with the FOLD sign (valley > 0, mountain < 0).
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace rigidfold {

// Why a traced branch ends. to_string gives the words the JSON has always used.
enum class StopReason {
  kNone,                // not traced
  kTargetReached,       // the driving crease reached the requested angle
  kFoldLimit,           // a crease reached +-180 deg (local facet interference, or fully folded)
  kSignSwitch,          // an M/V crease turned against its letter
  kGlobalInterference,  // two faces cross (FCL)
  kSingularPoint,       // the bordered determinant changed sign (a bifurcation, not located)
  kBifurcation,         // a located bifurcation
  kBifurcationNotLocated,
  kKnownPoint,          // returned to a point already found
  kClosedLoop,          // returned to the given state (a closed loop of motion)
  kTurningPoint,        // the driving crease turns back (choose another driving crease)
  kDepartureFailed,     // could not leave a singular point along a tangent line
  kCorrectorFailed,     // a Newton projection did not converge
  kContinuationFailed,  // continue_one_dof stopped (its reason is in the message)
  kMaxPoints,           // the point budget ran out
};
const char* to_string(StopReason r);

// The kind of a point where branches meet (branch explorer).
enum class PointKind { kFlat, kBifurcation, kFullyFolded, kInterference };
const char* to_string(PointKind k);

// A crease changed sign along a branch (relative to its last sign beyond the sign threshold).
struct SignSwitch {
  int crease = -1;
  double driving_value = 0.0;       // driving crease's fold angle at the crossing (interpolated, radians)
  bool against_assignment = false;  // the new sign contradicts the crease's M/V letter
};

struct TracedBranch {
  int id = 0;
  int from_point = -1, to_point = -1;  // branch explorer: indices of its points (-1: open end / given state)
  int sense = 0;                       // given-state branches: +1 / -1, the two ways out
  int dof_at_departure = -1;           // first-order DOF where it starts (1 for a traced 1-DOF branch)
  std::string dof_method;              // how it was counted (RankResult::method), empty if not counted
  int driving_edge = -1;               // the crease whose fold angle parameterises the branch
  double driving_begin = 0.0, driving_end = 0.0;  // its fold angle at the ends (radians)
  std::vector<Eigen::VectorXd> path;   // per-edge fold angles at every accepted point (radians)
  double max_residual = 0.0;           // largest ||r||_inf along the path (radians)
  double max_fold = 0.0;               // largest |rho| along the path (radians)
  StopReason stopped_by = StopReason::kNone;
  std::string stop_message;            // the tracer's detail (e.g. continuation's reason), may be empty
  int stop_crease = -1;                // fold limit / sign switch: the crease
  bool signs_match_assignment = true;  // every M/V crease agrees with its letter (or is flat) all along
  int first_wrong_crease = -1;
  std::vector<SignSwitch> sign_switches;
  // Global facet interference: first path index where faces cross (-1: never), the driving
  // crease's angle there, one crossing face pair.
  int global_interference_index = -1;
  double global_interference_driving = 0.0;
  std::pair<int, int> global_interference_faces{-1, -1};
  // Leading points of `path` that are a valid motion (letters kept where they count, no face
  // crossing, no fold past 180 deg). -1: not computed by this tracer.
  int valid_points = -1;
  // The tracer's linear algebra, in words (e.g. ContinuationResult::linear_solver), and its
  // numeric factorisations; empty and -1 when the tracer does not say.
  std::string linear_solver;
  int factorizations = -1;

  // "fold limit", or "fold limit (detail)" when the tracer left a message.
  std::string stop_text() const;
};

}  // namespace rigidfold
