#pragma once
// Stable states of a crease-spring pattern by multistart (the general `rigidfold energy`,
// no pattern-specific code): the energy is minimised on the loop-closure
// manifold (constrained_equilibrium.hpp) from
//   - the rest state itself (projected onto the manifold: it need not close exactly), and
//   - `random_starts` random fold states that respect the letters (M < 0, V > 0, U either
//     sign; magnitudes uniform in (0, max_start_fold)), each first projected onto the manifold
//     by the sign-respecting corrector (newton_projection.hpp with sign bounds).
// Every converged minimum whose reduced Hessian is positive definite is kept once (states
// closer than same_state_tolerance in fold angles are one). A search, not a proof: a state
// no start reaches is missed; the counts say how many starts reached each state.
// The springs do not hold the letters: a minimisation may end with a crease folded against
// its M/V letter, or with panels passing through each other (the energy knows no contact).
// Each state says so (creases_against_letters; interfering_faces from the faces placed at its
// fold angles, kernel/geometry/facet_interference.hpp), so a caller can keep the states that
// a sheet with those letters can reach.
// Units: radians; energy in the stiffness unit times rad^2.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct StableStateSearchOptions {
  int random_starts = 24;
  std::uint64_t seed = 1;               // the same seed gives the same starts on every platform
  double max_start_fold = 0.9 * 3.141592653589793;  // radians
  double same_state_tolerance = 1e-6;   // radians (inf-norm over the edges)
  EquilibriumOptions equilibrium;
};

struct FoundState {
  Equilibrium state;
  int reached_from = 0;  // starts that converged to it
  bool from_rest = false;  // the rest state's own start reached it
  std::vector<int> creases_against_letters;  // M with rho > 0 or V with rho < 0 (beyond the sign threshold)
  std::vector<std::pair<int, int>> interfering_faces;  // face pairs passing through each other
  bool physical() const { return creases_against_letters.empty() && interfering_faces.empty(); }
};

struct StableStateSearch {
  std::vector<FoundState> states;  // increasing energy
  int starts = 0;                  // starts tried (rest included)
  int starts_on_manifold = 0;      // starts the corrector put on the manifold
  int starts_converged = 0;        // minimisations that converged (stable or not)
};

// rest_edge_angles: one per edge (radians), the springs' rest state. Throws
// std::invalid_argument for wrong sizes.
StableStateSearch search_stable_states(const CreasePattern& pattern, const Topology& topology,
                                       const ClosureSystem& system, const CreaseSprings& springs,
                                       const Eigen::VectorXd& rest_edge_angles,
                                       const StableStateSearchOptions& options = {});

}  // namespace rigidfold
