#pragma once
// The JSON of the closed state nearest to target angles (design/target/nearest_state.hpp), as
// `rigidfold fold --target --json` prints it under "nearest_state". Angles in degrees,
// residuals in radians.
#include <nlohmann/json.hpp>

#include "design/target/nearest_state.hpp"

namespace rigidfold::report {

// Keys: converged, message, target_residual, residual, max_distance_deg, rms_distance_deg,
// worst_edge, free_creases, held_edges, iterations, stationarity, against_letters,
// per_crease [{angle_deg, target_deg}] (one per edge).
nlohmann::ordered_json nearest_state_json(const NearestState& state);

}  // namespace rigidfold::report
