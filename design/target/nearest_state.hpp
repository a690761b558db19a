#pragma once
// nearest_closed_state: the rigidly folded state of a pattern nearest to target fold angles
// (`rigidfold fold --target`; docs/cli/fold.md). A target exported by a compliant simulator
// (Origami Simulator's FOLD edges_foldAngle) or measured on a model does not close exactly:
// its faces do not meet. This finds the closed state nearest to it:
//     minimise |x - x_t|^2 over the free creases' angles x, subject to r(x) = 0
// (r: the loop-closure residual, kernel/closure/closure_system.hpp; held creases are constants
// at their target angle). Gauss-Newton SQP with minimum-norm steps: e = x - x_t goes to
// e' = J^+ (J e - r) (J may be rank-deficient: redundant closure rows, and the DOF), capped at
// max_step per crease. J^+ is applied exactly by a dense complete orthogonal decomposition up
// to 1,500 free creases; above, by CHOLMOD's regularised normal equations (MinimumNormSolver),
// whose rounding along J's null space (the manifold's tangent, where the SQP's steps go) is
// amplified by 1/lambda, so that large patterns may end unconverged. At the fixed point r = 0 and e lies in the row space of J (first-order
// optimality); `stationarity` is |e - J^+ J e| / |e|, the part of the move that could still be
// taken along the manifold. Converged: |r|_inf <= tolerance and the last step <= step_tolerance.
// A local minimum from the target: the nearest state on the target's side of the manifold.
// Units: radians; per-edge vectors indexed by edge.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct NearestStateOptions {
  std::vector<int> held_edges;    // creases kept at their target angle
  double tolerance = 1e-12;       // |r|_inf, radians
  double step_tolerance = 1e-12;  // |last step|_inf, radians
  double max_step = 0.5;          // |step|_inf cap, radians
  int max_iterations = 100;
};

struct NearestState {
  bool converged = false;
  std::string message;              // one line for the user
  Eigen::VectorXd target;           // per edge (radians)
  Eigen::VectorXd angles;           // per edge, the closed state (radians)
  double residual = 0.0;            // |r(angles)|_inf (radians)
  double target_residual = 0.0;     // |r(target)|_inf: how far the target is from closing
  double max_distance = 0.0;        // |angles - target|_inf over the creases (radians)
  double rms_distance = 0.0;        // over the free creases (radians)
  int worst_edge = -1;
  int free_creases = 0;
  int iterations = 0;
  double stationarity = 0.0;
  std::vector<int> held_edges;
  // The creases whose letter (M < 0, V > 0) the closed state folds the other way (|rho| > 1e-9).
  std::vector<int> against_letters;
};

// target: per-edge fold angles (radians), size pattern.num_edges(). Throws InputError when a
// held edge is not a foldable crease, or the pattern is outside the closure model (holes).
NearestState nearest_closed_state(const CreasePattern& pattern, const Topology& topology, const Eigen::VectorXd& target,
                                  const NearestStateOptions& options = {});

}  // namespace rigidfold
