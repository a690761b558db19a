#include "kernel/analysis/foldability_report.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "kernel/analysis/path_watch.hpp"
#include "kernel/analysis/reference_mobility.hpp"
#include "kernel/closure/vertex_residuals.hpp"
#include "kernel/math/number_text.hpp"

namespace rigidfold {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

const char* kLocalInterferenceOnly = "local only (creases reaching 180 deg)";
const char* kLocalAndGlobal =
    "local (a crease reaching 180 deg ends a branch) and global (faces crossing, FCL AABB tree) at every";

FoldabilityClass class_of(Verdict v, bool is_proof) {
  switch (v) {
    case Verdict::kRigidlyFoldable: return FoldabilityClass::kFoldable;
    case Verdict::kNotRigidlyFoldable:
      return is_proof ? FoldabilityClass::kNotFoldableProof : FoldabilityClass::kNotFoldableEvidence;
    default: return FoldabilityClass::kUndecided;
  }
}

// 1. Sheets with holes: mobility from the given 3D state.
void given_state_report(const CreasePattern& p, const Topology& t, const FoldabilityOptions& o,
                        FoldabilityReport& r) {
  ReferenceMobilityOptions mo;
  mo.use_assignment = o.use_assignment;
  mo.tolerances = o.tolerances;
  ReferenceMobility m = reference_mobility(p, t, mo);
  r.model = FoldabilityModel::kGivenStateHoleClosure;
  r.model_name = "general loop-closure solver with SE(3) hole closures, from the given state";
  r.is_proof = m.verdict != Verdict::kUndecided;
  r.verdict = class_of(m.verdict, r.is_proof);
  r.reason = m.reason;
  r.dof = m.dof;
  r.dof_basis = "rank of the closure Jacobian (vertex and hole rows) at the given state (" + m.dof_method + "), singular values below " +
                short_text(o.tolerances.rank_cut) + " x largest dropped; kept " + short_text(m.sigma_kept) +
                ", dropped " + short_text(m.sigma_dropped);
  r.holes_closed = m.holes;
  r.reference_residual = m.reference_residual;
  r.sigma_kept = m.sigma_kept;
  r.sigma_dropped = m.sigma_dropped;
  r.branches = std::move(m.branches);
  if (m.verdict == Verdict::kNotRigidlyFoldable) {
    FoldabilityObstruction ob;
    ob.kind = "first-order rigid";
    ob.message = m.reason;
    ob.least_residual = m.reference_residual;
    r.obstruction = ob;
  }
  r.max_residual = m.max_residual;
  r.interference_checked = std::string(kLocalAndGlobal) + " traced point";
}

// 2. Multiplier propagation: the exact verdict, and the family sampled per component.
void multiplier_report(const CreasePattern& p, const Topology& t, const FoldabilityOptions& o,
                       const FoldabilityVerdict& v, FoldabilityReport& r) {
  r.model = FoldabilityModel::kMultiplierPropagation;
  r.model_name = v.model;
  r.is_proof = v.verdict != Verdict::kUndecided;  // undecided: the mode search ran out of budget
  r.verdict = class_of(v.verdict, r.is_proof);
  r.reason = v.reason;
  r.dof = v.verdict == Verdict::kRigidlyFoldable ? v.dof : 0;
  r.dof_basis = "components of the fold family (exact)";
  if (v.obstruction) {
    FoldabilityObstruction ob;
    ob.kind = to_string(v.obstruction->kind);
    ob.message = v.obstruction->message;
    ob.exact = v.obstruction;
    r.obstruction = ob;
  }
  r.interference_checked = std::string(kLocalInterferenceOnly) + "; global face-face test not run on this model";
  if (v.verdict != Verdict::kRigidlyFoldable || !v.family) return;
  // The family tan(rho_e/2) = m_e * t: each component sampled from flat to the fold limit of
  // its fastest crease, with the closure residual and the letters checked at every sample.
  const FoldFamily& fam = *v.family;
  PathWatchOptions wo;
  wo.tolerances = o.tolerances;
  for (int c = 0; c < fam.num_components; ++c) {
    const int fastest = fam.fastest_crease(c);
    if (fastest < 0) continue;  // a component always folds some crease; guard anyway
    TracedBranch b;
    b.id = c;
    b.from_point = 0;
    b.dof_at_departure = 1;
    b.driving_edge = fastest;
    PathWatch watch(p, fastest, wo);
    for (int k = 1; k <= o.family_samples; ++k) {
      const double lead = o.tolerances.fold_limit() * k / o.family_samples;  // fold of the fastest crease
      const Eigen::VectorXd rho = fam.component_angles(c, fam.parameter_for(fastest, lead));
      b.max_residual = std::max(b.max_residual, max_vertex_closure_residual(t, rho));
      b.max_fold = std::max(b.max_fold, rho.cwiseAbs().maxCoeff());
      PathWatch::mark_letters(watch.observe(rho), b);
      b.path.push_back(rho);
    }
    b.valid_points = static_cast<int>(b.path.size());
    b.driving_end = b.path.back()[fastest];
    b.stopped_by = StopReason::kFoldLimit;
    b.stop_crease = fastest;
    b.stop_message = "fully folded: crease " + std::to_string(fastest) + " reaches 180 deg (local interference limit)";
    r.max_residual = std::max(r.max_residual, b.max_residual);
    r.branches.push_back(std::move(b));
  }
  BranchPoint flat;
  flat.kind = PointKind::kFlat;
  flat.angles = Eigen::VectorXd::Zero(p.num_edges());
  flat.kernel_dimension = -1;  // first-order rank inconclusive at the flat state; not computed
  r.points.push_back(flat);
  r.certificate_mismatch = v.certificate_mismatch;
  r.certificate_max_fold = v.certificate_max_fold;
  r.max_loop_gain_defect = v.max_loop_defect;
}

// Largest |rho| (capped at pi) over the valid points of an explored branch: before faces
// cross.
double reach_before_interference(const TracedBranch& b) {
  const int valid =
      b.global_interference_index >= 0 ? b.global_interference_index : static_cast<int>(b.path.size());
  double reach = 0;
  for (int k = 0; k < valid; ++k) reach = std::max(reach, std::min(b.path[k].cwiseAbs().maxCoeff(), std::numbers::pi));
  return reach;
}

// 3. The general loop-closure verdict, with the branch explorer where it applies.
void general_report(const CreasePattern& p, const Topology& t, const FoldabilityOptions& o, FoldabilityReport& r) {
  GeneralVerdictOptions go;
  go.use_assignment = o.use_assignment;
  go.tolerances = o.tolerances;
  GeneralVerdict g = general_verdict(p, t, go);
  r.model = FoldabilityModel::kGeneralLoopClosure;
  r.model_name = g.model;
  r.is_proof = g.is_proof;
  r.verdict = class_of(g.verdict, g.is_proof);
  r.reason = g.reason;
  r.dof = g.verdict == Verdict::kRigidlyFoldable ? std::max(g.trace.dof_at_departure, 0) : 0;
  r.dof_basis = "rank of the closure Jacobian at the traced point (" + g.trace.dof_method + "), singular values below " +
                short_text(o.tolerances.rank_cut) + " x largest dropped";
  r.sign_switches = g.trace.sign_switches;
  r.max_residual = g.trace.max_residual;
  if (g.verdict == Verdict::kRigidlyFoldable) r.certificate_mismatch = g.certificate_mismatch;
  if (g.verdict == Verdict::kNotRigidlyFoldable) {
    FoldabilityObstruction ob;
    ob.kind = g.is_proof ? "no foldable crease" : "no folded point found near flat";
    ob.message = g.reason;
    ob.least_residual = g.least_residual;
    ob.worst_vertices = g.worst_vertices;
    ob.crease_against_assignment = g.wrong_sign_crease;
    ob.starts_tried = g.starts_tried;
    ob.starts_converged_against_assignment = g.starts_wrong_sign;
    r.obstruction = ob;
  }
  BranchExploration x;
  if (o.explore_branches) {
    BranchExplorerOptions xo;
    xo.tolerances = o.tolerances;
    x = explore_branches(p, t, xo);
  } else {
    x.why_not = "not requested";
  }
  r.branches_explored = x.applicable;
  r.exploration_seconds = x.seconds;
  if (!x.applicable) {
    r.exploration_note = x.why_not;
    r.unrefined_singular_points = g.singular_points;
    if (g.verdict == Verdict::kRigidlyFoldable) {
      g.trace.id = 0;
      g.trace.from_point = 0;
      g.trace.signs_match_assignment = g.trace.sign_switches.empty();
      r.branches.push_back(std::move(g.trace));
    }
    r.interference_checked = std::string(kLocalInterferenceOnly) + ": pattern too large for the branch explorer";
    return;
  }
  // A branch from flat with DOF 1, every letter kept (or letters ignored), no face crossing
  // before it reaches the certificate fold, residual within the certificate bound: a rigid
  // folding motion the search may have missed.
  const TracedBranch* certified = nullptr;
  for (const TracedBranch& b : x.branches) {
    const bool letters_ok = !o.use_assignment || b.signs_match_assignment;
    if (!certified && b.from_point == 0 && letters_ok && b.dof_at_departure == 1 &&
        reach_before_interference(b) >= go.certificate_fold && b.max_residual <= o.tolerances.certificate_residual)
      certified = &b;
  }
  if (!r.foldable() && certified) {
    r.verdict = FoldabilityClass::kFoldable;
    r.is_proof = true;
    r.dof = 1;
    r.max_residual = certified->max_residual;
    r.obstruction.reset();
    r.reason = "branch " + std::to_string(certified->id) +
               " of the branch explorer leaves the flat state, keeps every letter and reaches the certificate fold; " +
               g.reason;
  }
  r.branches = std::move(x.branches);
  r.points = std::move(x.points);
  r.interference_checked = std::string(kLocalAndGlobal) + " explored point";
}

}  // namespace

const char* to_string(FoldabilityClass c) {
  switch (c) {
    case FoldabilityClass::kFoldable: return "foldable";
    case FoldabilityClass::kFoldableWithinTolerance: return "foldable within the input's precision";
    case FoldabilityClass::kNotFoldableProof: return "not foldable (proof)";
    case FoldabilityClass::kNotFoldableEvidence: return "not foldable (evidence)";
    case FoldabilityClass::kUndecided: return "undecided";
  }
  return "?";
}

const char* to_string(FoldabilityModel m) {
  switch (m) {
    case FoldabilityModel::kMultiplierPropagation: return "multiplier propagation";
    case FoldabilityModel::kGeneralLoopClosure: return "general loop closure";
    case FoldabilityModel::kGivenStateHoleClosure: return "given state with hole closures";
    case FoldabilityModel::kNone: return "none";
  }
  return "?";
}

int count_holes(const Topology& topology) {
  int holes = 0;
  for (const Component& c : topology.components) holes += c.holes;
  return holes;
}

ModelChoice choose_model(const CreasePattern& pattern, const Topology& topology, const FoldabilityOptions& options) {
  ModelChoice c;
  c.holes = count_holes(topology);
  if (c.holes > 0) {
    c.model = FoldabilityModel::kGivenStateHoleClosure;
    c.why = "the sheet has " + std::to_string(c.holes) +
            " hole(s): the multiplier model and the flat-state search do not apply; the given (3D) state is the "
            "reference";
    return c;
  }
  if (options.force_general) {
    c.model = FoldabilityModel::kGeneralLoopClosure;
    c.why = "forced (--general)";
    return c;
  }
  VerdictOptions vo;
  vo.flat_tolerance = options.tolerances.flat_kawasaki;
  vo.gain_tolerance = options.tolerances.loop_gain;
  FoldabilityVerdict v = options.use_assignment ? verdict_with_assignment(pattern, topology, vo)
                                                : verdict_ignoring_assignment(pattern, topology, vo);
  if (v.verdict == Verdict::kNotApplicable) {
    c.model = FoldabilityModel::kGeneralLoopClosure;
    c.why = "multiplier propagation not applicable: " + v.reason;
    return c;
  }
  c.model = FoldabilityModel::kMultiplierPropagation;
  c.why = "every interior vertex is a flat-foldable degree-4 vertex: exact O(creases) model";
  c.multiplier = std::move(v);
  return c;
}

FoldabilityReport check_foldability(const CreasePattern& pattern, const Topology& topology,
                                    const FoldabilityOptions& options) {
  const auto start = Clock::now();
  FoldabilityReport r;
  r.assignment_used = options.use_assignment;
  r.tolerances = options.tolerances;
  try {
    const ModelChoice c = choose_model(pattern, topology, options);
    r.model_choice = c.why;
    switch (c.model) {
      case FoldabilityModel::kGivenStateHoleClosure: given_state_report(pattern, topology, options, r); break;
      case FoldabilityModel::kMultiplierPropagation: multiplier_report(pattern, topology, options, *c.multiplier, r); break;
      default: general_report(pattern, topology, options, r); break;
    }
  } catch (const std::runtime_error& e) {  // a solver that cannot handle this sheet (e.g. a handle)
    r = FoldabilityReport{};
    r.assignment_used = options.use_assignment;
    r.tolerances = options.tolerances;
    r.model = FoldabilityModel::kNone;
    r.model_name = "none";
    r.reason = std::string("no solver applies to this pattern: ") + e.what();
  }
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace rigidfold
