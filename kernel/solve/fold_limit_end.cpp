#include "kernel/solve/fold_limit_end.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {

std::optional<FoldLimitEnd> solve_fold_limit_end(const ClosureSystem& system, const Eigen::VectorXd& x_before,
                                                 const Eigen::VectorXd& x_after, int crease, double fraction,
                                                 double tolerance, double max_distance) {
  const int k = system.unknown_of_edge(crease);
  if (k < 0) return std::nullopt;
  Eigen::VectorXd start = x_before + std::clamp(fraction, 0.0, 1.0) * (x_after - x_before);
  start[k] = std::copysign(std::numbers::pi, x_after[k]);
  NewtonOptions options;
  options.tolerance = tolerance;
  options.held_unknowns = {k};
  NewtonResult r = newton_project(system, start, options);
  // Creases that reach 180 deg together with this one (symmetric patterns) can land a
  // rounding error beyond it: hold them at +-pi too and project again.
  for (int round = 0; round < 2 && r.converged; ++round) {
    Eigen::VectorXd again = r.x;
    bool beyond = false;
    for (int i = 0; i < again.size(); ++i)
      if (std::fabs(again[i]) > std::numbers::pi) {
        again[i] = std::copysign(std::numbers::pi, again[i]);
        options.held_unknowns.push_back(i);
        beyond = true;
      }
    if (!beyond) break;
    r = newton_project(system, again, options);
  }
  if (!r.converged || (r.x - start).lpNorm<Eigen::Infinity>() > max_distance) return std::nullopt;
  for (int i = 0; i < r.x.size(); ++i)
    if (std::fabs(r.x[i]) > std::numbers::pi) return std::nullopt;  // still past 180 deg: not an end
  return FoldLimitEnd{r.x, r.residual_history.back()};
}

}  // namespace rigidfold
