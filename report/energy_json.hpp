#pragma once
// The JSON of the stable states of a pattern with crease springs
// (kernel/energy/crease_spring_states.hpp), as `rigidfold energy --json` prints it after its
// "file" and "rest" keys, and as the Python rigidfold.stable_states returns it. Serialises only.
//
// Keys: rest_closure_residual_rad, stiffness {mountain, valley, unassigned} (or {per_edge:
// [k per edge]} when the problem has edge_stiffness), starts,
// starts_on_manifold, starts_converged, stable_states [{energy, reached_from_starts,
// from_rest, keeps_letters, creases_against_letters, facet_interference,
// interfering_face_pairs, closure_residual_rad, stationarity_residual, tangent_dimension,
// min_reduced_hessian_eigenvalue (null when the tangent space is empty), fold_angles_deg
// (per edge; null for an edge that is not a hinge)}]. Only when the problem asks for barriers:
// barriers [{states [i, j] (indices into stable_states), found, top ("index-1 saddle",
// "singular point (flat state, cusp)" or "none"), message ("" when found),
// barrier_from_first, barrier_from_second (saddle energy minus the state's; null unless
// found), saddle_joins_states (not found, but its index-1 saddle descends to these two
// listed states instead: [k, l]; else null), saddle (null when the refinement did not run) {energy, converged,
// closure_residual_rad, stationarity_residual, negative_eigenvalues,
// reduced_hessian_eigenvalues, connects_the_states, fold_angles_deg}, string_converged,
// string_iterations, string_force, newton_iterations, climbing_image, path [{energy,
// fold_angles_deg}]}]. Numbers round-trip exactly.
#include <nlohmann/json.hpp>

#include "kernel/energy/crease_spring_states.hpp"

namespace rigidfold::report {

nlohmann::ordered_json crease_spring_states_json(const CreasePattern& pattern, const Topology& topology,
                                                 const CreaseSpringProblem& problem, const CreaseSpringStates& states);

}  // namespace rigidfold::report
