#include "report/nearest_state_json.hpp"

#include "kernel/math/angle_units.hpp"

namespace rigidfold::report {

nlohmann::ordered_json nearest_state_json(const NearestState& n) {
  nlohmann::ordered_json j;
  j["converged"] = n.converged;
  j["message"] = n.message;
  j["target_residual"] = n.target_residual;
  j["residual"] = n.residual;
  j["max_distance_deg"] = to_degrees(n.max_distance);
  j["rms_distance_deg"] = to_degrees(n.rms_distance);
  j["worst_edge"] = n.worst_edge;
  j["free_creases"] = n.free_creases;
  j["held_edges"] = n.held_edges;
  j["iterations"] = n.iterations;
  j["stationarity"] = n.stationarity;
  j["against_letters"] = n.against_letters;
  nlohmann::ordered_json per = nlohmann::ordered_json::array();
  for (Eigen::Index e = 0; e < n.angles.size(); ++e) per.push_back({{"angle_deg", to_degrees(n.angles[e])}, {"target_deg", to_degrees(n.target[e])}});
  j["per_crease"] = per;
  return j;
}

}  // namespace rigidfold::report
