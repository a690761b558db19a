#pragma once
// The JSON of a metamaterial run (design/metamaterial/metamaterial_request.hpp), as
// `rigidfold metamaterial --json` prints it (before its "provenance") and as the Python
// rigidfold.metamaterial returns it. Serialises only: every value comes from the run.
//
// A unit (--unit): unit, parameters {alpha_deg, a, b, c} (square twist) or {alpha_deg, beta_deg,
// l} (elements), fold_angle (what the fold and second angles are), samples, dimensions [3 names],
// ratios [2 names], height_maximum ({fold_deg, height} or null), height_stationary_points,
// sign_changes [{ratio, kind, fold_deg, negative_after}], ratios_defined {ratio: bool}, checks
// {max_constraint_residual, max_derivative_error, constraint_tolerance, derivative_tolerance},
// rows [{fold_deg, second_angle_deg, <dimensions>, d<dimension>_per_rad, <ratios>,
// constraint_residual, derivative_error}], and with the cross-check cross_check {sheet,
// twists_per_side, creases, traced_steps, compared_steps, theta_deg_range, tolerance,
// max_closure_residual, max_null_singular_value, min_next_singular_value, max_geometry_defect,
// max_phi_difference_rad, max_dimension_difference, max_derivative_difference,
// max_ratio_difference, nu_SL_negative, stationary_points [{kind, theta_deg_traced,
// theta_deg_closed, height_traced, height_closed, nu_HL_traced, nu_HL_before, nu_HL_after}],
// max_stationary_theta_difference_rad, max_stationary_height_difference, height_maximum
// {theta_deg_traced, theta_deg_closed, height_traced, height_closed}, seconds}.
//
// A stack (--stacked): stacked_metamaterial, parameters {alpha_deg, beta_deg, l, layers, steps},
// input, creases_per_layer, bonding_vertices_per_bond, tolerances {closed_form, bond,
// closure_residual}, max_closure_residual, max_bond_gap, max_dimension_difference,
// max_ratio_difference, phi_theta_relation {inverse_3_26_max_difference_rad,
// printed_3_26_max_difference_rad} (metamaterial 4 only), height_maximum ({phi_II_deg,
// theta_II_deg, height, negative_3d_before, in_negative_out_positive_after} or null), states
// [{phi_deg, theta_deg, W, L, H, W_closed, L_closed, H_closed, W_difference, L_difference,
// H_difference, nu_in, nu_out, nu_in_closed, nu_out_closed, bond_gap}], seconds.
// Numbers round-trip exactly; "seconds" is wall time and differs between runs.
#include <nlohmann/json.hpp>

#include "design/metamaterial/metamaterial_request.hpp"

namespace rigidfold::report {

// The unit's or the stack's object, whichever the run holds.
nlohmann::ordered_json metamaterial_json(const metamaterial::MetamaterialRun& run);

nlohmann::ordered_json metamaterial_unit_json(const metamaterial::MetamaterialUnitRun& run);
nlohmann::ordered_json stacked_metamaterial_json(const metamaterial::StackedMetamaterialRun& run);

}  // namespace rigidfold::report
