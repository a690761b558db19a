#pragma once
// The text `rigidfold check` prints for a foldability report (its JSON: foldability_json.hpp).
#include <string>

#include "kernel/analysis/foldability_report.hpp"

namespace rigidfold::report {

// The verdict and model, the reason, the precision assumed; for a (partial) yes the DOF,
// residual and certificate; the obstruction; the branches from a given state; the explorer's
// branches and bifurcations.
std::string foldability_text(const std::string& file, const FoldabilityReport& report);

}  // namespace rigidfold::report
