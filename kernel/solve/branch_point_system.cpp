#include "kernel/solve/branch_point_system.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "kernel/closure/closure_second_order.hpp"

namespace rigidfold {
namespace {

// G(z) and, if asked, DG(z) of the header's extended system.
struct Extended {
  Eigen::VectorXd G;
  Eigen::MatrixXd DG;
};

Extended evaluate_extended(const ClosureSystem& sys, const Topology& topo, const Eigen::MatrixXd& U,
                           const Eigen::VectorXd& z, bool with_jacobian) {
  const int n = sys.num_unknowns(), m = sys.num_rows();
  const Eigen::VectorXd x = z.head(n), c = z.tail(n - 1);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> Js;
  sys.evaluate(x, r, Js);
  const Eigen::MatrixXd J(Js);
  const Eigen::VectorXd psi = U * c;
  Extended e;
  e.G.resize(m + n + 1);
  e.G.head(m) = r;
  e.G.segment(m, n) = J.transpose() * psi;
  e.G[m + n] = 0.5 * (c.squaredNorm() - 1.0);
  if (with_jacobian) {
    e.DG = Eigen::MatrixXd::Zero(m + n + 1, 2 * n - 1);
    e.DG.block(0, 0, m, n) = J;
    e.DG.block(m, 0, n, n) = closure_weighted_hessian(sys, topo, x, psi);
    e.DG.block(m, n, n, n - 1) = J.transpose() * U;
    e.DG.block(m + n, n, 1, n - 1) = c.transpose();
  }
  return e;
}

}  // namespace

BranchPointSolve solve_branch_point(const ClosureSystem& system, const Topology& topology, const Eigen::VectorXd& x0,
                                    const Eigen::MatrixXd& U, const BranchPointOptions& opt) {
  const int n = system.num_unknowns(), m = system.num_rows();
  if (n < 2 || x0.size() != n || U.rows() != m || U.cols() != n - 1)
    throw std::invalid_argument("solve_branch_point: x0 needs num_unknowns() entries and U num_rows() x (n - 1)");
  BranchPointSolve out;
  out.error_bound = std::numeric_limits<double>::infinity();
  Eigen::VectorXd z(2 * n - 1);
  z.head(n) = x0;
  {
    const Eigen::MatrixXd UtJ = U.transpose() * dense_jacobian(system, x0);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(UtJ, Eigen::ComputeFullU);
    z.tail(n - 1) = svd.matrixU().col(n - 2);  // left singular vector of the smallest singular value
  }

  // Gauss-Newton until a step fails to halve the previous one below 1e-8: the iteration has
  // reached the rounding floor (in the quadratic regime each step is ~C times the square of
  // the previous one). That step is not taken.
  double previous = std::numeric_limits<double>::infinity();
  for (int k = 0; k < opt.max_iterations; ++k) {
    const Extended e = evaluate_extended(system, topology, U, z, true);
    out.residual_history.push_back(e.G.norm());
    const Eigen::VectorXd step = -e.DG.colPivHouseholderQr().solve(e.G);
    const double s = step.norm();
    if (!std::isfinite(s)) return out;
    if (s < 1e-8 && s > 0.5 * previous) break;
    z += step;
    out.step_history.push_back(s);
    ++out.iterations;
    previous = s;
    if (s == 0.0) break;
  }

  // The bound at the final iterate (header).
  const Extended e = evaluate_extended(system, topology, U, z, true);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(e.DG, Eigen::ComputeThinU | Eigen::ComputeThinV);
  out.sigma_min = svd.singularValues()[2 * n - 2];
  out.step_norm = svd.solve(e.G).norm();
  // Rounding noise of G: the part of G(z + d) - G(z) that the linear model does not explain
  // (the quadratic remainder, ~L |d|^2 = 1e-24 L, is far below it).
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> normal;
  double noise = 0.0;
  for (int probe = 0; probe < 4; ++probe) {
    Eigen::VectorXd d(2 * n - 1);
    for (int i = 0; i < d.size(); ++i) d[i] = normal(rng);
    d *= 1e-12 / d.norm();
    const Extended ep = evaluate_extended(system, topology, U, z + d, false);
    noise = std::max(noise, (ep.G - e.G - e.DG * d).norm());
  }
  out.noise = 4.0 * noise;
  // Lipschitz constant of DG: |D(DG)[v]|_2 <= sqrt(sum_j |D(DG)[e_j]|_F^2) for unit v.
  double sum = 0.0;
  for (int j = 0; j < 2 * n - 1; ++j) {
    Eigen::VectorXd zp = z, zm = z;
    zp[j] += opt.lipschitz_step;
    zm[j] -= opt.lipschitz_step;
    const Eigen::MatrixXd dD = (evaluate_extended(system, topology, U, zp, true).DG -
                                evaluate_extended(system, topology, U, zm, true).DG) / (2 * opt.lipschitz_step);
    sum += dD.squaredNorm();
  }
  out.lipschitz = opt.lipschitz_safety * std::sqrt(sum);

  out.x = z.head(n);
  const Eigen::VectorXd c = z.tail(n - 1);
  out.left_null = U * c.normalized();
  out.residual = system.residual(out.x).lpNorm<Eigen::Infinity>();
  if (!(out.sigma_min > 0)) return out;
  const double beta = 1.0 / out.sigma_min;
  const double eta = out.step_norm + beta * out.noise;
  out.kantorovich_h = beta * out.lipschitz * eta;
  if (!(out.kantorovich_h <= 0.5)) return out;
  out.converged = true;
  out.error_bound = 2.0 * eta;
  return out;
}

}  // namespace rigidfold
