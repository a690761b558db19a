#pragma once
// Small helpers shared by the crease-pattern generators (not a user-facing concept).
//
// - Parameter checks throw rigidfold::InputError whose place() is the name of the offending
//   parameter as spelled in the generator's Params struct (e.g. "alpha"); the CLI maps that
//   name to its flag.
// - finish_pattern() stamps the FOLD metadata and validates the pattern.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

// Throws InputError(param, what) unless ok.
void require(bool ok, const std::string& param, const std::string& what);

// Parses FOLD assignment letters (M, V, F, U, B, C, J; case-insensitive), ignoring spaces,
// commas and underscores. Throws InputError(param, ...) on any other character.
std::vector<Assignment> parse_assignment_letters(const std::string& letters, const std::string& param);
// The letters of an assignment vector, e.g. "MVVM".
std::string assignment_letters(const std::vector<Assignment>& assignment);

// Sets file_spec, file_creator, file_title, file_classes, frame_title, frame_classes,
// frame_attributes and "rigidfold:generator" (the parameters, for reproducibility) in
// pattern.extra, then runs complete_and_validate (which derives faces if none are given).
// Returns the validated pattern.
CreasePattern finish_pattern(CreasePattern pattern, const std::string& title, const std::string& frame_title,
                             const nlohmann::ordered_json& generator_parameters);

// The same for a pattern given directly in 3D (tubes): frame_classes "foldedForm",
// frame_attributes "3D", coords_2d false; after validation every crease that is not B
// gets its reference fold angle (reference_fold_angles) as edges_foldAngle and the letter V
// where that angle is >= 0, M otherwise.
CreasePattern finish_folded_pattern(CreasePattern pattern, const std::string& title, const std::string& frame_title,
                                    const nlohmann::ordered_json& generator_parameters);

// Degrees (to_degrees, kernel/math/angle_units.hpp) rounded to 1e-9 (for metadata: 30, not 29.999999999999996).
double deg_rounded(double radians);

}  // namespace rigidfold::generators
