#include "kernel/energy/stable_state_search.hpp"

#include <algorithm>
#include <stdexcept>

#include "kernel/analysis/tolerances.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/facet_interference.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/portable_random.hpp"

namespace rigidfold {

StableStateSearch search_stable_states(const CreasePattern& pattern, const Topology& topology,
                                       const ClosureSystem& system, const CreaseSprings& springs,
                                       const Eigen::VectorXd& rest_edge_angles, const StableStateSearchOptions& options) {
  if (rest_edge_angles.size() != pattern.num_edges())
    throw std::invalid_argument("search_stable_states: one rest angle per edge expected");
  const int n = system.num_unknowns();
  std::vector<int> signs(n, 0);
  for (int k = 0; k < n; ++k) signs[k] = assigned_fold_sign(pattern.assignments[system.edge_of_unknown(k)]);

  StableStateSearch out;
  SplitMix64 rng{options.seed};
  auto add = [&](const Eigen::VectorXd& start, bool is_rest) {
    ++out.starts;
    NewtonOptions project;
    project.max_iterations = 60;
    project.stall_window = 8;
    if (!is_rest) project.sign_bounds = signs;
    const NewtonResult on = newton_project(system, start, project);
    if (!on.converged) return;
    ++out.starts_on_manifold;
    Equilibrium eq = find_equilibrium(system, topology, springs, on.x, options.equilibrium);
    if (!eq.converged) return;
    ++out.starts_converged;
    if (!eq.stable) return;
    for (FoundState& f : out.states)
      if ((f.state.edge_angles - eq.edge_angles).lpNorm<Eigen::Infinity>() <= options.same_state_tolerance) {
        ++f.reached_from;
        f.from_rest = f.from_rest || is_rest;
        return;
      }
    out.states.push_back({std::move(eq), 1, is_rest});
  };
  add(system.unknowns_from_edges(rest_edge_angles), true);
  for (int s = 0; s < options.random_starts; ++s) {
    Eigen::VectorXd x(n);
    for (int k = 0; k < n; ++k) {
      const int sign = signs[k] != 0 ? signs[k] : (rng.uniform() < 0.5 ? -1 : 1);
      x[k] = sign * options.max_start_fold * rng.open_uniform();
    }
    add(x, false);
  }
  const Eigen::VectorXd reference = reference_fold_angles(pattern, topology);
  for (FoundState& f : out.states) {
    const Eigen::VectorXd& rho = f.state.edge_angles;
    for (int e = 0; e < pattern.num_edges(); ++e)
      if (assigned_fold_sign(pattern.assignments[e]) * rho[e] < -kDefaultTolerances.sign_threshold)
        f.creases_against_letters.push_back(e);
    const FoldedGeometry g = place_faces(pattern, topology, rho, reference);
    f.interfering_faces = find_facet_interference(pattern, g.vertices).face_pairs;
  }
  std::sort(out.states.begin(), out.states.end(),
            [](const FoundState& a, const FoundState& b) { return a.state.energy < b.state.energy; });
  return out;
}

}  // namespace rigidfold
