#pragma once
// The JSON of the SORCE front door's parts (design/sorce/sorce_design.hpp), as `rigidfold
// sorce --json` prints them. Serialises only. Infinite convexities (pivots, cusps) and
// undefined figures are written as null: JSON has no infinity.
//
// crease_json keys: edge, left_face, right_face, folds; when it folds also s0, arc_length
// [left, right], convexity_left / convexity_right [min, max], concave_left / concave_right
// [[t0, t1]...], cusps, ill_behaved, stationary, pivot_at_start, pivot_at_end, protrusion
// [left, right], rolling_residual, contact_residual, end_separation, stacks, consistency,
// pitch, contact_3d, rolled_gamma, rolled_translation.
// checks_json keys: consistency, pitch, closure_knots, closure_samples, contact_3d,
// rolling_residual, contact_residual, rolled_gamma, rolled_translation, not_rolled,
// flat_folded_end, all_stack, slab_interference [{t, faces}], interference_skipped_faces.
// cam_interference_json keys: checked, samples, passed, pairs_tested,
// rolling_partner_pairs_skipped, collisions [{t, faces, cam_edges}] (edge -1: the panel's slab),
// first (the first collision, when any).
// optimization_json keys: algorithm, stop_reason, evaluations, feasible, improved,
// figure_of_merit, min_convexity, faces (the faces searched, 3 coefficients each), coefficients,
// binding [{name, index, value, bound}].
#include <nlohmann/json.hpp>
#include <vector>

#include "design/sorce/sorce_cam_interference.hpp"
#include "design/sorce/sorce_optimize.hpp"
#include "design/sorce/sorce_pattern.hpp"

namespace rigidfold::report {

// x, or null when it is not finite.
nlohmann::ordered_json finite_or_null(double x);
nlohmann::ordered_json crease_json(const sorce::CreaseJoint& joint);
nlohmann::ordered_json checks_json(const sorce::PatternChecks& checks);
nlohmann::ordered_json cam_interference_json(const sorce::CamInterference& interference);
nlohmann::ordered_json optimization_json(const sorce::OffsetDesign& design, const std::vector<int>& faces);

}  // namespace rigidfold::report
