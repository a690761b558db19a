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

}  // namespace rigidfold
