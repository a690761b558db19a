#include "kernel/solve/stale_pcg.hpp"

#include <cmath>
#include <stdexcept>

#include "kernel/solve/preconditioned_cgls.hpp"

namespace rigidfold {

namespace {

// y = M v, M = (J_o^T J_o + a a^T)^-1 through the factor of G_o and its null vector w_o
// (stale_pcg.hpp). aw = a . w_o, nonzero.
Eigen::VectorXd apply_preconditioner(const MinimumNormSolver& factor, const Eigen::VectorXd& w_o,
                                     const Eigen::VectorXd& a, double aw, const Eigen::VectorXd& v) {
  const double mu = w_o.dot(v) / aw;  // = a . y
  Eigen::VectorXd u = v - mu * a;
  u -= w_o.dot(u) * w_o;  // 0 up to rounding; exactly off w_o before the 1/lambda amplification
  Eigen::VectorXd y = factor.inverse_times(u).col(0);
  y -= w_o.dot(y) * w_o;
  y += ((mu - a.dot(y)) / aw) * w_o;
  return y;
}

}  // namespace

StalePcgResult stale_pcg_step(const MinimumNormSolver& factor, const Eigen::VectorXd& w_fac,
                              const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r,
                              const Eigen::VectorXd& a, double c, const StalePcgOptions& options) {
  const int n = static_cast<int>(J.cols());
  if (factor.unknowns() != n || factor.kept_unknowns() != n)
    throw std::invalid_argument("stale_pcg_step: the factor needs the Jacobian's columns and no held unknowns");
  if (w_fac.size() != n || a.size() != n || r.size() != J.rows())
    throw std::invalid_argument("stale_pcg_step: w_fac and a need one entry per unknown, r one per row of J");
  StalePcgResult out;
  out.dx = Eigen::VectorXd::Zero(n);
  const double aw = a.dot(w_fac);
  if (!(std::abs(aw) >= 1e-8 * a.lpNorm<Eigen::Infinity>())) return out;  // M unusable: the caller refactorises
  // CGLS on A = [J; a^T], b = [r; c]; s = b - A dx split as (s_rows, s_last).
  Eigen::VectorXd s = r;
  double s_last = c, q_last = 0.0;  // q_last: the constraint row of the last A p
  CglsResult cg = preconditioned_cgls(
      n, [&](Eigen::VectorXd& g) { g = J.transpose() * s + s_last * a; },
      [&](const Eigen::VectorXd& p, Eigen::VectorXd& q) {
        q = J * p;
        q_last = a.dot(p);
        return q.squaredNorm() + q_last * q_last;
      },
      [&](double alpha, const Eigen::VectorXd& q) {
        s -= alpha * q;
        s_last -= alpha * q_last;
      },
      [&](const Eigen::VectorXd& g, Eigen::VectorXd& y) { y = apply_preconditioner(factor, w_fac, a, aw, g); },
      options.relative_tolerance, options.max_iterations);
  out.dx = std::move(cg.x);
  out.iterations = cg.iterations;
  out.converged = cg.converged;
  out.relative_residual = cg.relative_residual;
  return out;
}

}  // namespace rigidfold
