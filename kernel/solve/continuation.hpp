#pragma once
// 1-DOF pseudo-arclength continuation along the constraint manifold r(x) = 0 of a
// ClosureSystem (DESIGN.md, "Continuation").
//
// At a point x_k the tangent t_k is the unit null vector of J(x_k), oriented to continue the
// previous tangent (the first one along `direction`): from jacobian_rank (which also checks
// DOF = 1) for up to 2000 unknowns, above that by inverse iteration on the corrector's
// factorisation (the DOF is then not re-checked at every point). Predictor
// x_p = x_k + h t_k; corrector: Newton on the augmented system
// [r(x); t_k . (x - x_k) - h] = 0, each step the exact solution of the augmented linear
// system built from the minimum-norm step and the null vector of J (MinimumNormSolver:
// CHOLMOD on J^T J + lambda I, one symbolic analysis for the whole trace). The step h grows
// by 1.5 after a corrector that converges in <= 3 iterations and is halved after a failure
// (not converged, or the DOF at the new point is not 1, or the tangent turned by more than
// 0.5 rad).
//
// Units: x, h (arclength in unknown space) and residuals in radians.
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

struct ContinuationOptions {
  double initial_step = 0.05;   // h at the start (radians of arclength)
  double min_step = 1e-8;       // give up below this
  double max_step = 0.25;
  int max_points = 10000;
  double tolerance = 1e-12;     // corrector stop, ||r||_inf (radians)
  int max_corrector_iterations = 10;
  double lambda_relative = 1e-14;
};

struct ContinuationPoint {
  Eigen::VectorXd x;            // unknowns (radians), on the manifold
  double residual = 0.0;        // ||r(x)||_inf reached by the corrector
  double step = 0.0;            // arclength step that produced this point (0 for the start)
  int corrector_iterations = 0;
};

struct ContinuationResult {
  std::vector<ContinuationPoint> points;  // the start (after projection) first
  bool stopped = false;                   // `stop` returned true at the last point
  std::string reason;                     // "stop", "max_points", "step too small", "start not on manifold", "not 1 DOF"
};

// Traces from x0 (projected onto the manifold first) in the direction of `direction`
// (size num_unknowns(); only its sign against the tangent matters) until stop(x) is true
// at an accepted point. The system must have 1 DOF along the path.
ContinuationResult continue_one_dof(const ClosureSystem& system, const Eigen::VectorXd& x0,
                                    const Eigen::VectorXd& direction,
                                    const std::function<bool(const Eigen::VectorXd&)>& stop,
                                    const ContinuationOptions& options = {});

}  // namespace rigidfold
