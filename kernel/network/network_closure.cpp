#include "kernel/network/network_closure.hpp"

#include <cmath>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>

#include "kernel/solve/newton_projection.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {

NetworkClosure::NetworkClosure(LinkageNetwork network) : network_(std::move(network)) { validate_network(network_); }

Eigen::VectorXd NetworkClosure::residual(const Eigen::VectorXd& q) const {
  if (q.size() != num_unknowns()) throw std::invalid_argument("NetworkClosure::residual: wrong size");
  std::vector<double> qv(q.data(), q.data() + q.size());
  Eigen::VectorXd r(num_rows());
  for (int k = 0; k < network_.num_linkages(); ++k) {
    const NetworkLinkage& l = network_.linkages[k];
    const std::vector<double> t = linkage_joint_angles(l, qv);
    r.segment<3>(3 * k) = vertex_closure_residual(std::span<const double>(l.twists), std::span<const double>(t));
  }
  return r;
}

void NetworkClosure::evaluate(const Eigen::VectorXd& q, Eigen::VectorXd& r, Eigen::SparseMatrix<double>& J) const {
  if (q.size() != num_unknowns()) throw std::invalid_argument("NetworkClosure::evaluate: wrong size");
  std::vector<double> qv(q.data(), q.data() + q.size());
  r.resize(num_rows());
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::Vector3d rk;
  Eigen::Matrix3Xd Jk;
  for (int k = 0; k < network_.num_linkages(); ++k) {
    const NetworkLinkage& l = network_.linkages[k];
    const std::vector<double> t = linkage_joint_angles(l, qv);
    vertex_closure_jacobian(std::span<const double>(l.twists), std::span<const double>(t), rk, Jk);
    r.segment<3>(3 * k) = rk;
    // A joint appears once per linkage (validate_network), so every entry is stored once
    // and the pattern does not depend on q.
    for (std::size_t i = 0; i < l.joints.size(); ++i)
      for (int row = 0; row < 3; ++row)
        triplets.emplace_back(3 * k + row, l.joints[i].joint, l.joints[i].sign * Jk(row, static_cast<int>(i)));
  }
  J.resize(num_rows(), num_unknowns());
  J.setFromTriplets(triplets.begin(), triplets.end());
  J.makeCompressed();
}

double NetworkClosure::max_linkage_residual(const Eigen::VectorXd& q, int* worst_linkage) const {
  const Eigen::VectorXd r = residual(q);
  double worst = 0.0;
  int at = -1;
  for (int k = 0; k < network_.num_linkages(); ++k) {
    const double e = r.segment<3>(3 * k).norm();
    if (at < 0 || e > worst || std::isnan(e)) {
      worst = e;
      at = k;
    }
  }
  if (worst_linkage) *worst_linkage = at;
  return worst;
}

NetworkNewtonResult network_project(const NetworkClosure& system, const Eigen::VectorXd& q0,
                                    const NetworkNewtonOptions& options) {
  const int n = system.num_unknowns();
  if (q0.size() != n) throw std::invalid_argument("network_project: q0 has the wrong size");
  for (int j : options.held)
    if (j < 0 || j >= n) throw std::invalid_argument("network_project: held joint out of range");
  NetworkNewtonResult result;
  result.q = q0;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(result.q, r, J);
  double rnorm = r.size() ? r.lpNorm<Eigen::Infinity>() : 0.0;
  result.residual_history.push_back(rnorm);
  std::unique_ptr<MinimumNormSolver> solver;
  while (std::isfinite(rnorm) && rnorm > options.tolerance && result.iterations < options.max_iterations) {
    if (!solver) solver = std::make_unique<MinimumNormSolver>(J, options.held);
    if (!solver->factorize(J, options.lambda_relative)) break;
    Eigen::VectorXd dq = solver->solve(J, r);
    const double step = dq.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(step)) break;
    if (step > options.max_step) dq *= options.max_step / step;
    result.q -= dq;
    ++result.iterations;
    system.evaluate(result.q, r, J);
    rnorm = r.lpNorm<Eigen::Infinity>();
    result.residual_history.push_back(rnorm);
  }
  result.converged = std::isfinite(rnorm) && rnorm <= options.tolerance;
  return result;
}

RankResult network_mobility(const NetworkClosure& system, const Eigen::VectorXd& q, const std::vector<int>& held,
                            double relative_tolerance) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(q, r, J);
  if (!held.empty()) {
    // Drop the held joints' columns: the DOF of the remaining joints.
    std::vector<bool> drop(system.num_unknowns(), false);
    for (int j : held) {
      if (j < 0 || j >= system.num_unknowns()) throw std::invalid_argument("network_mobility: held joint out of range");
      drop[j] = true;
    }
    std::vector<Eigen::Triplet<double>> t;
    std::vector<int> col(system.num_unknowns(), -1);
    int nc = 0;
    for (int j = 0; j < system.num_unknowns(); ++j)
      if (!drop[j]) col[j] = nc++;
    for (int c = 0; c < J.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(J, c); it; ++it)
        if (col[c] >= 0) t.emplace_back(static_cast<int>(it.row()), col[c], it.value());
    Eigen::SparseMatrix<double> Jf(J.rows(), nc);
    Jf.setFromTriplets(t.begin(), t.end());
    J = Jf;
  }
  RankOptions options;
  options.relative_tolerance = relative_tolerance;
  return jacobian_rank(J, options);
}

}  // namespace rigidfold
