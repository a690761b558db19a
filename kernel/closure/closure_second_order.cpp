#include "kernel/closure/closure_second_order.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>
#include <vector>

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
  std::vector<double> angles, dir;
  std::vector<int> unknown;  // per fan slot: its unknown, or -1 (fixed and rigid creases do not move)
  for (int k = 0; k < system.num_vertices(); ++k) {
    const Fan& fan = topology.stars[system.vertex_of_block(k)].fans.at(0);
    const std::size_t d = fan.edges.size();
    angles.resize(d);
    dir.assign(d, 0.0);
    unknown.resize(d);
    for (std::size_t i = 0; i < d; ++i) {
      angles[i] = rho[fan.edges[i]];
      unknown[i] = system.unknown_of_edge(fan.edges[i]);
    }
    const Eigen::Vector3d wk = w.segment<3>(3 * k);
    // w . D^2 r[u] for the direction u that is 1 on fan slots i and j (i == j: slot i only).
    auto quad = [&](std::size_t i, std::size_t j) {
      dir[i] = 1.0;
      dir[j] = 1.0;
      const double q = wk.dot(vertex_closure_second_derivative(std::span<const double>(fan.sectors),
                                                               std::span<const double>(angles),
                                                               std::span<const double>(dir)));
      dir[i] = 0.0;
      dir[j] = 0.0;
      return q;
    };
    std::vector<double> diag(d, 0.0);
    for (std::size_t i = 0; i < d; ++i)
      if (unknown[i] >= 0) diag[i] = quad(i, i);
    for (std::size_t i = 0; i < d; ++i) {
      if (unknown[i] < 0) continue;
      H(unknown[i], unknown[i]) += diag[i];
      for (std::size_t j = i + 1; j < d; ++j) {
        if (unknown[j] < 0) continue;
        const double off = 0.5 * (quad(i, j) - diag[i] - diag[j]);
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
