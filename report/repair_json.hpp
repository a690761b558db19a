#pragma once
// The JSON of a repair (design/repair/pattern_repair.hpp), as `rigidfold repair --json`
// prints it. Lengths in the pattern's unit, angles in radians.
#include <nlohmann/json.hpp>

#include "design/repair/crease_addition.hpp"
#include "design/repair/pattern_repair.hpp"
#include "design/repair/tolerance_study.hpp"

namespace rigidfold::report {

// Keys: termination, succeeded, message, before (foldability_json), after (foldability_json
// or null), letters ("keep" or "free"), modes {per_vertex, chosen_without_letters}, constraints {kawasaki, loop_gain,
// free_coordinates, fixed_vertices}, violation {kawasaki_before, kawasaki_after,
// loop_gain_before, loop_gain_after}, move {max, rms, worst_vertex, pattern_size,
// max_relative, rms_relative, per_vertex [[vertex, distance], ...] for the vertices that
// moved}, costliest [{kind, vertices, before, lambda}], iterations, least_move_converged,
// stationarity, seconds.
nlohmann::ordered_json repair_json(const RepairSummary& summary);

// Keys: termination ("already foldable", "creases added" or "undecided"), succeeded, message,
// before (foldability_json), candidates, checks, searched_up_to, budget_exhausted, found
// [{creases [{vertices [v0, v1], face, letter}], verdict_class, dof, certificate_mismatch}],
// seconds.
nlohmann::ordered_json crease_addition_json(const CreaseAdditionSummary& summary);

// Keys: samples, on_flat_development, foldable, fraction, interval_95 [low, high], verdicts {class: count},
// degree4_model, loops [{vertices, mean_abs_log_gain}], repairs, repair_move_over_sigma
// {median, max}, message, seconds. With the options: sigma, distribution, seed.
nlohmann::ordered_json tolerance_study_json(const ToleranceStudy& study, const ToleranceStudyOptions& options);

}  // namespace rigidfold::report
