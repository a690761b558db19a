#pragma once
// PathWatch: the one watcher of a traced path's fold angles, point by point. Every tracer
// (general verdict, branch explorer, given-state mobility, trace_motion) feeds it its
// accepted points in order and reads back what happened on the segment from the previous
// point: sign switches, creases now against their letters, the first crease to pass the
// fold limit, creases reaching 180 deg.
//
// Semantics (chosen once for all tracers):
//   - a crease has a sign only while |rho| > sign_threshold; a SIGN SWITCH is a crease whose
//     sign differs from its last sign (so a crease that returns to its letter switches
//     again); its driving value is interpolated linearly where the crease crosses 0;
//   - with letters_from_start, an M/V crease's last sign starts as its letter's, so a crease
//     first seen against its letter is a switch at once (trace_motion's events); otherwise
//     a crease's sign starts at its first non-flat value;
//   - with skip_first_segment, the first segment (from a singular point such as the flat
//     state or a bifurcation, where near-zero creases have no meaningful sign) records no
//     switch: signs start at the second point;
//   - AGAINST its letter: an M/V crease with letter sign s and s * rho < -sign_threshold;
//   - FOLD LIMIT: the first crease (linearly, in |rho|) to pass pi - fold_limit_margin on
//     the segment, with the fraction of the segment where it does;
//   - AT 180 DEG: |rho| >= pi - at_fold_limit, reported once per crease.
// Units: radians.
#include <Eigen/Core>
#include <vector>

#include "kernel/analysis/tolerances.hpp"
#include "kernel/analysis/traced_branch.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// The smallest crease index whose fold angle is against its letter sign (letter_signs[e] *
// rho[e] < -sign_threshold; letter 0 never is), or -1. The one letter test of every tracer and
// of the general verdict's search.
int first_crease_against_letter(const std::vector<int>& letter_signs, const Eigen::VectorXd& rho,
                                double sign_threshold);

struct PathWatchOptions {
  Tolerances tolerances = kDefaultTolerances;
  bool letters_from_start = false;
  bool skip_first_segment = false;
};

class PathWatch {
 public:
  // What the segment ending at the observed point did.
  struct Segment {
    std::vector<SignSwitch> switches;
    int first_against_letter = -1;  // smallest crease index now against its letter, or -1
    int fold_limit_crease = -1;     // first crease past the fold limit on the segment, or -1
    double fold_limit_fraction = 1.0;  // where on the segment it passes (0 previous point, 1 this one)
    std::vector<int> reached_180;   // creases at 180 deg for the first time
  };

  // letters: the pattern's letters (assigned_fold_sign); only edges with movable[e] are
  // watched (empty: every edge). driving_edge names the driving values of switches.
  PathWatch(const CreasePattern& pattern, int driving_edge, const PathWatchOptions& options = {},
            std::vector<bool> movable = {});

  Segment observe(const Eigen::VectorXd& rho);
  int points() const { return points_; }

  // Records the segment's first crease against its letter on the branch (signs_match_assignment,
  // first_wrong_crease), once.
  static void mark_letters(const Segment& segment, TracedBranch& branch);

 private:
  std::vector<int> letter_;
  std::vector<bool> movable_;
  int driving_edge_;
  PathWatchOptions options_;
  std::vector<int> last_sign_;
  std::vector<bool> at_180_;
  Eigen::VectorXd previous_;
  int points_ = 0;
};

}  // namespace rigidfold
