#include "kernel/energy/crease_spring_states.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold {

CreaseSpringStates crease_spring_states(const CreasePattern& pattern, const Topology& topology,
                                        const CreaseSpringProblem& problem) {
  const int starts = problem.search.random_starts;
  if (starts < 0 || starts > kMaxSpringStateStarts)
    throw InputError("starts", "must be between 0 and " + std::to_string(kMaxSpringStateStarts));
  // The energy is searched over the states of a sheet folded from flat: a sheet with holes (a
  // tube, a thick FOLD's slabs) has no flat state of its own, so it is refused as input here
  // rather than by the closure system as an internal error.
  int holes = 0;
  for (const Component& c : topology.components) holes += c.holes;
  if (holes > 0)
    throw InputError("pattern", "has " + std::to_string(holes) +
                                    " hole(s) (a tube, or a thick FOLD): the energy model needs a sheet that folds from flat; "
                                    "`check` and `trace` handle sheets with holes from their given state");
  const ClosureSystem system(pattern, topology);
  if (system.num_unknowns() > kMaxSpringStateFreeCreases)
    throw InputError("pattern", std::to_string(system.num_unknowns()) + " free creases; the energy search takes at most " +
                                    std::to_string(kMaxSpringStateFreeCreases));
  if (problem.edge_stiffness.size() != 0 && problem.edge_stiffness.size() != pattern.num_edges())
    throw InputError("edge_stiffness", "has " + std::to_string(problem.edge_stiffness.size()) + " entries; the pattern has " +
                                           std::to_string(pattern.num_edges()) + " edges");
  const Eigen::VectorXd stiffness =
      problem.edge_stiffness.size() != 0 ? problem.edge_stiffness : stiffness_by_assignment(pattern, problem.stiffness);
  for (Eigen::Index e = 0; e < stiffness.size(); ++e)
    if (!std::isfinite(stiffness[e]) || stiffness[e] < 0.0)
      throw InputError("stiffness[" + std::to_string(e) + "]", "must be finite and >= 0");
  if (problem.rest.size() != pattern.num_edges())
    throw InputError(problem.rest_place, "has " + std::to_string(problem.rest.size()) + " angles; the pattern has " +
                                             std::to_string(pattern.num_edges()) + " edges");
  CreaseSprings springs;
  try {
    springs = make_crease_springs(pattern, stiffness, problem.rest);
  } catch (const InputError& e) {
    throw InputError(problem.rest_place, e.what());  // e.what() names the angle
  }

  CreaseSpringStates out;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(system.unknowns_from_edges(problem.rest), r, J);
  out.rest_closure_residual = r.size() ? r.lpNorm<Eigen::Infinity>() : 0.0;
  if (!(out.rest_closure_residual <= kRestClosureTolerance)) {
    Eigen::Index row = 0;
    if (r.size()) r.cwiseAbs().maxCoeff(&row);
    throw InputError(problem.rest_place, "the rest state does not close: loop-closure residual " +
                                             std::to_string(out.rest_closure_residual) + " rad (row " + std::to_string(row) +
                                             ", allowed " + std::to_string(kRestClosureTolerance) + ")");
  }
  out.search = search_stable_states(pattern, topology, system, springs, problem.rest, problem.search);
  if (out.search.states.empty())
    throw NoAnswerError("no stable state reached from " + std::to_string(out.search.starts) + " starts (" +
                        std::to_string(out.search.starts_converged) + " minimisations converged)");
  if (problem.barriers) {
    const int count = static_cast<int>(out.search.states.size());
    for (int i = 0; i < count; ++i)
      for (int j = i + 1; j < count; ++j) {
        if (count > kMaxAllPairsBarrierStates && j != i + 1) continue;
        StateBarrier barrier{i, j, {}};
        barrier.path = minimum_energy_path(system, topology, springs, out.search.states[i].state.x,
                                           out.search.states[j].state.x, problem.path);
        if (!barrier.path.found && barrier.path.descent_ends.size() == 2) {
          int ends[2] = {-1, -1};
          for (int s = 0; s < 2; ++s)
            for (int k = 0; k < count && ends[s] < 0; ++k)
              if ((out.search.states[k].state.edge_angles - barrier.path.descent_ends[s]).lpNorm<Eigen::Infinity>() <=
                  problem.path.same_state_tolerance)
                ends[s] = k;
          if (ends[0] >= 0 && ends[1] >= 0 && ends[0] != ends[1]) {
            barrier.saddle_joins[0] = std::min(ends[0], ends[1]);
            barrier.saddle_joins[1] = std::max(ends[0], ends[1]);
          }
        }
        out.barriers.push_back(std::move(barrier));
      }
  }
  if (problem.load) {
    std::vector<Eigen::VectorXd> starts{system.unknowns_from_edges(problem.rest)};
    for (const auto& f : out.search.states) starts.push_back(system.unknowns_from_edges(f.state.edge_angles));
    double best = INFINITY;
    for (const auto& x0 : starts) {
      HeightControlledEquilibrium eq = vertex_height_equilibrium(pattern, system, topology, springs, *problem.load, x0);
      if (!eq.converged) {
        best = std::min(best, eq.constraint_residual);
        continue;
      }
      bool seen = false;
      for (const auto& other : out.loaded) seen = seen || (other.edge_angles - eq.edge_angles).lpNorm<Eigen::Infinity>() <= 1e-6;
      if (!seen) out.loaded.push_back(std::move(eq));
    }
    if (out.loaded.empty())
      throw NoAnswerError("--load: no loaded equilibrium converged from " + std::to_string(starts.size()) +
                              " starts (the rest state and each stable state; smallest constraint residual)",
                          best);
    std::sort(out.loaded.begin(), out.loaded.end(), [](const auto& x, const auto& y) { return x.energy < y.energy; });
  }
  return out;
}

}  // namespace rigidfold
