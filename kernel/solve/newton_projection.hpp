#pragma once
// Newton projection onto the constraint manifold r(x) = 0 of a ClosureSystem: minimum-norm
// Gauss-Newton steps on a redundant, rank-deficient system (DESIGN.md, "Corrector").
//
// Each step solves, with A = J_f J_f^T + lambda I (J_f: J with the held columns removed),
//       y = A^{-1} r,   dx = J_f^T y   (one extra refinement solve on the linear residual
//                                       r - J_f dx removes most of the lambda bias),
//       x <- x - dx.
// For lambda -> 0 dx is the minimum-norm solution of J_f dx = r, so the iteration moves
// x the least distance that closes the loops to first order, and it converges
// quadratically at regular points of the manifold.
// A is factorised with CHOLMOD (supernodal LLT). Its sparsity pattern does not change
// between steps, so the symbolic analysis is done once and each step only refactorises.
// J J^T is singular whenever rows are redundant (always, for a quad mesh), hence lambda > 0:
// lambda = lambda_relative * max diag(J J^T), multiplied by 100 and retried if the numeric
// factorisation still meets a non-positive pivot.
//
// Units: x and residuals in radians. Tolerance on ||r||_inf.
#include <Eigen/Core>
#include <vector>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

struct NewtonOptions {
  double tolerance = 1e-12;         // stop when ||r||_inf <= tolerance (radians)
  int max_iterations = 30;          // Newton steps at most
  double lambda_relative = 1e-14;   // regularisation, relative to max diag(J J^T)
  double max_step = 0.5;            // ||dx||_inf cap per step (radians); steps are scaled down to it
  std::vector<int> held_unknowns;   // indices of unknowns kept at their starting value
};

struct NewtonResult {
  Eigen::VectorXd x;                     // last iterate (radians)
  std::vector<double> residual_history;  // ||r||_inf at x0, x1, ..., x (radians)
  bool converged = false;                // ||r(x)||_inf <= tolerance
  int iterations = 0;                    // Newton steps taken
  int factorizations = 0;                // numeric factorisations (>= iterations; retries count)
  int symbolic_analyses = 0;             // 1 unless the pattern changed (it does not for a ClosureSystem)
  double lambda = 0.0;                   // regularisation used in the last step
};

// Projects x0 (size system.num_unknowns(), radians) onto r(x) = 0.
// Throws std::invalid_argument for a wrong size or a held index out of range.
// Never throws for non-convergence: check NewtonResult::converged and the history.
NewtonResult newton_project(const ClosureSystem& system, const Eigen::VectorXd& x0,
                            const NewtonOptions& options = {});

}  // namespace rigidfold
