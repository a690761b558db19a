#pragma once
// The JSON of a foldability report (kernel/analysis/foldability_report.hpp), as
// `rigidfold check --json` prints it and `rigidfold report` embeds it per pattern. This file
// only serialises: every value, verdict and flag comes from the kernel's report.
#include <nlohmann/json.hpp>

#include "kernel/analysis/foldability_report.hpp"

namespace rigidfold::report {

// Keys: assignment, verdict (the three-valued summary: rigidly-foldable, not-rigidly-foldable,
// undecided), verdict_class (the six classes of docs/DESIGN.md), rigidly_foldable (bool, or null
// when undecided), is_proof, folds_in_part, model, model_choice, reason, dof, dof_tolerance, tolerances,
// branches [{id, signs_match_assignment, driving_crease, range_deg, max_fold_deg, stopped_by,
// max_residual, points, mv_switches, ...}], bifurcations [{parameter, kind, angles_deg, ...}],
// mv_switches, obstruction (null or object), max_residual (rad), certificate_mismatch
// (relative), interference, seconds; holes_closed, reference_residual for sheets with holes.
nlohmann::ordered_json foldability_json(const FoldabilityReport& report);

}  // namespace rigidfold::report
