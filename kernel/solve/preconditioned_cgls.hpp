#pragma once
// Preconditioned CGLS: CG on the normal equations A^T A x = A^T b with the residual
// s = b - A x carried explicitly (the recurrences stay in A rather than in A^T A), one shared
// loop for the corrector's stale-factor solves (MinimumNormSolver::solve_with_stale_factor,
// stale_pcg_step). The caller owns s and A and passes them as operations:
//   normal_residual(g)       g = A^T s (current s)
//   apply(p, q) -> ||q||^2   q = A p (the caller may keep more of A p, e.g. extra rows)
//   update_residual(alpha, q)  s -= alpha q, q from the apply just before
//   precondition(g, y)       y = M g, M symmetric positive definite (~ (A^T A)^-1)
// Stops when g . M g <= relative_tolerance^2 * g0 . M g0 (converged), after max_iterations,
// or when a curvature or g . M g is not finite and positive (rounding; not converged).
// x: size n, from 0; it holds the iterate reached even when not converged.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace rigidfold {

struct CglsResult {
  Eigen::VectorXd x;
  int iterations = 0;              // one apply and one precondition each
  bool converged = false;
  double relative_residual = 0.0;  // sqrt(g . M g / g0 . M g0) at the end
};

template <class NormalResidual, class Apply, class UpdateResidual, class Precondition>
CglsResult preconditioned_cgls(int n, NormalResidual&& normal_residual, Apply&& apply, UpdateResidual&& update_residual,
                               Precondition&& precondition, double relative_tolerance, int max_iterations) {
  CglsResult out;
  out.x = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd g, y, p, q;
  normal_residual(g);
  precondition(g, y);
  double gamma = g.dot(y);
  const double gamma0 = gamma;
  if (gamma0 == 0.0) {
    out.converged = true;  // b is orthogonal to range(A): x = 0
    return out;
  }
  if (!(gamma0 > 0.0) || !std::isfinite(gamma0)) return out;
  const double target = relative_tolerance * relative_tolerance * gamma0;
  p = y;
  while (out.iterations < max_iterations) {
    const double qq = apply(p, q);
    if (!(qq > 0.0) || !std::isfinite(qq)) break;
    const double alpha = gamma / qq;
    out.x += alpha * p;
    update_residual(alpha, q);
    normal_residual(g);
    precondition(g, y);
    const double gamma_new = g.dot(y);
    ++out.iterations;
    out.relative_residual = std::sqrt(std::max(gamma_new, 0.0) / gamma0);
    if (!std::isfinite(gamma_new)) break;
    if (gamma_new <= target) {
      out.converged = true;
      break;
    }
    if (!(gamma_new > 0.0)) break;  // M lost definiteness in rounding
    p = y + (gamma_new / gamma) * p;
    gamma = gamma_new;
  }
  return out;
}

}  // namespace rigidfold
