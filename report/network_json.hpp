#pragma once
// The JSON of a network of spherical linkages and its analysis
// (kernel/network/network_analysis.hpp), as `rigidfold network --json` prints it (before its
// "provenance") and as the Python rigidfold.network returns it. Serialises only: every value,
// verdict and flag comes from the analysis.
//
// Keys: network (the input's path as given), description (only when the input has one), model,
// joints, linkages, equations, closure_tolerance_rad, rank_tolerance_relative,
// flat_vertices_2_33 [linkage names], configuration {input_joint, input_start_deg,
// closed_at_input_start, starts; when closed residual_rad and joints_deg {joint: degrees in
// (-180, 180]}; when not least_residual_rad}, mobility (only when closed) {dof, dof_input_held,
// rank, sigma_max, sigma_kept, sigma_dropped, method, input_moves_1e-3_rad}, verdict,
// verdict_class, crease_pattern (only when one was built) {file, vertices, creases,
// central_angle_sum_deg, vertex_linkages, layout {linkage: "as given" or "reversed"}, letters,
// vertex_loop_residual_rad}, trace (only when traced) {steps, complete, stop_reason (only when
// not complete), points [{input_deg, outputs_deg {joint: degrees in (-180, 180]},
// residual_rad, dof}]}. Numbers round-trip exactly.
#include <nlohmann/json.hpp>
#include <string>

#include "kernel/network/network_analysis.hpp"

namespace rigidfold::report {

// A joint angle as the JSON and the CLI's text print it: degrees in (-180, 180].
double joint_angle_degrees(double radians);

// network_path: the input as the user named it; crease_pattern_path: where the crease pattern
// was written (the "file" of crease_pattern; unused without one).
nlohmann::ordered_json network_json(const std::string& network_path, const NetworkSpec& spec, const NetworkAnalysis& analysis,
                                    const NetworkAnalysisOptions& options, const std::string& crease_pattern_path);

}  // namespace rigidfold::report
