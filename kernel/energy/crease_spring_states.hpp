#pragma once
// The stable states of a crease pattern with torsional springs at its creases: the one kernel
// entry behind `rigidfold energy` and the Python rigidfold.stable_states.
// It checks the problem (size, stiffnesses, rest state), then runs the multistart search of
// stable_state_search.hpp on the loop-closure manifold with no symmetry imposed. With
// CreaseSpringProblem::barriers it also runs minimum_energy_path.hpp between pairs of the
// states found (each barrier reported only when its saddle passed its checks).
//
// Units: radians; stiffness in energy per rad^2; energy in the stiffness unit times rad^2.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/minimum_energy_path.hpp"
#include "kernel/energy/stable_state_search.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// Free creases the search takes at most: its tangent-space steps are dense
// (constrained_equilibrium.hpp).
inline constexpr int kMaxSpringStateFreeCreases = 400;
// A rest state must close to this loop-closure residual (radians): one read from a file with
// decimals closes to ~1e-12; one that misses by more is not a state of this pattern.
inline constexpr double kRestClosureTolerance = 1e-6;
// Random starts the search takes at most (besides the rest state).
inline constexpr int kMaxSpringStateStarts = 1000;
// Barriers: every pair of stable states when there are at most this many states; otherwise
// only the pairs adjacent in energy (state i and i + 1 of the list).
inline constexpr int kMaxAllPairsBarrierStates = 6;

struct CreaseSpringProblem {
  StiffnessByAssignment stiffness;   // per letter, >= 0
  // When not empty (size num_edges(), e.g. from stiffness_spec.hpp): one stiffness per edge,
  // used instead of `stiffness`.
  Eigen::VectorXd edge_stiffness;
  Eigen::VectorXd rest;              // per edge, radians (FOLD sign): the springs' rest state
  std::string rest_place = "rest";   // named when the rest state is bad (the CLI passes its file)
  StableStateSearchOptions search;   // random_starts in [0, kMaxSpringStateStarts], seed
  // A vertex held at a height (load_spec.hpp): its loaded equilibria are reached from the rest
  // state and from each stable state, with the same springs.
  std::optional<VertexHeightLoad> load;
  // Barriers between the stable states (minimum_energy_path.hpp), pairs as
  // kMaxAllPairsBarrierStates says. Off by default: one string search per pair.
  bool barriers = false;
  MinimumEnergyPathOptions path;
};

// The barrier between two stable states (indices into CreaseSpringStates::search.states).
struct StateBarrier {
  int first = 0, second = 0;  // first < second
  MinimumEnergyPath path;     // path.found: every check passed; else path.message says why
  // When not found but the path's index-1 saddle descends to two states of the list on both
  // sides (another pair): their indices, increasing; else {-1, -1}. A hint, not a barrier of
  // (first, second).
  int saddle_joins[2] = {-1, -1};
};

struct CreaseSpringStates {
  double rest_closure_residual = 0.0;  // ||r(rest)||_inf, radians (<= kRestClosureTolerance)
  StableStateSearch search;            // states in increasing energy, each checked (see there)
  // With a load: the distinct converged loaded equilibria (edge angles apart by more than
  // 1e-6 rad), in increasing energy.
  std::vector<HeightControlledEquilibrium> loaded;
  // With barriers: one entry per pair searched, in order (0,1), (0,2), ..., (1,2), ...
  std::vector<StateBarrier> barriers;
};

// Throws InputError naming the place: "pattern" (more than kMaxSpringStateFreeCreases free
// creases), "stiffness.mountain" / ".valley" / ".unassigned", "edge_stiffness" (wrong size;
// "stiffness[e]" for a negative or non-finite entry), "starts", rest_place (a rest
// state that does not close, with its residual and row; wrong size or range);
// NoAnswerError when no start reaches a stable state, or with a load when no loaded
// equilibrium converges (the residual: the smallest constraint residual reached).
CreaseSpringStates crease_spring_states(const CreasePattern& pattern, const Topology& topology,
                                        const CreaseSpringProblem& problem);

}  // namespace rigidfold
