#pragma once
// The JSON of an M-V assignment enumeration (kernel/analysis/assignment_enumeration.hpp), as
// `rigidfold assignments --json` prints it and rigidfold.enumerate_assignments returns it.
// Serialises only.
//
// Keys: file, creases (the edge of each letter position), symmetry_order, symmetry_rotations,
// branch (the subtree searched; [] for the whole search), complete, search_steps, assignments,
// classes (their count; null when the search was stopped), classes_reached (the representatives
// reached, always), classes_with_verdict, foldable_classes, not_foldable_classes,
// undecided_classes, no_assignment_because {vertex, reason} (only when a vertex blocks every
// assignment), listed [{letters, orbit_size, and with a verdict: verdict, is_proof, dof,
// reason}], seconds.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernel/analysis/assignment_enumeration.hpp"

namespace rigidfold::report {

nlohmann::ordered_json assignment_enumeration_json(const AssignmentEnumeration& r, const std::string& file,
                                                   const std::vector<int>& branch);

}  // namespace rigidfold::report
