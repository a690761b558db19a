#include "kernel/solve/continuation.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {

namespace {

// Above this many unknowns the tangent comes from the corrector's own factorisation
// (inverse iteration) instead of a rank-revealing factorisation of J at every point: SPQR
// on a 10^5-10^6-crease Jacobian costs far more than the whole corrector.
constexpr int kRankRevealingLimit = 2000;

// Unit tangent at x (null vector of J), or an empty vector if the DOF is not 1.
Eigen::VectorXd tangent_at(const ClosureSystem& system, const Eigen::VectorXd& x) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(x, r, J);
  const RankResult rk = jacobian_rank(J);
  if (rk.dof != 1 || rk.null_space.cols() != 1) return {};
  return rk.null_space.col(0);
}

// A fixed, generic start vector for inverse iteration (no special direction of the mesh).
Eigen::VectorXd generic_vector(int n) {
  Eigen::VectorXd g(n);
  for (int k = 0; k < n; ++k) g[k] = 1.0 + 0.5 * std::sin(1.7 * k + 0.3);
  return g;
}

struct Corrected {
  Eigen::VectorXd x;
  double residual = 0.0;
  int iterations = 0;
  bool converged = false;
  Eigen::VectorXd null_vector;  // unit null vector of J at the last linearisation point (if any)
};

// Newton on [r(x); t.(x - xk) - h] = 0 from xp. With w the unit null vector of J(x), the
// exact step of the augmented linear system [J; t^T] dx = [r; c] is
//     dx = J^+ r + beta w,   beta = (c - t.J^+ r) / (t.w)
// (J^+ r is the minimum-norm solution, orthogonal to w; the augmented matrix has full
// column rank at a regular 1-DOF point), so the corrector keeps Newton's quadratic
// convergence while factorising only J^T J + lambda I, whose pattern (and symbolic
// analysis, in `solver`) is shared by every step of the trace.
Corrected correct(const ClosureSystem& system, MinimumNormSolver& solver, const Eigen::VectorXd& xk,
                  const Eigen::VectorXd& t, double h, const Eigen::VectorXd& xp, const ContinuationOptions& options) {
  Corrected c;
  c.x = xp;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  for (;;) {
    system.evaluate(c.x, r, J);
    const double arc = t.dot(c.x - xk) - h;
    c.residual = std::max(r.size() > 0 ? r.lpNorm<Eigen::Infinity>() : 0.0, std::abs(arc));
    if (c.residual <= options.tolerance) {
      c.converged = true;
      return c;
    }
    if (c.iterations >= options.max_corrector_iterations || !std::isfinite(c.residual)) return c;
    if (!solver.factorize(J, options.lambda_relative)) return c;
    const Eigen::VectorXd d = solver.solve(J, r);
    c.null_vector = solver.null_vector(J, t);
    const double tw = t.dot(c.null_vector);
    if (std::abs(tw) < 1e-8) return c;  // the tangent plane turned away: not a regular 1-DOF point
    c.x -= d + ((arc - t.dot(d)) / tw) * c.null_vector;
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
  Eigen::VectorXd r0;
  Eigen::SparseMatrix<double> J0;
  system.evaluate(start.x, r0, J0);
  MinimumNormSolver solver(J0);
  const bool rank_revealing = system.num_unknowns() <= kRankRevealingLimit;
  // Large systems: the tangent is the null vector of the corrector's G (inverse iteration);
  // the DOF is not re-checked by a rank-revealing factorisation there.
  auto tangent = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& guess) -> Eigen::VectorXd {
    if (rank_revealing) return tangent_at(system, x);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    system.evaluate(x, r, J);
    if (!solver.factorize(J, options.lambda_relative)) return {};
    return solver.null_vector(J, guess);
  };
  Eigen::VectorXd t = tangent(start.x, generic_vector(system.num_unknowns()));
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
    const Corrected c = correct(system, solver, xk, t, h, xk + h * t, options);
    Eigen::VectorXd t_new;
    if (c.converged) {
      // Large systems reuse the null vector of the last corrector step (at an iterate within
      // about the previous residual of c.x): accurate enough for a predictor and the turn test.
      t_new = (rank_revealing || c.null_vector.size() == 0) ? tangent(c.x, t) : c.null_vector;
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
