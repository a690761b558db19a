#include "app/energy_json.hpp"

#include <cmath>

#include "kernel/math/angle_units.hpp"

namespace rigidfold::cli {

nlohmann::ordered_json crease_spring_states_json(const CreasePattern& pattern, const Topology& topology,
                                                 const CreaseSpringProblem& problem, const CreaseSpringStates& states) {
  using Json = nlohmann::ordered_json;
  const StableStateSearch& s = states.search;
  Json j;
  j["rest_closure_residual_rad"] = states.rest_closure_residual;
  if (problem.edge_stiffness.size() != 0) {
    Json per_edge = Json::array();
    for (Eigen::Index e = 0; e < problem.edge_stiffness.size(); ++e) per_edge.push_back(problem.edge_stiffness[e]);
    j["stiffness"] = {{"per_edge", per_edge}};
  } else {
    j["stiffness"] = {{"mountain", problem.stiffness.mountain}, {"valley", problem.stiffness.valley}, {"unassigned", problem.stiffness.unassigned}};
  }
  j["starts"] = s.starts;
  j["starts_on_manifold"] = s.starts_on_manifold;
  j["starts_converged"] = s.starts_converged;
  Json list = Json::array();
  for (const FoundState& f : s.states) {
    Json sj;
    sj["energy"] = f.state.energy;
    sj["reached_from_starts"] = f.reached_from;
    sj["from_rest"] = f.from_rest;
    sj["keeps_letters"] = f.creases_against_letters.empty();
    sj["creases_against_letters"] = f.creases_against_letters;
    sj["facet_interference"] = !f.interfering_faces.empty();
    Json pairs = Json::array();
    for (const auto& [a, b] : f.interfering_faces) pairs.push_back({a, b});
    sj["interfering_face_pairs"] = pairs;
    sj["closure_residual_rad"] = f.state.closure_residual;
    sj["stationarity_residual"] = f.state.stationarity_residual;
    sj["tangent_dimension"] = f.state.tangent_dimension;
    sj["min_reduced_hessian_eigenvalue"] = std::isfinite(f.state.min_eigenvalue) ? Json(f.state.min_eigenvalue) : Json(nullptr);
    Json angles = Json::array();
    for (int e = 0; e < pattern.num_edges(); ++e)
      angles.push_back(topology.edge_is_hinge[e] ? Json(to_degrees(f.state.edge_angles[e])) : Json(nullptr));
    sj["fold_angles_deg"] = angles;
    list.push_back(sj);
  }
  j["stable_states"] = list;
  return j;
}

}  // namespace rigidfold::cli
