#include "kernel/solve/stale_pcg.hpp"

#include <cmath>
#include <stdexcept>

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
  double s_last = c;
  Eigen::VectorXd g = J.transpose() * s + s_last * a;
  Eigen::VectorXd z = apply_preconditioner(factor, w_fac, a, aw, g);
  double gamma = g.dot(z);
  const double gamma0 = gamma;
  if (gamma0 == 0.0) {
    out.converged = true;  // b is orthogonal to range(A): dx = 0
    return out;
  }
  if (!(gamma0 > 0.0) || !std::isfinite(gamma0)) return out;
  const double target = options.relative_tolerance * options.relative_tolerance * gamma0;
  Eigen::VectorXd p = z, q;
  while (out.iterations < options.max_iterations) {
    q = J * p;
    const double q_last = a.dot(p);
    const double qq = q.squaredNorm() + q_last * q_last;
    if (!(qq > 0.0) || !std::isfinite(qq)) break;
    const double alpha = gamma / qq;
    out.dx += alpha * p;
    s -= alpha * q;
    s_last -= alpha * q_last;
    g = J.transpose() * s + s_last * a;
    z = apply_preconditioner(factor, w_fac, a, aw, g);
    const double gamma_new = g.dot(z);
    ++out.iterations;
    out.relative_residual = std::sqrt(std::max(gamma_new, 0.0) / gamma0);
    if (!std::isfinite(gamma_new)) break;
    if (gamma_new <= target) {
      out.converged = true;
      break;
    }
    if (!(gamma_new > 0.0)) break;  // M lost definiteness (rounding): give up, the caller refactorises
    p = z + (gamma_new / gamma) * p;
    gamma = gamma_new;
  }
  return out;
}

}  // namespace rigidfold
