#include "report/energy_json.hpp"

#include <cmath>

#include "kernel/math/angle_units.hpp"

namespace rigidfold::report {

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
  if (problem.barriers) {
    auto angles_deg = [&](const Eigen::VectorXd& rho) {
      Json a = Json::array();
      for (int e = 0; e < pattern.num_edges(); ++e) a.push_back(topology.edge_is_hinge[e] ? Json(to_degrees(rho[e])) : Json(nullptr));
      return a;
    };
    Json barriers = Json::array();
    for (const StateBarrier& b : states.barriers) {
      const MinimumEnergyPath& m = b.path;
      Json bj;
      bj["states"] = {b.first, b.second};
      bj["found"] = m.found;
      bj["top"] = to_string(m.top);
      bj["message"] = m.message;
      bj["barrier_from_first"] = m.found ? Json(m.barrier_from_a) : Json(nullptr);
      bj["barrier_from_second"] = m.found ? Json(m.barrier_from_b) : Json(nullptr);
      bj["saddle_joins_states"] = b.saddle_joins[0] >= 0 ? Json({b.saddle_joins[0], b.saddle_joins[1]}) : Json(nullptr);
      Json saddle;
      if (m.saddle.x.size() != 0) {
        saddle["energy"] = m.saddle.energy;
        saddle["converged"] = m.saddle.converged;
        saddle["closure_residual_rad"] = m.saddle.closure_residual;
        saddle["stationarity_residual"] = m.saddle.stationarity_residual;
        saddle["negative_eigenvalues"] = m.negative_eigenvalues;
        Json ev = Json::array();
        for (Eigen::Index i = 0; i < m.saddle.reduced_hessian_eigenvalues.size(); ++i) ev.push_back(m.saddle.reduced_hessian_eigenvalues[i]);
        saddle["reduced_hessian_eigenvalues"] = ev;
        saddle["connects_the_states"] = m.connects;
        saddle["fold_angles_deg"] = angles_deg(m.saddle.edge_angles);
      }
      bj["saddle"] = saddle.is_null() ? Json(nullptr) : saddle;
      bj["string_converged"] = m.string_converged;
      bj["string_iterations"] = m.string_iterations;
      bj["string_force"] = m.string_force;
      bj["newton_iterations"] = m.newton_iterations;
      bj["climbing_image"] = m.climbing_image;
      Json path = Json::array();
      for (const PathImage& im : m.images) path.push_back({{"energy", im.energy}, {"fold_angles_deg", angles_deg(im.edge_angles)}});
      bj["path"] = path;
      barriers.push_back(bj);
    }
    j["barriers"] = barriers;
  }
  return j;
}

}  // namespace rigidfold::report
