#pragma once
// The foldability verdict of a pattern as the JSON object `rigidfold check --json` prints
// (also embedded per pattern in `rigidfold report`).
#include <nlohmann/json.hpp>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {

// Keys: rigidly_foldable (bool, or null when undecided), verdict, model, reason, dof,
// branches [{id, signs_match_assignment, range_deg, stopped_by, max_residual}],
// bifurcations [{parameter, angles_deg, kind}], obstruction (null or object),
// max_residual (rad), certificate_mismatch (relative), interference, seconds.
nlohmann::ordered_json foldability_json(const CreasePattern& pattern, const Topology& topology, bool ignore_assignment);

}  // namespace rigidfold::cli
