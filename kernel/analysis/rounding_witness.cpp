#include "kernel/analysis/rounding_witness.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "kernel/analysis/rounding_residual_bound.hpp"
#include "kernel/math/so3.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {
namespace {

// Residual r = log(prod Rx(rho_i) Rz(alpha_i)) and its Jacobian with respect to the sectors:
// with R = Q_i Rz(alpha_i) S_i, Q_i = (prod_{j<i} Rx Rz) Rx(rho_i), dR/dalpha_i = [Q_i e_z]x R,
// so column i = Jl^-1(r) Q_i e_z.
void sector_jacobian(const std::vector<double>& sectors, const std::vector<double>& rho, Eigen::Vector3d& r,
                     Eigen::Matrix3Xd& J) {
  const int n = static_cast<int>(sectors.size());
  Eigen::Matrix3Xd axes(3, n);
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
  for (int i = 0; i < n; ++i) {
    P = P * rot_x(rho[i]);
    axes.col(i) = P.col(2);
    P = P * rot_z(sectors[i]);
  }
  r = so3_log(P);
  J = so3_left_jacobian_inverse(r) * axes;
}

}  // namespace

RoundingWitness rounding_witness(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& given,
                                 std::optional<double> stated_tolerance) {
  RoundingWitness w;
  w.precision = input_precision(p, stated_tolerance);
  w.witness = t;
  w.explained = true;
  const std::vector<std::vector<double>> bounds = sector_rounding_bounds(p, t, w.precision);
  for (std::size_t k = 0; k < t.interior_vertices.size(); ++k) {
    const int v = t.interior_vertices[k];
    Fan& fan = w.witness.stars[v].fans[0];
    const int n = static_cast<int>(fan.edges.size());
    std::vector<double> rho(n);
    for (int i = 0; i < n; ++i) rho[i] = given[fan.edges[i]];
    const std::vector<double>& bound = bounds[k];
    for (int i = 0; i < n; ++i) w.max_sector_bound = std::max(w.max_sector_bound, bound[i]);
    const std::vector<double> measured = fan.sectors;
    std::vector<double>& sec = fan.sectors;
    Eigen::Vector3d r;
    Eigen::Matrix3Xd J;
    sector_jacobian(sec, rho, r, J);
    w.given_residual = std::max(w.given_residual, r.norm());
    // Gauss-Newton, least bound-weighted change: d = -W J^T (J W J^T)^-1 r, W = diag(bound^2).
    for (int it = 0; it < 20 && r.norm() > 1e-15; ++it) {
      Eigen::VectorXd W(n);
      for (int i = 0; i < n; ++i) W[i] = bound[i] * bound[i];
      const Eigen::Matrix3d A = J * W.asDiagonal() * J.transpose();
      const Eigen::Vector3d y = A.completeOrthogonalDecomposition().solve(r);
      const Eigen::VectorXd d = -(W.asDiagonal() * J.transpose() * y);
      if (!d.allFinite()) break;
      for (int i = 0; i < n; ++i) sec[i] += d[i];
      const double before = r.norm();
      sector_jacobian(sec, rho, r, J);
      if (r.norm() >= before) break;  // no further progress: round-off
    }
    w.witness_residual = std::max(w.witness_residual, r.norm());
    for (int i = 0; i < n; ++i) {
      const double change = std::abs(sec[i] - measured[i]);
      w.max_sector_change = std::max(w.max_sector_change, change);
      const double ratio = bound[i] > 0 ? change / bound[i] : (change > 0 ? INFINITY : 0.0);
      if (ratio > w.max_change_ratio) {
        w.max_change_ratio = ratio;
        w.worst_vertex = v;
      }
    }
  }
  w.explained = w.max_change_ratio <= 1.0 && w.witness_residual <= 1e-13;
  return w;
}

}  // namespace rigidfold
