#include "design/target/nearest_state.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {
namespace {

// Up to this many free creases the least-norm steps are dense (exact on J's null space).
constexpr int kDenseUnknowns = 1500;

}  // namespace

NearestState nearest_closed_state(const CreasePattern& pattern, const Topology& topology, const Eigen::VectorXd& target,
                                  const NearestStateOptions& options) {
  if (target.size() != pattern.num_edges()) throw std::invalid_argument("nearest_closed_state: one target angle per edge");
  NearestState out;
  out.target = target;
  out.held_edges = options.held_edges;
  ClosureOptions closure;
  closure.close_holes = count_holes(topology) > 0;
  for (int e : options.held_edges) {
    if (e < 0 || e >= pattern.num_edges())
      throw InputError("held edge " + std::to_string(e), "is not an edge of the pattern (it has " + std::to_string(pattern.num_edges()) + ")");
    if (!topology.edge_is_hinge[e] || !is_foldable_crease(pattern.assignments[e]))
      throw InputError("held edge " + std::to_string(e), "is not a crease that folds (M, V or U between two faces)");
    closure.fixed.push_back({e, target[e]});
  }
  std::optional<ClosureSystem> built;
  try {
    built.emplace(pattern, topology, closure);
  } catch (const std::runtime_error& e) {
    throw InputError("faces", e.what());
  }
  const ClosureSystem& system = *built;
  const Eigen::VectorXd xt = system.unknowns_from_edges(target);
  out.free_creases = system.num_unknowns();
  out.target_residual = system.num_rows() > 0 ? system.residual(xt).lpNorm<Eigen::Infinity>() : 0.0;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(xt.size());
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(xt, r, J);
  // The least-norm solution of J d = b. Dense (a complete orthogonal decomposition, exact
  // on J's null space) up to kDenseUnknowns; above, CHOLMOD's regularised normal equations,
  // whose null-space component carries rounding amplified by 1/lambda: there the steps along
  // the manifold are noisy and the iteration may end unconverged (then said so).
  const bool dense = system.num_unknowns() <= kDenseUnknowns;
  MinimumNormSolver solver(J);
  auto least_norm = [&](const Eigen::VectorXd& b, Eigen::VectorXd& d) {
    if (dense) {
      d = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(Eigen::MatrixXd(J)).solve(b);
      return true;
    }
    if (!solver.factorize(J, 1e-14)) return false;
    d = solver.solve(J, b);
    return true;
  };
  double last_step = INFINITY;
  for (; out.iterations < options.max_iterations; ++out.iterations) {
    if (r.size() == 0 || (r.lpNorm<Eigen::Infinity>() <= options.tolerance && last_step <= options.step_tolerance)) {
      out.converged = true;
      break;
    }
    Eigen::VectorXd next;
    if (!least_norm(J * e - r, next)) break;
    Eigen::VectorXd step = next - e;
    const double size = step.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(size)) break;
    if (size > options.max_step) step *= options.max_step / size;
    e += step;
    last_step = step.lpNorm<Eigen::Infinity>();
    system.evaluate(xt + e, r, J);
  }
  out.residual = r.size() > 0 ? r.lpNorm<Eigen::Infinity>() : 0.0;
  if (Eigen::VectorXd projected; out.converged && e.size() > 0 && e.norm() > 0 && least_norm(J * e, projected)) {
    // The part of the move along the manifold's tangent (null space of J): 0 at the optimum.
    out.stationarity = (e - projected).norm() / e.norm();
  }
  out.angles = system.edges_from_unknowns(xt + e);
  double sum = 0;
  for (int k = 0; k < system.num_unknowns(); ++k) sum += e[k] * e[k];
  out.rms_distance = system.num_unknowns() > 0 ? std::sqrt(sum / system.num_unknowns()) : 0.0;
  for (int edge = 0; edge < pattern.num_edges(); ++edge) {
    if (system.unknown_of_edge(edge) < 0) continue;
    const double d = std::abs(out.angles[edge] - target[edge]);
    if (d > out.max_distance) {
      out.max_distance = d;
      out.worst_edge = edge;
    }
    const int sign = assigned_fold_sign(pattern.assignments[edge]);
    if (sign != 0 && sign * out.angles[edge] < -1e-9) out.against_letters.push_back(edge);
  }
  std::ostringstream msg;
  if (out.converged) {
    msg << "closed state found: closure residual " << out.residual << " rad, " << to_degrees(out.max_distance)
        << " deg from the target at most (edge " << out.worst_edge << ")";
  } else {
    msg << "no closed state found near the target in " << out.iterations << " iterations: closure residual " << out.residual
        << " rad left";
  }
  out.message = msg.str();
  return out;
}

}  // namespace rigidfold
