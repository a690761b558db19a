#include "kernel/closure/closure_second_order.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>
#include <vector>

#include "kernel/math/so3.hpp"
#include "kernel/vertex/vertex_second_order.hpp"

namespace rigidfold {

Eigen::VectorXd closure_second_derivative(const ClosureSystem& system, const Topology& topology,
                                          const Eigen::VectorXd& x, const Eigen::VectorXd& t) {
  const int n = system.num_unknowns();
  if (x.size() != n || t.size() != n)
    throw std::invalid_argument("closure_second_derivative: x and t need num_unknowns() entries");
  Eigen::VectorXd out = Eigen::VectorXd::Zero(system.num_rows());
  const Eigen::VectorXd rho = system.edges_from_unknowns(x);
  std::vector<double> angles, dir;
  for (int k = 0; k < system.num_vertices(); ++k) {
    const Fan& fan = topology.stars[system.vertex_of_block(k)].fans.at(0);
    angles.resize(fan.edges.size());
    dir.resize(fan.edges.size());
    for (std::size_t i = 0; i < fan.edges.size(); ++i) {
      const int e = fan.edges[i];
      angles[i] = rho[e];
      const int u = system.unknown_of_edge(e);
      dir[i] = u >= 0 ? t[u] : 0.0;  // fixed and rigid creases do not move
    }
    out.segment<3>(3 * k) = vertex_closure_second_derivative(std::span<const double>(fan.sectors),
                                                             std::span<const double>(angles),
                                                             std::span<const double>(dir));
  }
  if (system.num_holes() > 0) {
    const double h = 1e-5 / std::max(1.0, t.lpNorm<Eigen::Infinity>());
    Eigen::VectorXd rp, rm;
    Eigen::SparseMatrix<double> Jp, Jm;
    system.evaluate(x + h * t, rp, Jp);
    system.evaluate(x - h * t, rm, Jm);
    const Eigen::VectorXd d = (Jp * t - Jm * t) / (2 * h);
    const int begin = system.hole_row_begin();
    out.segment(begin, system.num_rows() - begin) = d.segment(begin, system.num_rows() - begin);
  }
  return out;
}

Eigen::MatrixXd closure_weighted_hessian(const ClosureSystem& system, const Topology& topology,
                                         const Eigen::VectorXd& x, const Eigen::VectorXd& w) {
  const int n = system.num_unknowns();
  if (x.size() != n || w.size() != system.num_rows())
    throw std::invalid_argument("closure_weighted_hessian: x needs num_unknowns() and w num_rows() entries");
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  const Eigen::VectorXd rho = system.edges_from_unknowns(x);
  // For R = prod_i Rx(rho_i) Rz(alpha_i) (crease 0's frame), dR/drho_i = [a_i]x R with a_i the
  // axis of crease i (the product of the factors before it applied to e_x), and a_j moves with
  // rho_i (i < j) as a_i x a_j, so d2R/drho_i drho_j = [a_i]x [a_j]x R for i <= j in fan
  // order. The vertex row's second derivative is vee(skew(.)) of that (header), so each pair
  // costs a 3 x 3 product: O(d^2) per vertex, where the polarisation of
  // vertex_closure_second_derivative cost O(d^3) (65% of a 120-crease waterbomb's time).
  std::vector<Eigen::Vector3d> axis;
  std::vector<Eigen::Matrix3d> axis_times_r;  // [a_j]x R
  std::vector<int> unknown;  // per fan slot: its unknown, or -1 (fixed and rigid creases do not move)
  for (int k = 0; k < system.num_vertices(); ++k) {
    const Fan& fan = topology.stars[system.vertex_of_block(k)].fans.at(0);
    const std::size_t d = fan.edges.size();
    axis.resize(d);
    axis_times_r.resize(d);
    unknown.resize(d);
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    for (std::size_t i = 0; i < d; ++i) {
      axis[i] = R.col(0);
      unknown[i] = system.unknown_of_edge(fan.edges[i]);
      R = R * rot_x(rho[fan.edges[i]]) * rot_z(fan.sectors[i]);
    }
    for (std::size_t j = 0; j < d; ++j) axis_times_r[j] = skew(axis[j]) * R;
    const Eigen::Vector3d wk = w.segment<3>(3 * k);
    // w . vee(skew(M)) for the second derivative M of R.
    auto weighted = [&](const Eigen::Matrix3d& M) { return wk.dot(skew_part_vector(M)); };
    for (std::size_t i = 0; i < d; ++i) {
      if (unknown[i] < 0) continue;
      const Eigen::Matrix3d ai = skew(axis[i]);
      H(unknown[i], unknown[i]) += weighted(ai * axis_times_r[i]);
      for (std::size_t j = i + 1; j < d; ++j) {
        if (unknown[j] < 0) continue;
        const double off = weighted(ai * axis_times_r[j]);
        H(unknown[i], unknown[j]) += off;
        H(unknown[j], unknown[i]) += off;
      }
    }
  }
  if (system.num_holes() > 0) {
    const int begin = system.hole_row_begin(), rows = system.num_rows() - begin;
    const double h = 1e-5;
    Eigen::VectorXd r, xp = x, xm = x;
    Eigen::SparseMatrix<double> Jp, Jm;
    for (int c = 0; c < n; ++c) {
      xp[c] += h;
      xm[c] -= h;
      system.evaluate(xp, r, Jp);
      system.evaluate(xm, r, Jm);
      const Eigen::MatrixXd dJ = (Eigen::MatrixXd(Jp) - Eigen::MatrixXd(Jm)).middleRows(begin, rows) / (2 * h);
      H.col(c) += dJ.transpose() * w.segment(begin, rows);
      xp[c] = x[c];
      xm[c] = x[c];
    }
  }
  return H;
}

}  // namespace rigidfold
