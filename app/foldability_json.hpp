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
// The model is the cheapest exact one that applies: multiplier propagation (flat-foldable
// degree-4 vertices; its yes and no are both exact), else the general loop-closure solver
// (a yes is a traced branch; a no is numerical evidence, flagged by is_proof = false).
// force_general: skip multiplier propagation even where it applies (for cross-checks).
nlohmann::ordered_json foldability_json(const CreasePattern& pattern, const Topology& topology, bool ignore_assignment,
                                        bool force_general = false);

}  // namespace rigidfold::cli
