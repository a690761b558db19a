#include "report/metamaterial_json.hpp"

#include <string>
#include <vector>

#include "kernel/math/angle_units.hpp"

namespace rigidfold::report {
namespace {

using Json = nlohmann::ordered_json;
using metamaterial::MetamaterialUnit;

void add_unit_parameters(const metamaterial::MetamaterialParams& p, Json& j) {
  if (p.unit == MetamaterialUnit::kSquareTwist) {
    j["parameters"] = {{"alpha_deg", to_degrees(p.square_twist.alpha)}, {"a", p.square_twist.a}, {"b", p.square_twist.b}, {"c", p.square_twist.c}};
    j["fold_angle"] = "theta_deg: fold magnitude of the S-direction pleats; second_angle_deg: phi of the L-direction pleats by (3-31)";
    return;
  }
  j["parameters"] = {{"alpha_deg", to_degrees(p.element.alpha)}, {"beta_deg", to_degrees(p.element.beta)}, {"l", p.element.l}};
  j["fold_angle"] = p.unit == MetamaterialUnit::kElement3
                        ? "rho_deg = 180 - phi of A2B2; second_angle_deg: dihedral theta of B4B5 by (3-26)"
                        : "rho_deg = 180 - phi of A2B2; second_angle_deg: the dihedral phi of A2B2";
}

// Each row's keys are the unit's own dimension and ratio names (L, S, H or W, L, H).
Json unit_rows_json(const metamaterial::MetamaterialTable& t, const std::vector<std::string>& dn, const std::vector<std::string>& rn) {
  Json rows = Json::array();
  for (const auto& r : t.rows) {
    Json o;
    o["fold_deg"] = to_degrees(r.fold);
    o["second_angle_deg"] = to_degrees(r.second_angle);
    o[dn[0]] = r.x;
    o[dn[1]] = r.y;
    o[dn[2]] = r.H;
    o["d" + dn[0] + "_per_rad"] = r.dx;
    o["d" + dn[1] + "_per_rad"] = r.dy;
    o["d" + dn[2] + "_per_rad"] = r.dH;
    o[rn[0]] = r.nu_in;
    o[rn[1]] = r.nu_out;
    o["constraint_residual"] = r.constraint_residual;
    o["derivative_error"] = r.derivative_error;
    rows.push_back(o);
  }
  return rows;
}

Json cross_check_json(const metamaterial::SquareTwistCrossCheck& cc) {
  Json stationary = Json::array();
  for (const auto& q : cc.stationary)
    stationary.push_back({{"kind", q.maximum ? "maximum" : "minimum"},
                          {"theta_deg_traced", to_degrees(q.theta_traced)},
                          {"theta_deg_closed", to_degrees(q.theta_closed)},
                          {"height_traced", q.height_traced},
                          {"height_closed", q.height_closed},
                          {"nu_HL_traced", q.nu_HL_at},
                          {"nu_HL_before", q.nu_HL_before},
                          {"nu_HL_after", q.nu_HL_after}});
  return {{"sheet", "3x3 square-twist tessellation, layout type3-rows (T1), traced by the general loop-closure solver"},
          {"twists_per_side", cc.twists_per_side},
          {"creases", cc.creases},
          {"traced_steps", cc.traced_steps},
          {"compared_steps", cc.compared_steps},
          {"theta_deg_range", {cc.theta_range_deg[0], cc.theta_range_deg[1]}},
          {"tolerance", metamaterial::kCrossCheckTolerance},
          {"max_closure_residual", cc.max_residual},
          {"max_null_singular_value", cc.max_null_singular},
          {"min_next_singular_value", cc.min_next_singular},
          {"max_geometry_defect", cc.max_geometry_defect},
          {"max_phi_difference_rad", cc.max_phi_difference},
          {"max_dimension_difference", cc.max_dimension_difference},
          {"max_derivative_difference", cc.max_derivative_difference},
          {"max_ratio_difference", cc.max_ratio_difference},
          {"nu_SL_negative", cc.nu_SL_negative},
          {"stationary_points", stationary},
          {"max_stationary_theta_difference_rad", cc.max_stationary_theta_difference},
          {"max_stationary_height_difference", cc.max_stationary_height_difference},
          {"height_maximum", {{"theta_deg_traced", to_degrees(cc.height_maximum_theta_traced)},
                              {"theta_deg_closed", to_degrees(cc.height_maximum_theta_closed)},
                              {"height_traced", cc.height_maximum_traced},
                              {"height_closed", cc.height_maximum_closed}}},
          {"seconds", cc.seconds}};
}

Json stack_states_json(const metamaterial::StackedMetamaterialCheck& c) {
  Json states = Json::array();
  for (const auto& r : c.states)
    states.push_back({{"phi_deg", to_degrees(r.phi)}, {"theta_deg", to_degrees(r.theta)},
                      {"W", r.W}, {"L", r.L}, {"H", r.H},
                      {"W_closed", r.W_closed}, {"L_closed", r.L_closed}, {"H_closed", r.H_closed},
                      {"W_difference", r.W - r.W_closed}, {"L_difference", r.L - r.L_closed}, {"H_difference", r.H - r.H_closed},
                      {"nu_in", r.nu_in}, {"nu_out", r.nu_out}, {"nu_in_closed", r.nu_in_closed}, {"nu_out_closed", r.nu_out_closed},
                      {"bond_gap", r.bond_gap}});
  return states;
}

}  // namespace

nlohmann::ordered_json metamaterial_unit_json(const metamaterial::MetamaterialUnitRun& run) {
  const metamaterial::MetamaterialParams& p = run.params;
  const metamaterial::MetamaterialTable& t = run.table;
  const std::vector<std::string> dn = metamaterial::dimension_names(p.unit);
  const std::vector<std::string> rn = metamaterial::ratio_names(p.unit);
  Json j;
  j["unit"] = metamaterial::unit_name(p.unit);
  add_unit_parameters(p, j);
  j["samples"] = p.samples;
  j["dimensions"] = dn;
  j["ratios"] = rn;
  if (t.has_height_maximum)
    j["height_maximum"] = {{"fold_deg", to_degrees(t.height_maximum_fold)}, {"height", t.height_maximum}};
  else
    j["height_maximum"] = nullptr;
  j["height_stationary_points"] = t.height_stationary_points;
  Json changes = Json::array();
  for (const auto& c : t.sign_changes)
    changes.push_back({{"ratio", c.ratio == "nu_in" ? rn[0] : rn[1]},
                       {"kind", c.kind},
                       {"fold_deg", to_degrees(c.fold)},
                       {"negative_after", c.negative_after}});
  j["sign_changes"] = changes;
  j["ratios_defined"] = {{rn[0], t.nu_in_defined}, {rn[1], t.nu_out_defined}};
  j["checks"] = {{"max_constraint_residual", t.max_constraint_residual},
                 {"max_derivative_error", t.max_derivative_error},
                 {"constraint_tolerance", metamaterial::kConstraintTolerance},
                 {"derivative_tolerance", metamaterial::kDerivativeTolerance}};
  j["rows"] = unit_rows_json(t, dn, rn);
  if (run.cross_check) j["cross_check"] = cross_check_json(*run.cross_check);
  return j;
}

nlohmann::ordered_json stacked_metamaterial_json(const metamaterial::StackedMetamaterialRun& run) {
  const metamaterial::StackedMetamaterialCheck& c = run.check;
  Json j;
  j["stacked_metamaterial"] = c.params.metamaterial;
  j["parameters"] = {{"alpha_deg", run.alpha_deg}, {"beta_deg", run.beta_deg}, {"l", c.params.l},
                     {"layers", c.options.layers}, {"steps", c.options.steps}};
  j["input"] = "phi_deg: dihedral of the seed's A2B2 (180 = flat); theta_deg: metamaterial 4's B4B5 (else = phi)";
  j["creases_per_layer"] = c.creases;
  j["bonding_vertices_per_bond"] = c.bonding_vertices;
  j["tolerances"] = {{"closed_form", metamaterial::kStackTolerance}, {"bond", metamaterial::kStackBond},
                     {"closure_residual", metamaterial::kStackResidual}};
  j["max_closure_residual"] = c.max_residual;
  j["max_bond_gap"] = c.max_bond_gap;
  j["max_dimension_difference"] = c.max_dimension_difference;
  j["max_ratio_difference"] = c.max_ratio_difference;
  if (c.params.metamaterial == 4) {
    j["phi_theta_relation"] = {{"inverse_3_26_max_difference_rad", c.max_relation_difference},
                               {"printed_3_26_max_difference_rad", c.printed_relation_difference}};
  }
  if (c.has_maximum)
    j["height_maximum"] = {{"phi_II_deg", to_degrees(c.phi_II)}, {"theta_II_deg", to_degrees(c.theta_II)},
                           {"height", c.height_max}, {"negative_3d_before", c.negative_3d_before},
                           {"in_negative_out_positive_after", c.in_negative_out_positive_after}};
  else
    j["height_maximum"] = nullptr;
  j["states"] = stack_states_json(c);
  j["seconds"] = c.seconds;
  return j;
}

nlohmann::ordered_json metamaterial_json(const metamaterial::MetamaterialRun& run) {
  return run.stacked ? stacked_metamaterial_json(*run.stacked) : metamaterial_unit_json(*run.unit);
}

}  // namespace rigidfold::report
