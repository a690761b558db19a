#include "kernel/solve/continuation.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {

namespace {

// Unit tangent at x (null vector of J), or an empty vector if the DOF is not 1.
Eigen::VectorXd tangent_at(const ClosureSystem& system, const Eigen::VectorXd& x) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(x, r, J);
  const RankResult rk = jacobian_rank(J);
  if (rk.dof != 1 || rk.null_space.cols() != 1) return {};
  return rk.null_space.col(0);
}

struct Corrected {
  Eigen::VectorXd x;
  double residual = 0.0;
  int iterations = 0;
  bool converged = false;
};

// Gauss-Newton on [r(x); t.(x - xk) - h] = 0 from xp.
Corrected correct(const ClosureSystem& system, const Eigen::VectorXd& xk, const Eigen::VectorXd& t, double h,
                  const Eigen::VectorXd& xp, const ContinuationOptions& options) {
  const int m = system.num_rows(), n = system.num_unknowns();
  Corrected c;
  c.x = xp;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  Eigen::SparseMatrix<double> identity(m + 1, m + 1);
  identity.setIdentity();
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.cholmod().print = 0;
  bool analysed = false;
  for (;;) {
    system.evaluate(c.x, r, J);
    Eigen::VectorXd ra(m + 1);
    ra.head(m) = r;
    ra[m] = t.dot(c.x - xk) - h;
    c.residual = ra.lpNorm<Eigen::Infinity>();
    if (c.residual <= options.tolerance) {
      c.converged = true;
      return c;
    }
    if (c.iterations >= options.max_corrector_iterations || !std::isfinite(c.residual)) return c;
    // Augmented Jacobian: J with the row t^T appended.
    std::vector<Eigen::Triplet<double>> trip;
    trip.reserve(J.nonZeros() + n);
    for (int col = 0; col < J.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(J, col); it; ++it) trip.emplace_back(it.row(), col, it.value());
    for (int k = 0; k < n; ++k) trip.emplace_back(m, k, t[k]);
    Eigen::SparseMatrix<double> A(m + 1, n);
    A.setFromTriplets(trip.begin(), trip.end());
    const Eigen::SparseMatrix<double> AAt = A * A.transpose();
    double lambda = options.lambda_relative * std::max(1.0, AAt.diagonal().maxCoeff());
    Eigen::SparseMatrix<double> M;
    for (int attempt = 0;; ++attempt) {
      M = AAt + lambda * identity;
      if (!analysed) llt.analyzePattern(M), analysed = true;
      llt.factorize(M);
      if (llt.info() == Eigen::Success) break;
      if (attempt >= 12) return c;
      lambda *= 100.0;
    }
    Eigen::VectorXd dx = A.transpose() * llt.solve(ra);
    dx += A.transpose() * llt.solve(Eigen::VectorXd(ra - A * dx));
    c.x -= dx;
    ++c.iterations;
  }
}

}  // namespace

ContinuationResult continue_one_dof(const ClosureSystem& system, const Eigen::VectorXd& x0,
                                    const Eigen::VectorXd& direction,
                                    const std::function<bool(const Eigen::VectorXd&)>& stop,
                                    const ContinuationOptions& options) {
  if (x0.size() != system.num_unknowns() || direction.size() != system.num_unknowns())
    throw std::invalid_argument("continue_one_dof: x0 and direction need num_unknowns() entries");
  ContinuationResult out;
  NewtonOptions nopt;
  nopt.tolerance = options.tolerance;
  const NewtonResult start = newton_project(system, x0, nopt);
  if (!start.converged) {
    out.reason = "start not on manifold";
    return out;
  }
  out.points.push_back({start.x, start.residual_history.back(), 0.0, start.iterations});
  Eigen::VectorXd t = tangent_at(system, start.x);
  if (t.size() == 0) {
    out.reason = "not 1 DOF";
    return out;
  }
  if (t.dot(direction) < 0) t = -t;
  double h = options.initial_step;
  while (static_cast<int>(out.points.size()) < options.max_points) {
    if (stop(out.points.back().x)) {
      out.stopped = true;
      out.reason = "stop";
      return out;
    }
    const Eigen::VectorXd& xk = out.points.back().x;
    const Corrected c = correct(system, xk, t, h, xk + h * t, options);
    Eigen::VectorXd t_new;
    if (c.converged) {
      t_new = tangent_at(system, c.x);
      if (t_new.size() != 0 && t_new.dot(t) < 0) t_new = -t_new;
    }
    if (!c.converged || t_new.size() == 0 || std::acos(std::clamp(t_new.dot(t), -1.0, 1.0)) > 0.5) {
      h *= 0.5;
      if (h < options.min_step) {
        out.reason = "step too small";
        return out;
      }
      continue;
    }
    out.points.push_back({c.x, c.residual, h, c.iterations});
    t = t_new;
    if (c.iterations <= 3) h = std::min(h * 1.5, options.max_step);
  }
  out.reason = "max_points";
  return out;
}

}  // namespace rigidfold
