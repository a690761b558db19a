#include "report/foldability_json.hpp"

#include "kernel/math/angle_units.hpp"

namespace rigidfold::report {
namespace {

using Json = nlohmann::ordered_json;

// The three-valued summary the JSON has always carried beside the class.
const char* summary(const FoldabilityReport& r) {
  if (r.foldable()) return to_string(Verdict::kRigidlyFoldable);
  if (r.not_foldable()) return to_string(Verdict::kNotRigidlyFoldable);
  return to_string(Verdict::kUndecided);
}

Json degrees(const Eigen::VectorXd& radians) {
  Json a = Json::array();
  for (Eigen::Index i = 0; i < radians.size(); ++i) a.push_back(to_degrees(radians[i]));
  return a;
}

Json switches_json(const std::vector<SignSwitch>& switches) {
  Json sw = Json::array();
  for (const SignSwitch& s : switches)
    sw.push_back({{"crease", s.crease}, {"driving_deg", to_degrees(s.driving_value)}, {"against_assignment", s.against_assignment}});
  return sw;
}

Json tolerances_json(const Tolerances& t) {
  return {{"residual_rad", t.residual},
          {"certificate_residual_rad", t.certificate_residual},
          {"rank_cut_relative", t.rank_cut},
          {"cone_rank_cut_relative", t.cone_rank_cut},
          {"sign_threshold_rad", t.sign_threshold},
          {"fold_limit_deg", to_degrees(t.fold_limit())},
          {"at_180_rad", t.at_fold_limit},
          {"placement_mismatch_relative", t.placement_mismatch},
          {"kawasaki_rad", t.flat_kawasaki},
          {"loop_gain_relative", t.loop_gain},
          {"evidence_floor_rad", t.evidence_floor}};
}

Json branch_json(const TracedBranch& b, const FoldabilityReport& r) {
  Json jb;
  jb["id"] = b.id;
  if (r.model == FoldabilityModel::kGivenStateHoleClosure) {
    jb["from_point"] = "given state";
    jb["sense"] = b.sense;
  } else {
    jb["from_point"] = b.from_point;
    jb["to_point"] = b.to_point >= 0 ? Json(b.to_point) : Json(nullptr);
  }
  jb["dof"] = b.dof_at_departure;
  jb["signs_match_assignment"] = r.assignment_used ? Json(b.signs_match_assignment) : Json(nullptr);
  if (!b.signs_match_assignment && b.first_wrong_crease >= 0) jb["first_crease_against_assignment"] = b.first_wrong_crease;
  jb["driving_crease"] = b.driving_edge;
  jb["range_deg"] = {to_degrees(b.driving_begin), to_degrees(b.driving_end)};
  jb["max_fold_deg"] = to_degrees(b.max_fold);
  jb["stopped_by"] = b.stop_text();
  if (b.stop_crease >= 0) jb["stop_crease"] = b.stop_crease;
  jb["max_residual"] = b.max_residual;
  jb["points"] = b.path.size();
  if (b.valid_points >= 0) jb["valid_points"] = b.valid_points;
  jb["mv_switches"] = switches_json(b.sign_switches);
  if (!b.linear_solver.empty()) {
    jb["linear_solver"] = b.linear_solver;
    jb["factorizations"] = b.factorizations;
  }
  if (r.model != FoldabilityModel::kMultiplierPropagation) {
    Json gi = nullptr;
    if (b.global_interference_faces.first >= 0) {
      gi = {{"faces", {b.global_interference_faces.first, b.global_interference_faces.second}}};
      if (b.global_interference_index >= 0) gi["from_driving_deg"] = to_degrees(b.global_interference_driving);
    }
    jb["global_interference"] = gi;
  }
  return jb;
}

Json point_json(std::size_t index, const BranchPoint& pt, const FoldabilityReport& r) {
  Json jp;
  jp["point"] = index;
  if (r.model == FoldabilityModel::kMultiplierPropagation) {
    jp["kind"] = "flat state: every vertex's two modes meet (singular; first-order rank inconclusive)";
    jp["parameter"] = 0.0;
    jp["angles_deg"] = degrees(pt.angles);
    return jp;
  }
  jp["kind"] = to_string(pt.kind);
  if (pt.kind == PointKind::kBifurcation) {
    jp["parameter"] = to_degrees(pt.parameter);
    jp["parameter_crease"] = pt.parameter_edge;
    jp["parameter_kind"] = "fold angle of crease " + std::to_string(pt.parameter_edge) + " (deg), the arriving branch's driving crease";
    jp["location_error_bound_rad"] = pt.location_error_bound;  // bound on |x - x*|_2 over the unknowns
    jp["sigma_ratio"] = pt.sigma_second_smallest / std::max(pt.sigma_max, 1e-300);
  } else {
    jp["parameter"] = 0.0;
  }
  jp["kernel_dimension"] = pt.kernel_dimension;
  jp["tangent_lines"] = pt.tangent_lines;
  jp["angles_deg"] = degrees(pt.angles);
  return jp;
}

Json obstruction_json(const FoldabilityObstruction& o) {
  Json j;
  j["kind"] = o.kind;
  j["message"] = o.message;
  if (o.exact) {
    const Obstruction& e = *o.exact;
    if (!e.cycle_vertices.empty()) j["loop_vertices"] = e.cycle_vertices;
    if (!e.cycle_creases.empty()) j["loop_creases"] = e.cycle_creases;
    if (e.vertex >= 0) j["vertex"] = e.vertex;
    if (e.crease >= 0) j["crease"] = e.crease;
    if (e.kind == Obstruction::Kind::kLoopGain) {
      j["loop_gain"] = e.loop_gain;
      j["loop_gain_defect"] = e.defect;
    }
  }
  if (o.least_residual >= 0) j["least_residual"] = o.least_residual;
  if (!o.worst_vertices.empty() || o.starts_tried >= 0) {
    Json worst = Json::array();
    for (auto [v, res] : o.worst_vertices) worst.push_back({{"vertex", v}, {"residual", res}});
    j["worst_vertices"] = worst;
  }
  if (o.crease_against_assignment >= 0) j["crease_against_assignment"] = o.crease_against_assignment;
  if (o.starts_tried >= 0) {
    j["starts_tried"] = o.starts_tried;
    j["starts_converged_against_assignment"] = o.starts_converged_against_assignment;
  }
  return j;
}

}  // namespace

Json foldability_json(const FoldabilityReport& r) {
  Json j;
  j["assignment"] = r.assignment_used ? "as given (sign constraints)" : "ignored";
  j["verdict"] = summary(r);
  j["verdict_class"] = to_string(r.verdict);
  j["rigidly_foldable"] = r.foldable() ? Json(true) : r.not_foldable() ? Json(false) : Json(nullptr);
  j["is_proof"] = r.is_proof;
  j["folds_in_part"] = r.folds_in_part;
  j["model"] = r.model_name;
  j["model_choice"] = r.model_choice;
  j["reason"] = r.reason;
  j["dof"] = r.dof;
  j["dof_tolerance"] = r.dof_basis;
  j["tolerances"] = tolerances_json(r.tolerances);
  j["coordinate_precision"] = r.coordinate_precision;
  if (r.model == FoldabilityModel::kGivenStateHoleClosure) {
    j["holes_closed"] = r.holes_closed;
    j["reference_residual"] = r.reference_residual;
  }
  if (r.certificate_mismatch) j["certificate_mismatch"] = *r.certificate_mismatch;
  if (r.certificate_max_fold) j["certificate_max_fold_deg"] = to_degrees(*r.certificate_max_fold);
  if (r.max_loop_gain_defect) j["max_loop_gain_defect"] = *r.max_loop_gain_defect;
  Json branches = Json::array();
  for (const TracedBranch& b : r.branches) branches.push_back(branch_json(b, r));
  j["branches"] = branches;
  if (r.model == FoldabilityModel::kGeneralLoopClosure)
    j["branch_exploration"] = r.branches_explored ? Json({{"points", r.points.size()}, {"branches", r.branches.size()},
                                                          {"seconds", r.exploration_seconds},
                                                          {"work_budget_exhausted", r.exploration_budget_exhausted}})
                                                  : Json(r.exploration_note);
  Json points = Json::array();
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const PointKind k = r.points[i].kind;
    if (k == PointKind::kFlat || k == PointKind::kBifurcation) points.push_back(point_json(i, r.points[i], r));
  }
  for (const SingularPoint& s : r.unrefined_singular_points)
    points.push_back({{"parameter", to_degrees(s.driving_value)},
                      {"parameter_kind", "driving crease fold angle (deg)"},
                      {"angles_deg", degrees(s.angles)},
                      {"kind", "singular point (bordered determinant changes sign); not refined (pattern too large for the branch explorer)"}});
  j["bifurcations"] = points;
  if (r.model == FoldabilityModel::kGeneralLoopClosure) j["mv_switches"] = switches_json(r.sign_switches);
  j["obstruction"] = r.obstruction ? obstruction_json(*r.obstruction) : Json(nullptr);
  if (r.input_precision) {
    const auto& ip = *r.input_precision;
    if (ip.witness_kind == "coordinates" || ip.witness_kind == "drawn points")
      j["input_precision"] = {{"witness", ip.witness_kind == "coordinates"
                                              ? "flat-foldable pattern within the rounding of the coordinates"
                                              : "flat-foldable pattern, each vertex within the box of the points drawn for it grown by their rounding"},
                              {"decimal_places", ip.decimal_places},
                              {"significant_digits", ip.significant_digits},
                              {"coordinate_rounding", ip.coordinate_rounding},
                              {"kawasaki_defect_as_read_rad", ip.given_residual},
                              {"witness_max_coordinate_move", ip.max_coordinate_move},
                              {"witness_move_over_rounding", ip.max_change_ratio},
                              {"defect_explained_by_rounding", ip.explained},
                              {"exact_data_verdict", ip.exact_data_verdict}};
    else
      j["input_precision"] = {{"witness", "sectors within their rounding bounds closing the given state"},
                              {"decimal_places", ip.decimal_places},
                              {"significant_digits", ip.significant_digits},
                              {"coordinate_rounding", ip.coordinate_rounding},
                              {"given_state_closure_gap_rad", ip.given_residual},
                              {"sector_rounding_bound_rad", ip.max_sector_bound},
                              {"witness_max_sector_change_rad", ip.max_sector_change},
                              {"witness_change_over_bound", ip.max_change_ratio},
                              {"gap_explained_by_rounding", ip.explained},
                              {"exact_data_verdict", ip.exact_data_verdict}};
    if (ip.loop_gain_enclosure) {
      // The witness's failing cycle, over every pattern within the boxes.
      j["input_precision"]["loop_gain_enclosure"] = {(*ip.loop_gain_enclosure)[0], (*ip.loop_gain_enclosure)[1]};
      j["input_precision"]["loop_gain_proof"] =
          ip.loop_gain_proof_note.empty() ? Json("proven: the enclosure excludes 1") : Json(ip.loop_gain_proof_note);
    }
  }
  if (r.strictness)
    j["strictness"] = {{"strict", r.strictness->strict},
                       {"flat_lettered_creases", r.strictness->flat_lettered},
                       {"flat_below_fraction_of_max_fold", r.strictness->flat_fraction},
                       {"strict_obstruction_vertices", r.strictness->strict_obstruction_vertices},
                       {"strict_obstruction", r.strictness->strict_obstruction_vertices.empty()
                                                  ? "none found"
                                                  : "two straight lettered crease lines cross at these degree-4 vertices: "
                                                    "no motion from flat folds all four creases there (proof)"},
                       {"meaning", r.strictness->strict ? "every M/V crease folds (strict)"
                                                        : "weak: the listed M/V creases stay flat"},
                       {"strict_verdict", strict_verdict(*r.strictness)}};
  if (!r.certificate_samples.empty()) {
    // The certifying path, sampled, for replay by other tools (a multi-DOF path is not
    // exposed by `trace`).
    Json states = Json::array();
    for (const Eigen::VectorXd& rho : r.certificate_samples) states.push_back(degrees(rho));
    j["certificate_states_deg"] = std::move(states);
  }
  if (!r.search_evidence.empty()) {
    Json ev = Json::array();
    for (const AmplitudeEvidence& e : r.search_evidence)
    {
      Json one = {{"amplitude_rad", e.amplitude},
                  {"least_residual_rad", e.least_residual},
                  {"driving_crease", e.driving_edge},
                  {"explained_by_rounding", e.explained_by_rounding}};
      if (e.norm_search_residual >= 0) one["norm_search_residual_rad"] = e.norm_search_residual;
      if (e.rounding_ratio >= 0) one["rounding_ratio"] = e.rounding_ratio;
      if (e.polished) one["newton_polish"] = e.polish_outcome;
      ev.push_back(std::move(one));
    }
    j["search_evidence"] = {{"sign_respecting_least_squares", ev},
                            {"growth_exponent", r.residual_growth_exponent},
                            {"evidence_floor_rad", r.tolerances.evidence_floor}};
    if (const ScaledNormSearch& sn = r.scaled_norm_search; sn.starts > 0)
      j["search_evidence"]["at_the_patterns_scale"] = {{"norm_rad", sn.amplitude},
                                                       {"starts", sn.starts},
                                                       {"least_residual_rad", sn.least_residual},
                                                       {"is_evidence", false}};
  }
  j["max_residual"] = r.max_residual;
  j["interference"] = r.interference_checked;
  if (!r.pieces.empty()) {
    Json pieces = Json::array();
    for (const auto& v : r.pieces)
      pieces.push_back({{"faces", v.faces}, {"creases", v.creases}, {"interior_vertices", v.interior_vertices},
                        {"verdict_class", to_string(v.verdict)}, {"is_proof", v.is_proof}, {"dof", v.dof},
                        {"model", v.model_name}, {"reason", v.reason}});
    j["pieces"] = std::move(pieces);
  }
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace rigidfold::report
