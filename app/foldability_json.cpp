#include "app/foldability_json.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include "kernel/analysis/branch_explorer.hpp"
#include "kernel/analysis/general_verdict.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/analysis/reference_mobility.hpp"
#include "kernel/closure/vertex_residuals.hpp"

namespace rigidfold::cli {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kDeg = 180.0 / std::numbers::pi;

// The check's "rigidly_foldable": true, false, or null when the models available did not decide.
Json rigidly_foldable_json(Verdict v) {
  if (v == Verdict::kRigidlyFoldable) return true;
  if (v == Verdict::kNotRigidlyFoldable) return false;
  return nullptr;
}

Json obstruction_json(const Obstruction& o) {
  Json j;
  j["kind"] = to_string(o.kind);
  j["message"] = o.message;
  if (!o.cycle_vertices.empty()) j["loop_vertices"] = o.cycle_vertices;
  if (!o.cycle_creases.empty()) j["loop_creases"] = o.cycle_creases;
  if (o.vertex >= 0) j["vertex"] = o.vertex;
  if (o.crease >= 0) j["crease"] = o.crease;
  if (o.kind == Obstruction::Kind::kLoopGain) {
    j["loop_gain"] = o.loop_gain;
    j["loop_gain_defect"] = o.defect;
  }
  return j;
}

// The keys every traced branch reports, from the branch explorer (BranchTrace) or from a
// sheet's given state (MobilityBranch): both carry these fields under the same names.
template <class TracedBranch>
void add_traced_branch_keys(Json& jb, const TracedBranch& b, bool ignore_assignment) {
  jb["signs_match_assignment"] = ignore_assignment ? Json(nullptr) : Json(b.signs_match_assignment);
  if (!b.signs_match_assignment && b.first_wrong_crease >= 0) jb["first_crease_against_assignment"] = b.first_wrong_crease;
  jb["driving_crease"] = b.driving_edge;
  jb["range_deg"] = {b.driving_begin * kDeg, b.driving_end * kDeg};
  jb["max_fold_deg"] = b.max_fold * kDeg;
  jb["stopped_by"] = b.stopped_by;
  if (b.stop_crease >= 0) jb["stop_crease"] = b.stop_crease;
  jb["max_residual"] = b.max_residual;
  jb["points"] = b.path.size();
  Json sw = Json::array();
  for (const SignSwitch& s : b.sign_switches)
    sw.push_back({{"crease", s.crease}, {"driving_deg", s.driving_value * kDeg}, {"against_assignment", s.against_assignment}});
  jb["mv_switches"] = sw;
}

// The general loop-closure solver's verdict: a traced branch from near flat (yes), or the
// least residual reached at a small fold (no: numerical evidence, not a proof).
Json general_json(const CreasePattern& p, const Topology& t, bool ignore_assignment, const std::string& why_general) {
  GeneralVerdictOptions options;
  options.use_assignment = !ignore_assignment;
  const GeneralVerdict g = general_verdict(p, t, options);
  Json j;
  j["assignment"] = ignore_assignment ? "ignored" : "as given (sign constraints)";
  j["verdict"] = to_string(g.verdict);
  j["rigidly_foldable"] = rigidly_foldable_json(g.verdict);
  j["model"] = g.model;
  j["model_choice"] = why_general;
  j["reason"] = g.reason;
  j["is_proof"] = g.verdict == Verdict::kRigidlyFoldable || g.is_proof;
  j["dof"] = g.verdict == Verdict::kRigidlyFoldable ? std::max(g.dof, 0) : 0;
  j["dof_tolerance"] = "rank of the closure Jacobian at the traced point, singular values below 1e-9 x largest dropped";
  // Every branch through the flat state and its bifurcations, where the pattern is small
  // enough for the dense second-order analysis (branch_explorer.hpp).
  BranchExplorerOptions xo;
  const BranchExploration x = explore_branches(p, t, xo);
  Json branches = Json::array();
  Json bifurcations = Json::array();
  bool explored_yes = false;
  if (x.applicable) {
    for (const BranchTrace& b : x.branches) {
      Json jb;
      jb["id"] = b.id;
      jb["from_point"] = b.from_point;
      jb["to_point"] = b.to_point >= 0 ? Json(b.to_point) : Json(nullptr);
      jb["dof"] = b.dof_at_departure;
      add_traced_branch_keys(jb, b, ignore_assignment);
      jb["global_interference"] =
          b.global_interference_index < 0
              ? Json(nullptr)
              : Json({{"from_driving_deg", b.global_interference_driving * kDeg},
                      {"faces", {b.global_interference_faces.first, b.global_interference_faces.second}}});
      branches.push_back(jb);
      // A branch from flat with every letter kept (or letters ignored), no face crossing,
      // reaching the certificate fold: a rigid folding motion.
      const bool letters_ok = ignore_assignment || b.signs_match_assignment;
      int valid = static_cast<int>(b.path.size());
      if (b.global_interference_index >= 0) valid = b.global_interference_index;
      double reach = 0;
      for (int k = 0; k < valid; ++k) reach = std::max(reach, std::min(b.path[k].cwiseAbs().maxCoeff(), std::numbers::pi));
      if (b.from_point == 0 && letters_ok && b.dof_at_departure == 1 && reach >= options.certificate_fold &&
          b.max_residual <= 1e-10)
        explored_yes = true;
    }
    for (std::size_t i = 0; i < x.points.size(); ++i) {
      const BranchPoint& pt = x.points[i];
      if (pt.kind != "flat" && pt.kind != "bifurcation") continue;
      std::vector<double> deg(pt.angles.data(), pt.angles.data() + pt.angles.size());
      for (double& d : deg) d *= kDeg;
      Json jp;
      jp["point"] = i;
      jp["kind"] = pt.kind;
      if (pt.kind == "bifurcation") {
        jp["parameter"] = pt.parameter * kDeg;
        jp["parameter_crease"] = pt.parameter_edge;
        jp["parameter_kind"] = "fold angle of crease " + std::to_string(pt.parameter_edge) + " (deg), the arriving branch's driving crease";
        jp["location_uncertainty_rad"] = pt.parameter_uncertainty;
        jp["sigma_ratio"] = pt.sigma_second_smallest / std::max(pt.sigma_max, 1e-300);
      } else {
        jp["parameter"] = 0.0;
      }
      jp["kernel_dimension"] = pt.kernel_dimension;
      jp["tangent_lines"] = pt.tangent_lines;
      jp["angles_deg"] = deg;
      bifurcations.push_back(jp);
    }
  } else {
    for (const auto& s : g.singular_points) {
      std::vector<double> deg(s.angles.data(), s.angles.data() + s.angles.size());
      for (double& d : deg) d *= kDeg;
      bifurcations.push_back({{"parameter", s.driving_value * kDeg}, {"parameter_kind", "driving crease fold angle (deg)"},
                              {"angles_deg", deg}, {"kind", "singular point (bordered determinant changes sign); not refined (pattern too large for the branch explorer)"}});
    }
    if (g.verdict == Verdict::kRigidlyFoldable)
      branches.push_back({{"id", 0},
                          {"signs_match_assignment", ignore_assignment ? Json(nullptr) : Json(g.sign_switches.empty())},
                          {"range_deg", {0.0, g.max_fold * kDeg}},
                          {"stopped_by", g.stopped_by},
                          {"max_residual", g.max_residual},
                          {"driving_crease", g.driving_crease},
                          {"points", g.path.size()}});
  }
  if (g.verdict == Verdict::kRigidlyFoldable) j["certificate_mismatch"] = g.certificate_mismatch;
  if (g.verdict != Verdict::kRigidlyFoldable && explored_yes) {
    j["verdict"] = to_string(Verdict::kRigidlyFoldable);
    j["rigidly_foldable"] = true;
    j["reason"] = "a branch leaving the flat state keeps every letter and reaches the certificate fold (branch explorer); " + g.reason;
    j["dof"] = 1;
  }
  j["branches"] = branches;
  j["branch_exploration"] = x.applicable ? Json({{"points", x.points.size()}, {"branches", x.branches.size()}, {"seconds", x.seconds}})
                                         : Json(x.why_not);
  j["bifurcations"] = bifurcations;
  Json switches = Json::array();
  for (const auto& s : g.sign_switches)
    switches.push_back({{"crease", s.crease}, {"driving_deg", s.driving_value * kDeg}, {"against_assignment", s.against_assignment}});
  j["mv_switches"] = switches;
  if (g.verdict == Verdict::kNotRigidlyFoldable) {
    Json o;
    o["kind"] = "no folded point found near flat";
    o["message"] = g.reason;
    o["least_residual"] = g.least_residual;
    Json worst = Json::array();
    for (auto [v, r] : g.worst_vertices) worst.push_back({{"vertex", v}, {"residual", r}});
    o["worst_vertices"] = worst;
    if (g.wrong_sign_crease >= 0) o["crease_against_assignment"] = g.wrong_sign_crease;
    o["starts_tried"] = g.starts_tried;
    o["starts_converged_against_assignment"] = g.starts_wrong_sign;
    j["obstruction"] = o;
  } else {
    j["obstruction"] = nullptr;
  }
  j["max_residual"] = g.max_residual;
  j["interference"] = x.applicable ? "local (a crease reaching 180 deg ends a branch) and global (faces crossing, FCL AABB tree) at every explored point"
                                   : "local only (creases reaching 180 deg): pattern too large for the branch explorer";
  j["seconds"] = g.seconds + x.seconds;
  return j;
}

// Sheets with holes (tubes): mobility from the given 3D state with the SE(3) hole closures.
Json mobility_json(const CreasePattern& p, const Topology& t, bool ignore_assignment, int holes) {
  ReferenceMobilityOptions options;
  options.use_assignment = !ignore_assignment;
  const ReferenceMobility m = reference_mobility(p, t, options);
  Json j;
  j["assignment"] = ignore_assignment ? "ignored" : "as given (sign constraints)";
  j["verdict"] = to_string(m.verdict);
  j["rigidly_foldable"] = rigidly_foldable_json(m.verdict);
  j["model"] = "general loop-closure solver with SE(3) hole closures, from the given state";
  j["model_choice"] = "the sheet has " + std::to_string(holes) +
                      " hole(s): the multiplier model and the flat-state search do not apply; the given (3D) state is "
                      "the reference";
  j["reason"] = m.reason;
  j["is_proof"] = m.verdict != Verdict::kUndecided;
  j["dof"] = m.dof;
  j["dof_tolerance"] = "rank of the closure Jacobian (vertex and hole rows) at the given state, singular values below "
                       "1e-9 x largest dropped; kept " + std::to_string(m.sigma_kept) + ", dropped " +
                       std::to_string(m.sigma_dropped);
  j["holes_closed"] = m.holes;
  j["reference_residual"] = m.reference_residual;
  Json branches = Json::array();
  for (const MobilityBranch& b : m.branches) {
    Json jb;
    jb["id"] = b.id;
    jb["from_point"] = "given state";
    jb["sense"] = b.sense;
    jb["dof"] = m.dof;
    add_traced_branch_keys(jb, b, ignore_assignment);
    jb["valid_points"] = b.valid_points;
    jb["global_interference"] =
        b.interfering_faces.first < 0 ? Json(nullptr)
                                      : Json({{"faces", {b.interfering_faces.first, b.interfering_faces.second}}});
    branches.push_back(jb);
  }
  j["branches"] = branches;
  j["bifurcations"] = Json::array();
  if (m.verdict == Verdict::kNotRigidlyFoldable)
    j["obstruction"] = {{"kind", "first-order rigid"}, {"message", m.reason}, {"least_residual", m.reference_residual}};
  else
    j["obstruction"] = nullptr;
  j["max_residual"] = m.max_residual;
  j["interference"] = "local (a crease reaching 180 deg ends a branch) and global (faces crossing, FCL AABB tree) at every traced point";
  j["seconds"] = m.seconds;
  return j;
}

}  // namespace

Json foldability_json(const CreasePattern& p, const Topology& t, bool ignore_assignment, bool force_general) {
  const auto start = std::chrono::steady_clock::now();
  int holes = 0;
  for (const Component& c : t.components) holes += c.holes;
  if (holes > 0) return mobility_json(p, t, ignore_assignment, holes);
  if (force_general) return general_json(p, t, ignore_assignment, "forced (--general)");
  const FoldabilityVerdict v = ignore_assignment ? verdict_ignoring_assignment(p, t) : verdict_with_assignment(p, t);
  if (v.verdict == Verdict::kNotApplicable) {
    try {
      return general_json(p, t, ignore_assignment, "multiplier propagation not applicable: " + v.reason);
    } catch (const std::runtime_error& e) {  // e.g. holes: no SE(3) hole closure yet
      Json j;
      j["verdict"] = to_string(Verdict::kUndecided);
      j["rigidly_foldable"] = nullptr;
      j["model"] = "none";
      j["reason"] = std::string("general solver unavailable for this pattern: ") + e.what();
      j["dof"] = 0;
      j["branches"] = Json::array();
      j["bifurcations"] = Json::array();
      j["obstruction"] = nullptr;
      j["max_residual"] = 0.0;
      j["seconds"] = 0.0;
      return j;
    }
  }
  Json j;
  j["assignment"] = ignore_assignment ? "ignored" : "as given (sign constraints)";
  j["verdict"] = to_string(v.verdict);
  j["rigidly_foldable"] = rigidly_foldable_json(v.verdict);
  j["model"] = v.model;
  j["model_choice"] = "every interior vertex is a flat-foldable degree-4 vertex: exact O(creases) model";
  j["is_proof"] = true;
  j["reason"] = v.reason;
  j["dof"] = v.verdict == Verdict::kRigidlyFoldable ? v.dof : 0;
  Json branches = Json::array();
  Json bifurcations = Json::array();
  double max_residual = 0;
  if (v.verdict == Verdict::kRigidlyFoldable && v.family) {
    // The family tan(rho_e/2) = m_e * t: sample it from flat to just short of the fully
    // folded state (the first crease reaching 180 deg) and record the closure residual.
    const FoldFamily& fam = *v.family;
    int limiting = -1;
    double largest = 0;
    for (int e = 0; e < p.num_edges(); ++e)
      if (fam.component[e] >= 0 && std::fabs(fam.multiplier[e]) > largest) {
        largest = std::fabs(fam.multiplier[e]);
        limiting = e;
      }
    for (int c = 0; c < fam.num_components; ++c) {
      double worst = 0, reached = 0;
      bool signs_ok = true;
      for (int k = 1; k <= 64; ++k) {
        const double lead = (179.0 / kDeg) * k / 64;  // fold of the fastest crease
        std::vector<double> params(fam.num_components, 0.0);
        params[c] = limiting >= 0 ? fam.parameter_for(limiting, lead) : std::tan(lead / 2);
        const Eigen::VectorXd rho = fam.angles(params);
        worst = std::max(worst, max_vertex_closure_residual(t, rho));
        reached = std::max(reached, rho.cwiseAbs().maxCoeff());
        for (int e = 0; e < p.num_edges(); ++e) {
          if (p.assignments[e] == Assignment::Mountain && rho[e] > 0) signs_ok = false;
          if (p.assignments[e] == Assignment::Valley && rho[e] < 0) signs_ok = false;
        }
      }
      max_residual = std::max(max_residual, worst);
      branches.push_back({{"id", c},
                          {"signs_match_assignment", signs_ok},
                          {"range_deg", {0.0, reached * kDeg}},
                          {"stopped_by", "fully folded: crease " + std::to_string(limiting) + " reaches 180 deg (local interference limit)"},
                          {"max_residual", worst}});
    }
    bifurcations.push_back({{"parameter", 0.0},
                            {"angles_deg", std::vector<double>(p.num_edges(), 0.0)},
                            {"kind", "flat state: every vertex's two modes meet (singular; first-order rank inconclusive)"}});
    j["certificate_mismatch"] = v.certificate_mismatch;
    j["certificate_max_fold_deg"] = v.certificate_max_fold * kDeg;
    j["max_loop_gain_defect"] = v.max_loop_defect;
  }
  j["branches"] = branches;
  j["bifurcations"] = bifurcations;
  j["obstruction"] = v.obstruction ? obstruction_json(*v.obstruction) : Json(nullptr);
  j["max_residual"] = max_residual;
  j["interference"] = "local only (creases reaching 180 deg); global face-face test not yet implemented";
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return j;
}

}  // namespace rigidfold::cli
