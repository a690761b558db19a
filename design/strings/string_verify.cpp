#include "design/strings/string_verify.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold::design {

StringVerification verify_string_with_general_solver(const MiuraString& s, const CreasePattern& pattern,
                                                     const StringState& state, double perturbation) {
  if (state.mode != ThetaMode::Transmitted)
    throw std::invalid_argument("verify_string_with_general_solver: needs a Transmitted-mode state (one DOF sheet)");
  const int n = s.size();
  const StringPatternIndex ix{n};
  const Topology topo = build_topology(pattern, "string pattern");
  ClosureOptions opt;
  opt.fixed.push_back({ix.spinal_edge(0), state.edge_fold_angles[ix.spinal_edge(0)]});
  const ClosureSystem system(pattern, topo, opt);
  Eigen::VectorXd x0 = system.unknowns_from_edges(state.edge_fold_angles);
  if (perturbation != 0) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < x0.size(); ++k) x0[k] += perturbation * u(rng);
  }
  const NewtonResult nr = newton_project(system, x0);
  StringVerification v;
  v.converged = nr.converged;
  v.iterations = nr.iterations;
  v.closure_residual = nr.residual_history.empty() ? 0.0 : nr.residual_history.back();
  v.solver_angles = system.edges_from_unknowns(nr.x);
  for (int e = 0; e < 3 * n + 1; ++e)
    v.max_angle_error = std::max(v.max_angle_error, std::fabs(v.solver_angles[e] - state.edge_fold_angles[e]));
  v.folded = place_faces(pattern, topo, v.solver_angles, Eigen::VectorXd::Zero(pattern.num_edges()));
  v.placement_mismatch = v.folded.max_mismatch;
  for (int k = 0; k < n + 2; ++k)
    v.max_spine_error = std::max(v.max_spine_error, (v.folded.vertices[ix.spine_vertex(k)] - state.spine[k]).norm());
  return v;
}

}  // namespace rigidfold::design
