#pragma once
// A simple branch point of a 1-DOF solution curve of the loop closure, solved as a regular
// (non-singular) system by Gauss-Newton, with a verified error bound (docs/DESIGN.md,
// "Bifurcation").
//
// Extended system. Unknowns z = (x, c): x the n fold-angle unknowns (radians), c in R^(n-1)
// the coordinates of a left null vector psi = U c of J(x) in a fixed orthonormal basis U
// (m x (n-1)): the range of J at a regular point of the branch near the branch point.
//   G(z) = [ r(x)          ]  m rows   closure (ClosureSystem::residual)
//          [ J(x)^T U c    ]  n rows   U c is a left null vector of J: the rank dropped
//          [ (c.c - 1) / 2 ]  1 row    normalisation
// Why U: along a 1-DOF branch J has rank n - 1 but may have more than n - 1 rows (the 12
// rows of a 12-crease Kokotsakis unit): their left null vectors exist all along the branch
// and are no singularity. Restricted to range(J(xa)), psi can only be the new one, which
// appears where the rank drops to n - 2.
// Regularity. At a simple branch point (rank J = n - 2, ker J = span(p1, p2), and the 2 x 2
// matrix B_ij = p_i^T H(psi) p_j nonsingular, H(w) = sum_k w_k Hess r_k: the two branches
// cross transversally) DG = [J 0; H(Uc) J^T U; 0 c^T] has full column rank 2n - 1:
// DG (dx, dc) = 0 forces dx in ker J, then p_i^T H dx = 0, so B (a, b) = 0 and dx = 0; then
// (U^T J)^T dc = 0 gives dc || c, and c.dc = 0 gives dc = 0. G(z*) = 0, so Gauss-Newton
// (least-squares steps, m + n + 1 rows >= 2n - 1 columns) converges quadratically.
//
// Error bound (Newton-Kantorovich on the square system Q^T G, Q an orthonormal basis of
// range DG(z); z* is a zero of it). At the final iterate z:
//   beta  = 1 / sigma_min(DG(z))
//   eta   = |DG(z)^+ G(z)|_2 + beta * noise   (the Gauss-Newton step plus what the rounding
//           noise of the computed G can hide; noise measured, see BranchPointSolve)
//   L     = Lipschitz constant of DG near z, estimated from central differences of DG along
//           every coordinate (sqrt of the sum of squared Frobenius norms bounds the
//           derivative's norm), times a safety factor 10
//   h = beta L eta <= 1/2  =>  a zero z* with |z - z*|_2 <= 2 eta / (1 + sqrt(1 - 2h)) <= 2 eta.
// The reported bound is 2 eta, on |x - x*|_2 (so on every fold angle). It is tested against
// an independent 50-digit solve (tests/solve/branch_point_test.cpp).
//
// Units: radians. Dense linear algebra (SVDs of (m + n + 1) x (2n - 1)): for the small
// patterns where bifurcations are analysed.
#include <Eigen/Core>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct BranchPointOptions {
  int max_iterations = 30;
  // Lipschitz safety factor on the central-difference estimate of DG's derivative.
  double lipschitz_safety = 10.0;
  // Step of those central differences (radians; c is a unit vector).
  double lipschitz_step = 1e-5;
};

struct BranchPointSolve {
  bool converged = false;           // the iteration reached its rounding floor and h <= 1/2
  Eigen::VectorXd x;                // the branch point (unknowns, radians)
  Eigen::VectorXd left_null;        // psi = U c, unit (m): J(x)^T psi ~ 0
  std::vector<double> residual_history;  // |G(z_k)|_2 at every iterate, z_0 the start
  std::vector<double> step_history;      // |z_{k+1} - z_k|_2, the Gauss-Newton steps taken
  int iterations = 0;
  double residual = 0.0;            // |r(x)|_inf, closure at the final x (radians)
  double sigma_min = 0.0;           // smallest singular value of DG at the final z (1 / beta)
  double step_norm = 0.0;           // |DG^+ G|_2 at the final z (the next step, not taken)
  double noise = 0.0;               // measured rounding noise of G: max over random probes of
                                    // |G(z + d) - G(z) - DG d|_2, |d| = 1e-12, times 4
  double lipschitz = 0.0;           // L above (safety factor included)
  double kantorovich_h = 0.0;       // beta L eta
  double error_bound = 0.0;         // 2 eta: bound on |x - x*|_2 (radians); +inf if not converged
};

// Inputs: the closure system and the topology it was built from; a start x0 near the branch
// point (radians); U (m x (n-1), orthonormal columns spanning the range of J at a regular
// point of the branch nearby). c_0 is the left singular vector of U^T J(x0) of its smallest
// singular value. Throws std::invalid_argument on size mismatches.
BranchPointSolve solve_branch_point(const ClosureSystem& system, const Topology& topology, const Eigen::VectorXd& x0,
                                    const Eigen::MatrixXd& U, const BranchPointOptions& options = {});

}  // namespace rigidfold
