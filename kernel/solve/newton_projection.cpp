#include "kernel/solve/newton_projection.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rigidfold {

namespace {

bool same_pattern(const Eigen::SparseMatrix<double>& A, const std::vector<int>& outer, const std::vector<int>& inner) {
  if (static_cast<std::size_t>(A.outerSize() + 1) != outer.size() ||
      static_cast<std::size_t>(A.nonZeros()) != inner.size())
    return false;
  return std::equal(outer.begin(), outer.end(), A.outerIndexPtr()) &&
         std::equal(inner.begin(), inner.end(), A.innerIndexPtr());
}

}  // namespace

NewtonResult newton_project(const ClosureSystem& system, const Eigen::VectorXd& x0, const NewtonOptions& options) {
  const int n = system.num_unknowns();
  const int m = system.num_rows();
  if (x0.size() != n)
    throw std::invalid_argument("newton_project: x0 has " + std::to_string(x0.size()) + " entries, expected " +
                                std::to_string(n));
  // Column selector: held unknowns get a zero column in J_f = J * S.
  Eigen::VectorXd keep = Eigen::VectorXd::Ones(n);
  for (int k : options.held_unknowns) {
    if (k < 0 || k >= n) throw std::invalid_argument("newton_project: held unknown " + std::to_string(k) + " out of range");
    keep[k] = 0.0;
  }

  NewtonResult result;
  result.x = x0;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(result.x, r, J);
  double rnorm = m > 0 ? r.lpNorm<Eigen::Infinity>() : 0.0;
  result.residual_history.push_back(rnorm);
  if (m == 0 || n == 0) {
    result.converged = rnorm <= options.tolerance;
    return result;
  }

  Eigen::SparseMatrix<double> identity(m, m);
  identity.setIdentity();
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.cholmod().print = 0;  // a failed (non-positive) pivot is handled here, not printed
  std::vector<int> outer, inner;

  while (rnorm > options.tolerance && result.iterations < options.max_iterations) {
    const Eigen::SparseMatrix<double> Jf = J * keep.asDiagonal();
    const Eigen::SparseMatrix<double> JJt = Jf * Jf.transpose();
    const double scale = std::max(1.0, JJt.diagonal().maxCoeff());
    double lambda = options.lambda_relative * scale;
    Eigen::SparseMatrix<double> A;
    for (int attempt = 0;; ++attempt) {
      A = JJt + lambda * identity;
      if (!same_pattern(A, outer, inner)) {
        llt.analyzePattern(A);
        ++result.symbolic_analyses;
        outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
        inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
      }
      llt.factorize(A);
      ++result.factorizations;
      if (llt.info() == Eigen::Success) break;
      if (attempt >= 12) {  // lambda grew by 1e24: give up, report what we have
        result.lambda = lambda;
        return result;
      }
      lambda *= 100.0;
    }
    result.lambda = lambda;
    Eigen::VectorXd dx = Jf.transpose() * llt.solve(r);
    // One refinement on the linear residual: the lambda-biased step becomes (nearly) the
    // minimum-norm solution, and the left-null part of r stays out of the step.
    const Eigen::VectorXd lin = r - Jf * dx;
    dx += Jf.transpose() * llt.solve(lin);
    const double step = dx.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(step)) return result;
    if (step > options.max_step) dx *= options.max_step / step;
    result.x -= dx;
    ++result.iterations;
    system.evaluate(result.x, r, J);
    rnorm = r.lpNorm<Eigen::Infinity>();
    result.residual_history.push_back(rnorm);
  }
  result.converged = rnorm <= options.tolerance;
  return result;
}

}  // namespace rigidfold
