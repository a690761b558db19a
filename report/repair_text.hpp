#pragma once
// The text `rigidfold repair`, `check --tolerance-study` and `fold --target` print, for the
// reports of design/repair and design/target (the JSON: repair_json.hpp,
// nearest_state_json.hpp). Only writes what the reports say.
#include <string>

#include "design/repair/crease_addition.hpp"
#include "design/repair/pattern_repair.hpp"
#include "design/repair/tolerance_study.hpp"
#include "design/target/nearest_state.hpp"

namespace rigidfold::report {

// The termination, the input's check, the constraints and their violation before and after,
// the move, the costliest constraints, the repaired pattern's check.
std::string repair_text(const std::string& file, const RepairSummary& summary);
// The input's check, the candidates, each addition found with its check.
std::string crease_addition_text(const std::string& file, const CreaseAdditionSummary& summary);
// The fraction, the verdicts, the loops opened most, the repair moves.
std::string tolerance_study_text(const std::string& file, const ToleranceStudy& study);
// One line: the nearest closed state's distance from the target, residuals, iterations.
std::string nearest_state_text(const std::string& target, const NearestState& state);

}  // namespace rigidfold::report
