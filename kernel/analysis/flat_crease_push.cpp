#include "kernel/analysis/flat_crease_push.hpp"

#include <stdexcept>

#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {

std::optional<Eigen::VectorXd> push_off_flat_creases(const ClosureSystem& sys, const Eigen::VectorXd& x,
                                                     const std::vector<int>& sign, double tolerance,
                                                     double flat_fraction) {
  const int n = sys.num_unknowns();
  if (x.size() != n || static_cast<int>(sign.size()) != sys.num_edges())
    throw std::invalid_argument("push_off_flat_creases: x needs one entry per unknown, the signs one per edge");
  const double xmax = n ? x.cwiseAbs().maxCoeff() : 0.0;
  if (!(xmax > 0)) return std::nullopt;
  // Lettered creases at most flat_fraction of the largest fold at y (or against their letter).
  auto flat_at = [&](const Eigen::VectorXd& y) {
    const double cut = flat_fraction * y.cwiseAbs().maxCoeff();
    std::vector<int> flat;
    for (int i = 0; i < n; ++i) {
      const int s = sign[sys.edge_of_unknown(i)];
      if (s != 0 && s * y[i] <= cut) flat.push_back(i);
    }
    return flat;
  };
  const std::vector<int> flat = flat_at(x);
  if (flat.empty()) return std::nullopt;
  for (double tau : {1e-2, 1e-3}) {
    std::vector<int> held = flat;
    for (int round = 0; round < 8; ++round) {
      Eigen::VectorXd y = x;
      for (int i : held) y[i] = sign[sys.edge_of_unknown(i)] * tau * xmax;
      NewtonOptions nopt;
      nopt.tolerance = tolerance;
      nopt.held_unknowns = held;
      const NewtonResult nr = newton_project(sys, y, nopt);
      if (!nr.converged) break;
      const std::vector<int> against = flat_at(nr.x);
      if (against.empty()) return nr.x;
      held.insert(held.end(), against.begin(), against.end());
      if (static_cast<int>(held.size()) >= n) break;  // nothing left to move
    }
  }
  return std::nullopt;
}

}  // namespace rigidfold
