#pragma once
// The augmented Newton step of the continuation corrector by a Krylov solve preconditioned
// with a stale factorisation (an iterative path for large systems).
//
// Problem: the step dx of the corrector's augmented linear system
//       A dx = b,   A = [J; a^T]  ((m + 1) x n, full column rank at a regular 1-DOF point),
//       b = [r; c]
// in the least-squares sense (J has redundant rows; r is in range(J) only to first order).
// MinimumNormSolver gets it from a fresh factorisation of G = J^T J + lambda I at every
// Newton iteration (dx = J^+ r + beta w). Here it is solved by CGLS (CG on the normal
// equations A^T A dx = A^T b, with the residual s = b - A dx carried explicitly, which keeps
// the recurrences in A rather than in A^T A) preconditioned by M = (J_o^T J_o + a a^T)^-1,
// where J_o is the Jacobian of an earlier factorisation (the stale factor held by a
// MinimumNormSolver) and w_o its unit null vector. M is applied exactly through that
// factor: for v, with mu = (w_o . v) / (a . w_o),
//       y_perp = Q G_o^-1 Q (v - mu a)    (Q = I - w_o w_o^T: G_o^-1 restricted to w_o's complement)
//       y      = y_perp + ((mu - a . y_perp) / (a . w_o)) w_o
// which solves (J_o^T J_o + a a^T) y = v; one pair of triangular solves per application.
// G_o itself cannot serve: its eigenvalue lambda along w_o (lambda ~ 1e-14) would turn any
// component of a vector along w_o into a 1e14-fold outlier of the preconditioned spectrum.
// With a factor from a nearby point M A^T A is close to the identity, and the soft
// (long-wavelength) modes that make the stationary chord iteration stall are exactly the
// ones M takes care of: a few CG iterations reach what one fresh factorisation would.
//
// Stopping criterion: sqrt(g . M g) <= relative_tolerance * sqrt(g0 . M g0), g = A^T s the
// normal-equation residual (g0 = A^T b). With M ~ (A^T A)^-1, sqrt(g . M g) is about
// ||A e|| (e: the error of dx), i.e. the part of the next nonlinear residual that the
// linear solve leaves, relative to the current one. The corrector passes
// relative_tolerance ~ ||r||_inf (Eisenstat-Walker's forcing term proportional to the
// residual), so Newton keeps its quadratic convergence; its last step is as exact as the
// direct one's (the residual after it is far below the 1e-12 tolerance).
// Not converged within max_iterations (a preconditioner from too far away, or a |a . w_o|
// too small to use): `converged` is false and the caller refactorises (the fresh factor is
// then the next preconditioner).
//
// Units: dx and r in radians (those of the ClosureSystem); a is dimensionless.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {

struct StalePcgOptions {
  double relative_tolerance = 1e-10;  // on sqrt(g . M g) against its start value (see above)
  int max_iterations = 8;             // CG iterations at most; above this the caller refactorises
};

struct StalePcgResult {
  Eigen::VectorXd dx;               // the step (radians); 0 if nothing was done
  int iterations = 0;               // CG iterations (one preconditioner application each)
  bool converged = false;           // the stopping criterion was met
  double relative_residual = 0.0;   // sqrt(g . M g / g0 . M g0) at the end
};

// Least-squares solution of [J; a^T] dx = [r; c] by CGLS preconditioned with `factor`'s
// (stale) factorisation of G_o = J_o^T J_o + lambda I and w_fac, the unit null vector of
// J_o. `factor` must have no held unknowns and a successful factorize; J must have its
// pattern. Throws std::invalid_argument for wrong sizes or a factor with held unknowns.
StalePcgResult stale_pcg_step(const MinimumNormSolver& factor, const Eigen::VectorXd& w_fac,
                              const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r,
                              const Eigen::VectorXd& a, double c, const StalePcgOptions& options = {});

}  // namespace rigidfold
