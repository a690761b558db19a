#include "app/foldability_json.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold::cli {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kDeg = 180.0 / std::numbers::pi;

// Largest vertex-closure residual (rad) over all interior vertices at fold angles rho.
double max_vertex_residual(const Topology& t, const Eigen::VectorXd& rho) {
  double worst = 0;
  for (int v : t.interior_vertices) {
    const Fan& fan = t.stars[v].fans[0];
    std::vector<double> angles;
    for (int e : fan.edges) angles.push_back(rho[e]);
    worst = std::max(worst, vertex_closure_residual(fan.sectors, angles).norm());
  }
  return worst;
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

}  // namespace

Json foldability_json(const CreasePattern& p, const Topology& t, bool ignore_assignment) {
  const auto start = std::chrono::steady_clock::now();
  const FoldabilityVerdict v = ignore_assignment ? verdict_ignoring_assignment(p, t) : verdict_with_assignment(p, t);
  Json j;
  j["assignment"] = ignore_assignment ? "ignored" : "as given (sign constraints)";
  j["verdict"] = to_string(v.verdict);
  if (v.verdict == Verdict::kRigidlyFoldable) j["rigidly_foldable"] = true;
  else if (v.verdict == Verdict::kNotRigidlyFoldable) j["rigidly_foldable"] = false;
  else j["rigidly_foldable"] = nullptr;  // not decided by the models available
  j["model"] = v.verdict == Verdict::kNotApplicable ? "none (general loop-closure solver not yet available)" : v.model;
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
        worst = std::max(worst, max_vertex_residual(t, rho));
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
