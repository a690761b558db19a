#include "kernel/analysis/foldability_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "kernel/analysis/interval_loop_gain.hpp"
#include "kernel/analysis/path_watch.hpp"
#include "kernel/analysis/reference_mobility.hpp"
#include "kernel/analysis/rounding_witness.hpp"
#include "kernel/analysis/straight_line_folds.hpp"
#include "kernel/pattern/pattern_components.hpp"
#include "kernel/pattern/vertex_boxes.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/rank.hpp"
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
  // A folded form without holes whose given state does not close: judge it against the
  // file's precision, on the rounding witness's sectors.
  std::optional<RoundingWitness> witness;
  if (count_holes(t) == 0 && !t.interior_vertices.empty()) {
    const Eigen::VectorXd given = reference_fold_angles(p, t);
    if (max_vertex_closure_residual(t, given) > o.tolerances.certificate_residual)
      witness = rounding_witness(p, t, given, o.coordinate_tolerance);
  }
  report_progress(o.progress, [] { return std::string("given-state model: rank and branches at the given state"); });
  ReferenceMobility m = reference_mobility(p, witness && witness->explained ? witness->witness : t, mo);
  r.model = FoldabilityModel::kGivenStateHoleClosure;
  r.model_name = count_holes(t) > 0 ? "general loop-closure solver with SE(3) hole closures, from the given state"
                                     : "general loop-closure solver, from the given state";
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
  if (!witness) return;
  FoldabilityReport::InputPrecision ip;
  ip.decimal_places = witness->precision.decimal_places;
  ip.significant_digits = witness->precision.significant_digits;
  ip.coordinate_rounding = witness->precision.max_rounding;
  ip.given_residual = witness->given_residual;
  ip.max_sector_bound = witness->max_sector_bound;
  ip.max_sector_change = witness->max_sector_change;
  ip.max_change_ratio = witness->max_change_ratio;
  ip.explained = witness->explained;
  ip.exact_data_verdict = "not foldable from the given state as read: it is no configuration of the exact data (closure gap " +
                          short_text(witness->given_residual) + " rad), and its flat state is none either";
  const std::string precision_text =
      describe_precision(witness->precision) + ", sectors known to " + short_text(ip.max_sector_bound) + " rad";
  if (!witness->explained) {
    r.verdict = FoldabilityClass::kUndecided;
    r.is_proof = false;
    r.dof = 0;
    r.branches.clear();
    r.obstruction.reset();
    if (!witness->precision.rounded)  // --tolerance exact: no change is allowed
      r.reason = "the given state leaves a closure gap of " + short_text(ip.given_residual) + " rad and the " +
                 describe_precision(witness->precision) + ": it is no configuration of this pattern, nor is the flat state";
    else
      r.reason = "the given state leaves a closure gap of " + short_text(ip.given_residual) +
                 " rad, more than the file's rounding explains (" + precision_text + "; the least sector change closing it is " +
                 short_text(ip.max_change_ratio) + " x its bound at vertex " + std::to_string(witness->worst_vertex) +
                 "): not a rigidly folded state of this pattern within its precision";
  } else if (r.foldable()) {
    r.verdict = FoldabilityClass::kFoldableWithinTolerance;
    r.reason = "foldable within the input's precision: " + precision_text + "; a pattern whose sectors differ from the file's by at most " +
               short_text(ip.max_sector_change) + " rad (" + short_text(ip.max_change_ratio) +
               " of the rounding bound) has the given state as an exact configuration, and " + r.reason;
  } else {
    r.reason = "within the input's precision (" + precision_text + ", sectors moved by at most " + short_text(ip.max_sector_change) +
               " rad to close the given state): " + r.reason;
  }
  r.input_precision = ip;
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

// 2'. The multiplier model's verdict on a flat-foldable witness within the file's rounding
// (flat_foldable_witness.hpp): a yes holds within the input's precision; a no is a proof for
// the witness only, so "undecided" for the file.
void within_precision_report(const FlatFoldableWitness& w, FoldabilityReport& r) {
  FoldabilityReport::InputPrecision ip;
  ip.witness_kind = w.drawn_point_bounds ? "drawn points" : "coordinates";
  ip.decimal_places = w.precision.decimal_places;
  ip.significant_digits = w.precision.significant_digits;
  ip.coordinate_rounding = w.precision.max_rounding;
  ip.given_residual = w.max_kawasaki_defect;
  ip.max_coordinate_move = w.max_move;
  ip.max_change_ratio = w.max_move_ratio;
  ip.explained = w.explained;
  ip.exact_data_verdict = "not decided here: as read, vertex " + std::to_string(w.worst_defect_vertex) + " misses Kawasaki by " +
                          short_text(w.max_kawasaki_defect) +
                          " rad, so the exact multiplier model does not apply (check --general judges the exact numbers)";
  const std::string bounds_text =
      w.drawn_point_bounds
          ? "points drawn with " + std::to_string(ip.decimal_places) + " decimals (each vertex within the box of the points drawn for it, "
            "grown by their rounding: half-width <= " + short_text(ip.coordinate_rounding) + ")"
          : describe_precision(w.precision);
  const std::string witness_text =
      bounds_text + "; moving each coordinate by at most " + short_text(ip.max_coordinate_move) + " (" + short_text(ip.max_change_ratio) +
      " of its allowed move) makes every vertex flat-foldable (largest Kawasaki defect as read " + short_text(ip.given_residual) +
      " rad, of the witness " + short_text(w.witness_kawasaki) + " rad)" +
      (w.loop_gain_rows > 0 ? " and gives each of its " + std::to_string(w.loop_gain_rows) +
                                  " independent cycles of ties loop gain 1 in the modes the letters allow"
                            : std::string());
  if (r.foldable()) {
    r.verdict = FoldabilityClass::kFoldableWithinTolerance;
    r.reason = "foldable within the input's precision: " + witness_text + ", and that pattern is " + r.reason;
  } else if (r.not_foldable()) {
    // The witness's loop gain repeated over every pattern within the boxes of the file's
    // rounding (interval_loop_gain.hpp): where its enclosure excludes 1, the "no" holds for
    // the file (its own numbers lie in the boxes) and every pattern it may stand for.
    const std::optional<Obstruction>& exact = r.obstruction ? r.obstruction->exact : std::nullopt;
    if (r.assignment_used && exact && exact->kind == Obstruction::Kind::kLoopGain) {
      const IntervalLoopGainProof proof = interval_loop_gain_proof(w.witness, w.witness_topology, w.box_lo, w.box_hi,
                                                                   exact->cycle_vertices, exact->cycle_creases);
      // The witness lies in the boxes, so its own gain (or its inverse, by the cycle's
      // direction) must lie in the enclosure: a check of both computations.
      const bool holds_witness =
          proof.gain.contains(exact->loop_gain) || (exact->loop_gain != 0.0 && proof.gain.contains(1.0 / exact->loop_gain));
      ip.loop_gain_enclosure = {proof.gain.lo, proof.gain.hi};
      // Every crease must have an end at a locked vertex (this cycle's, or a proven face
      // cycle's), or a crease elsewhere might still fold alone.
      bool every_crease_locked = false;
      if (proof.proven && holds_witness) {
        const FaceCycleProof faces = face_cycle_loop_gain_proof(w.witness, w.witness_topology, w.box_lo, w.box_hi);
        std::vector<char> locked(w.witness.num_vertices(), 0);
        for (int v : exact->cycle_vertices) locked[v] = 1;
        for (int v : faces.locked_vertices) locked[v] = 1;
        every_crease_locked = every_hinge_has_a_locked_end(w.witness, w.witness_topology, locked);
      }
      if (proof.proven && holds_witness && every_crease_locked) {
        r.verdict = FoldabilityClass::kNotFoldableProof;
        r.is_proof = true;
        r.dof = 0;
        std::string cycle;
        for (int v : exact->cycle_vertices) cycle += " " + std::to_string(v);
        r.reason = "not foldable, for every pattern within the input's precision: around vertices" + cycle +
                   " the first-order rates of the degree-4 vertices, in the one mode the letters allow at each, give a "
                   "loop gain within [" + short_text(proof.gain.lo) + ", " + short_text(proof.gain.hi) +
                   "] (interval arithmetic over the boxes: " + bounds_text + "), never 1, so no rigid motion from flat "
                   "that keeps the letters folds any crease at those vertices; on a flat-foldable witness within the "
                   "boxes the gain is " + short_text(exact->loop_gain);
        r.model_name += " (with an interval loop-gain proof over the input's precision)";
        ip.exact_data_verdict = "not foldable: the file's own numbers lie within the boxes the proof covers";
        r.input_precision = ip;
        return;
      }
      ip.loop_gain_proof_note = !proof.proven ? proof.why_not
                                : !holds_witness ? "the enclosure does not hold the witness's own gain (internal check failed)"
                                                 : "proven for the creases at the cycle's vertices, but some crease has no end "
                                                   "at a vertex of a proven cycle";
    }
    // A proof for the witness only: the least move makes every vertex flat-foldable but does
    // not aim at the loop gains, so a rounded Miura's witness misses gain 1 by ~1e-6 while a
    // pattern within the rounding folds. Undecided, with the witness's obstruction beside it.
    r.verdict = FoldabilityClass::kUndecided;
    r.is_proof = false;
    r.dof = 0;
    r.reason = "undecided within the input's precision: " + witness_text + ", and that pattern does not fold (" + r.reason +
               "); another pattern within the rounding may, and the exact numbers are not flat-foldable";
  } else {
    r.reason = "within the input's precision: " + witness_text + "; on that pattern: " + r.reason;
  }
  r.model_name += " (on a flat-foldable witness within the input's precision)";
  r.input_precision = ip;
}

// 2''. A face's cycle of degree-4 vertices whose first-order loop gain excludes 1 over every
// pattern within the input's precision (interval_loop_gain.hpp): a proof that needs neither
// Kawasaki nor the numerical search. False (r untouched) where no face's cycle is proven.
bool first_order_loop_gain_report(const CreasePattern& p, const Topology& t, const FoldabilityOptions& o,
                                  FoldabilityReport& r) {
  // --general asks for the numerical solver itself (cross-checks).
  if (!o.use_assignment || o.force_general || t.interior_vertices.empty()) return false;
  for (const Eigen::Vector3d& v : p.vertices)
    if (v.z() != 0.0) return false;  // a folded form: the flat state is not what the file gives
  const VertexBoxes boxes = vertex_boxes(p, o.coordinate_tolerance);
  const FaceCycleProof f = face_cycle_loop_gain_proof(p, t, boxes.lo, boxes.hi);
  // A proof for every crease, or the numerical search decides (a crease away from the locked
  // vertices might fold alone).
  if (!f.every_crease_locked) return false;
  std::string cycle;
  for (int v : f.cycle_vertices) cycle += " " + std::to_string(v);
  r.model = FoldabilityModel::kGeneralLoopClosure;
  r.model_name = "first-order loop gain (interval arithmetic)";
  r.model_choice += "; a face's cycle of degree-4 vertices decides it exactly, the numerical search is not run";
  r.verdict = FoldabilityClass::kNotFoldableProof;
  r.is_proof = true;
  r.dof = 0;
  r.reason = "not foldable" + std::string(boxes.exact ? "" : ", for every pattern within the input's precision") +
             ": around face " + std::to_string(f.face) + " (vertices" + cycle +
             ") the first-order rates of the degree-4 vertices, in the one mode the letters allow at each, give a loop "
             "gain within [" + short_text(f.proof.gain.lo) + ", " + short_text(f.proof.gain.hi) +
             "] (interval arithmetic" + (boxes.exact ? std::string(" on the numbers as read") : " over the boxes") +
             "), never 1, so no rigid motion from flat that keeps the letters folds any crease at those vertices; " +
             std::to_string(f.faces_proven) + " face cycle(s) proven so, and every crease has an end at one of their " +
             std::to_string(f.locked_vertices.size()) + " vertices: no crease folds";
  FoldabilityObstruction ob;
  ob.kind = "loop gain";
  ob.message = r.reason;
  r.obstruction = ob;
  r.interference_checked = "not needed: no motion";
  return true;
}

// Up to 6 states of path[0 .. count), evenly spread, the first and the last included.
std::vector<Eigen::VectorXd> sample_path(const std::vector<Eigen::VectorXd>& path, int count) {
  count = std::min<int>(count, static_cast<int>(path.size()));
  std::vector<Eigen::VectorXd> out;
  const int samples = std::min(count, 6);
  for (int k = 0; k < samples; ++k) {
    const int i = samples == 1 ? count - 1 : static_cast<int>(std::lround(double(k) * (count - 1) / (samples - 1)));
    out.push_back(path[static_cast<std::size_t>(i)]);
  }
  return out;
}

// 3. The general loop-closure verdict, with the branch explorer where it applies.
void general_report(const CreasePattern& p, const Topology& t, const FoldabilityOptions& o, FoldabilityReport& r) {
  GeneralVerdictOptions go;
  go.use_assignment = o.use_assignment;
  go.tolerances = o.tolerances;
  go.coordinate_tolerance = o.coordinate_tolerance;
  go.progress = o.progress;
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
  if (g.verdict == Verdict::kRigidlyFoldable) r.strictness = g.strictness;
  r.search_evidence = g.evidence;
  r.residual_growth_exponent = g.growth_exponent;
  r.scaled_norm_search = g.scaled_norm_search;
  r.max_residual = g.trace.max_residual;
  if (g.verdict == Verdict::kRigidlyFoldable) {
    r.certificate_mismatch = g.certificate_mismatch;
    r.certificate_samples = sample_path(g.trace.path, g.trace.valid_points);
  }
  if (g.verdict == Verdict::kNotRigidlyFoldable || (g.verdict == Verdict::kUndecided && g.least_residual >= 0)) {
    FoldabilityObstruction ob;
    ob.kind = g.is_proof ? "no foldable crease"
              : g.verdict == Verdict::kUndecided ? "no folded point found near flat, no evidence either way"
                                                  : "no folded point found near flat";
    ob.message = g.reason;
    ob.least_residual = g.least_residual;
    ob.worst_vertices = g.worst_vertices;
    ob.crease_against_assignment = g.wrong_sign_crease;
    ob.starts_tried = g.starts_tried;
    ob.starts_converged_against_assignment = g.starts_wrong_sign;
    r.obstruction = ob;
  }
  BranchExploration x;
  if (o.explore_branches && r.foldable() && r.dof > o.max_explored_dof) {
    x.why_not = "not run: the certified motion has DOF " + std::to_string(r.dof) + " at the flat state (more than " +
                std::to_string(o.max_explored_dof) + "), of which the explorer's departures would be an arbitrary sample";
  } else if (o.explore_branches) {
    BranchExplorerOptions xo;
    xo.tolerances = o.tolerances;
    xo.progress = o.progress;
    report_progress(o.progress, [] { return std::string("branch explorer: starting from the flat state"); });
    x = explore_branches(p, t, xo);
  } else {
    x.why_not = "not requested";
  }
  r.branches_explored = x.applicable;
  r.exploration_seconds = x.seconds;
  r.exploration_budget_exhausted = x.budget_exhausted;
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
    // Strictness at the branch's farthest valid point (before any face crossing).
    const int last = (certified->global_interference_index >= 0 ? certified->global_interference_index
                                                                 : static_cast<int>(certified->path.size())) - 1;
    if (last >= 0) r.strictness = strictness_at(p, certified->path[last]);
    r.certificate_samples = sample_path(certified->path, last + 1);
    r.reason = "branch " + std::to_string(certified->id) +
               " of the branch explorer leaves the flat state, keeps every letter and reaches the certificate fold; " +
               g.reason;
  }
  r.branches = std::move(x.branches);
  r.points = std::move(x.points);
  r.interference_checked = std::string(kLocalAndGlobal) + " explored point";
}

StraightLineOptions line_options(const FoldabilityOptions& o) {
  StraightLineOptions so;
  so.use_assignment = o.use_assignment;
  so.tolerances = o.tolerances;
  return so;
}

// The straight-line facts (straight_line_folds.hpp): a line that folds alone certifies weak
// foldability where the search found nothing; crossing lines prove that no motion is strict.
void straight_line_report(const CreasePattern& p, const Topology& t, const FoldabilityOptions& o,
                          const StraightLineAnalysis& lines, FoldabilityReport& r) {
  if (r.strictness) r.strictness->strict_obstruction_vertices = lines.strict_obstruction_vertices;
  if (r.foldable() || lines.folds.empty()) return;
  const StraightLineFold& line = lines.folds.front();
  // DOF on the motion (halfway), the same rank test as the general verdict's.
  const ClosureSystem sys(p, t);
  Eigen::VectorXd rho_mid = line.path[line.path.size() / 2];
  Eigen::VectorXd res;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(sys.unknowns_from_edges(rho_mid), res, J);
  RankOptions ro;
  ro.relative_tolerance = o.tolerances.rank_cut;
  const RankResult rk = jacobian_rank(J, ro);
  TracedBranch b;
  b.id = static_cast<int>(r.branches.size());
  b.from_point = 0;
  b.dof_at_departure = rk.dof;
  b.dof_method = rk.method;
  b.driving_edge = line.creases.front();
  PathWatchOptions wo;
  wo.tolerances = o.tolerances;
  PathWatch watch(p, b.driving_edge, wo);
  for (const Eigen::VectorXd& rho : line.path) {
    b.max_fold = std::max(b.max_fold, rho.cwiseAbs().maxCoeff());
    PathWatch::mark_letters(watch.observe(rho), b);
    b.path.push_back(rho);
  }
  b.max_residual = line.max_residual;
  b.valid_points = static_cast<int>(b.path.size());
  b.driving_begin = b.path.front()[b.driving_edge];
  b.driving_end = b.path.back()[b.driving_edge];
  b.stopped_by = StopReason::kFoldLimit;
  b.stop_crease = b.driving_edge;
  b.stop_message = "the straight line reaches the fold limit (every crease of it at once)";
  r.verdict = FoldabilityClass::kFoldable;
  r.is_proof = true;
  r.dof = rk.dof;
  r.dof_basis = "rank of the closure Jacobian halfway along the straight-line fold (" + rk.method + "), singular values below " +
                short_text(o.tolerances.rank_cut) + " x largest dropped";
  r.max_residual = std::max(r.max_residual, line.max_residual);
  r.obstruction.reset();
  r.strictness = strictness_at(p, line.path.back());
  r.certificate_samples = sample_path(line.path, static_cast<int>(line.path.size()));
  r.strictness->strict_obstruction_vertices = lines.strict_obstruction_vertices;
  std::string verts;
  r.reason = "the straight crease line of " + std::to_string(line.creases.size()) + " creases from boundary vertex " +
             std::to_string(line.vertices.front()) + " to boundary vertex " + std::to_string(line.vertices.back()) +
             " folds alone (every other crease flat), " + (line.sign < 0 ? "as a mountain" : "as a valley") +
             ", closure residual at most " + short_text(line.max_residual) + " rad along the motion to " +
             short_text(o.tolerances.fold_limit()) + " rad: weakly foldable (" +
             std::to_string(lines.folds.size()) + " such line(s) checked)" +
             (r.reason.empty() ? std::string("") : "; the search: " + r.reason);
  r.branches.push_back(std::move(b));
}

}  // namespace

const char* to_string(FoldabilityClass c) {
  switch (c) {
    case FoldabilityClass::kFoldable: return "foldable";
    case FoldabilityClass::kFoldableWithinTolerance: return "foldable within the input's precision";
    case FoldabilityClass::kFoldableInPart: return "foldable only in part";
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
  if (!topology.interior_vertices.empty()) {
    // A folded form whose sectors are not developable: the flat state is no configuration.
    double worst = 0.0;
    for (int v : topology.interior_vertices)
      worst = std::max(worst, std::abs(topology.stars[v].sector_sum() - 2 * std::numbers::pi));
    if (worst > options.tolerances.flat_kawasaki &&
        reference_fold_angles(pattern, topology).cwiseAbs().maxCoeff() > options.tolerances.sign_threshold) {
      c.model = FoldabilityModel::kGivenStateHoleClosure;
      c.why = "a folded form whose vertices are not developable (sector sums differ from 360 deg by up to " +
              short_text(worst) + " rad): the flat state is no configuration of these sectors; the given (3D) state is the "
              "reference";
      return c;
    }
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
    // Not flat-foldable as read: within the rounding of the file's coordinates?
    std::optional<FlatFoldableWitness> w = flat_foldable_witness(pattern, topology, options.tolerances.flat_kawasaki, nullptr,
                                                                   options.coordinate_tolerance);
    if (w && w->explained) {
      FoldabilityVerdict wv = options.use_assignment ? verdict_with_assignment(w->witness, w->witness_topology, vo)
                                                     : verdict_ignoring_assignment(w->witness, w->witness_topology, vo);
      // The least move aims at Kawasaki only; where the letters leave one mode per vertex and
      // the witness fails a loop gain, a second least move also closes every cycle's gain.
      if (options.use_assignment && wv.verdict == Verdict::kNotRigidlyFoldable && wv.obstruction &&
          wv.obstruction->kind == Obstruction::Kind::kLoopGain) {
        std::vector<FlatFoldMode> modes;
        for (int v : w->witness_topology.interior_vertices) {
          const std::vector<FlatFoldMode> m = modes_matching_letters(w->witness, w->witness_topology.stars[v].fans[0]);
          if (m.size() != 1) break;
          modes.push_back(m[0]);
        }
        if (modes.size() == w->witness_topology.interior_vertices.size()) {
          std::optional<FlatFoldableWitness> w2 = flat_foldable_witness(pattern, topology, options.tolerances.flat_kawasaki, &modes,
                                                                         options.coordinate_tolerance);
          if (w2 && w2->explained) {
            FoldabilityVerdict wv2 = verdict_with_assignment(w2->witness, w2->witness_topology, vo);
            if (wv2.verdict == Verdict::kRigidlyFoldable) {
              w = std::move(w2);
              wv = std::move(wv2);
            }
          }
        }
      }
      if (wv.verdict != Verdict::kNotApplicable) {
        c.model = FoldabilityModel::kMultiplierPropagation;
        c.why = "every interior vertex is a degree-4 vertex flat-foldable within the rounding of the coordinates "
                "(Kawasaki defect up to " + short_text(w->max_kawasaki_defect) + " rad at vertex " +
                std::to_string(w->worst_defect_vertex) + "; a witness pattern moves each coordinate by at most " +
                short_text(w->max_move_ratio) + " of its rounding): exact O(creases) model on the witness";
        c.multiplier = std::move(wv);
        c.flat_witness = std::move(w);
        return c;
      }
    }
    c.model = FoldabilityModel::kGeneralLoopClosure;
    c.why = "multiplier propagation not applicable: " + v.reason;
    if (w)
      c.why += "; not explained by the rounding of the coordinates (a flat-foldable witness moves a coordinate by " +
               short_text(w->max_move_ratio) + " x its rounding at vertex " + std::to_string(w->worst_move_vertex) + ")";
    return c;
  }
  c.model = FoldabilityModel::kMultiplierPropagation;
  c.why = "every interior vertex is a flat-foldable degree-4 vertex: exact O(creases) model";
  c.multiplier = std::move(v);
  return c;
}

namespace {

// With letters, the headline answers the strict question (foldability_report.hpp): a certified
// motion that leaves lettered creases flat is a partial answer, and crossing straight lettered
// lines turn it into a proof that no motion folds every lettered crease.
void answer_the_strict_question(const FoldabilityOptions& options, FoldabilityReport& r) {
  if (!options.use_assignment || r.verdict != FoldabilityClass::kFoldable || !r.strictness || r.strictness->strict) return;
  const StrictnessReport& st = *r.strictness;
  r.folds_in_part = true;
  const std::string flat = std::to_string(st.flat_lettered.size()) + " lettered crease(s) flat";
  if (st.strict_obstruction_vertices.empty()) {
    r.verdict = FoldabilityClass::kFoldableInPart;
    r.reason = "foldable only in part: the certified motion keeps every letter but leaves " + flat +
               "; no motion folding every lettered crease was found, and none is ruled out; " + r.reason;
    return;
  }
  r.verdict = FoldabilityClass::kNotFoldableProof;
  r.is_proof = true;
  FoldabilityObstruction ob;
  ob.kind = "crossing lettered lines";
  ob.message = "straight lettered crease lines cross at " + std::to_string(st.strict_obstruction_vertices.size()) +
               " degree-4 vertices (first: vertex " + std::to_string(st.strict_obstruction_vertices.front()) +
               "), where no motion from flat folds all four creases: no motion folds every lettered crease";
  r.reason = "not foldable: " + ob.message + " (proof); foldable only in part, leaving " + flat + ": " + r.reason;
  r.obstruction = std::move(ob);
}

// A sheet of several pieces: each checked alone (FoldabilityReport::pieces), and the whole
// sheet's verdict compared with what the pieces imply.
void check_pieces(const CreasePattern& pattern, const Topology& topology, const FoldabilityOptions& options,
                  FoldabilityReport& r) {
  bool some_folds = false, all_proven_rigid = true;
  int dof = 0;
  for (const PatternComponent& piece : split_components(pattern, topology)) {
    report_progress(options.progress, [&] {
      return "piece " + std::to_string(r.pieces.size() + 1) + " of " + std::to_string(topology.components.size());
    });
    FoldabilityReport::PieceVerdict v;
    v.faces = piece.pattern.num_faces();
    try {
      const Topology t = build_topology(piece.pattern, "piece " + std::to_string(r.pieces.size()));
      for (int e = 0; e < piece.pattern.num_edges(); ++e) v.creases += t.edge_is_hinge[e] ? 1 : 0;
      v.interior_vertices = static_cast<int>(t.interior_vertices.size());
      const FoldabilityReport pr = check_foldability(piece.pattern, t, options);
      v.verdict = pr.verdict;
      v.is_proof = pr.is_proof;
      v.dof = pr.dof;
      v.model_name = pr.model_name;
      v.reason = pr.reason;
    } catch (const std::exception& e) {  // a piece of a valid sheet is valid; say so if not
      v.reason = std::string("not checked alone: ") + e.what();
    }
    some_folds = some_folds || v.verdict == FoldabilityClass::kFoldable;
    all_proven_rigid = all_proven_rigid && v.verdict == FoldabilityClass::kNotFoldableProof;
    if (v.verdict == FoldabilityClass::kFoldable) dof += v.dof;
    r.pieces.push_back(std::move(v));
  }
  std::string disagreement;
  if (some_folds && !r.foldable()) disagreement = "a piece folds on its own, so the sheet folds (the others held flat)";
  else if (all_proven_rigid && r.foldable()) disagreement = "every piece is proven rigid on its own";
  else if (some_folds && r.verdict == FoldabilityClass::kFoldable && r.dof != dof)
    disagreement = "the pieces' DOF add up to " + std::to_string(dof) + ", not " + std::to_string(r.dof);
  r.reason += "; " + std::to_string(r.pieces.size()) + " pieces checked separately" +
              (disagreement.empty() ? " (they agree)" : ", which disagree with the whole sheet's check: " + disagreement);
}

}  // namespace

FoldabilityReport check_foldability(const CreasePattern& pattern, const Topology& topology,
                                    const FoldabilityOptions& options) {
  const auto start = Clock::now();
  if (options.coordinate_tolerance && !(*options.coordinate_tolerance >= 0 && std::isfinite(*options.coordinate_tolerance)))
    throw std::invalid_argument("check_foldability: coordinate_tolerance must be finite and >= 0");
  FoldabilityReport r;
  r.assignment_used = options.use_assignment;
  r.tolerances = options.tolerances;
  const std::string precision = describe_input_precision(pattern, options.coordinate_tolerance);
  r.coordinate_precision = precision;
  try {
    report_progress(options.progress, [] { return std::string("choosing the model"); });
    const ModelChoice c = choose_model(pattern, topology, options);
    r.model_choice = c.why;
    report_progress(options.progress, [&] { return "model: " + std::string(to_string(c.model)); });
    std::optional<StraightLineAnalysis> lines;  // computed once, where a model needs it
    switch (c.model) {
      case FoldabilityModel::kGivenStateHoleClosure: given_state_report(pattern, topology, options, r); break;
      case FoldabilityModel::kMultiplierPropagation:
        if (c.flat_witness) {
          // Within the input's precision: the model's exact verdict on the witness.
          const FlatFoldableWitness& w = *c.flat_witness;
          multiplier_report(w.witness, w.witness_topology, options, *c.multiplier, r);
          within_precision_report(w, r);
          break;
        }
        if (c.multiplier->verdict != Verdict::kRigidlyFoldable) lines = straight_line_folds(pattern, topology, line_options(options));
        if (!lines || lines->crossing_vertices.empty()) {
          multiplier_report(pattern, topology, options, *c.multiplier, r);
          break;
        }
        // Two straight lines cross at some vertex (multipliers 0 and infinity there): the
        // model's "no" holds for motions that fold every crease, not for one that leaves a
        // line flat, so the general model and the straight-line facts decide.
        r.model_choice += "; but straight crease lines cross at some vertices, where its \"no\" (" + c.multiplier->reason +
                          ") only rules out motions that fold every crease: the general model decides";
        [[fallthrough]];
      default: {
        report_progress(options.progress, [] { return std::string("straight crease lines"); });
        if (!lines) lines = straight_line_folds(pattern, topology, line_options(options));
        if (!lines->folds.empty() && !lines->strict_obstruction_vertices.empty()) {
          // Both questions are settled exactly: weakly foldable (a line folds alone), not
          // strictly (crossing lettered lines). The numerical search could add neither.
          r.model = FoldabilityModel::kGeneralLoopClosure;
          r.model_name = "straight crease lines (exact)";
          r.model_choice += "; a straight line folds alone and straight lettered lines cross: both strict and weak "
                            "foldability are decided exactly, the numerical search is not run";
          r.interference_checked = std::string(kLocalInterferenceOnly) + " (a single line folding: faces cannot cross before 180 deg)";
        } else if (!first_order_loop_gain_report(pattern, topology, options, r)) {
          general_report(pattern, topology, options, r);
        }
        straight_line_report(pattern, topology, options, *lines, r);
        break;
      }
    }
  } catch (const std::runtime_error& e) {  // a solver that cannot handle this sheet (e.g. a handle)
    r = FoldabilityReport{};
    r.assignment_used = options.use_assignment;
    r.tolerances = options.tolerances;
    r.coordinate_precision = precision;
    r.model = FoldabilityModel::kNone;
    r.model_name = "none";
    r.reason = std::string("no solver applies to this pattern: ") + e.what();
  }
  if (topology.components.size() > 1) check_pieces(pattern, topology, options, r);
  answer_the_strict_question(options, r);
  // Letters ignored and no motion found: a motion that keeps the letters is one with them
  // ignored too, so the lettered check's yes, when it has one, is the answer here (a rounded
  // Miura-ori's witness is decided by the multiplier model only with its letters).
  if (!options.use_assignment && !r.foldable() &&
      std::any_of(pattern.assignments.begin(), pattern.assignments.end(),
                  [](Assignment a) { return assigned_fold_sign(a) != 0; })) {
    FoldabilityOptions keep_letters = options;
    keep_letters.use_assignment = true;
    FoldabilityReport with = check_foldability(pattern, topology, keep_letters);
    if (with.foldable()) {
      with.assignment_used = false;
      with.model_choice = "letters ignored: " + r.model_choice + " - " + r.reason +
                          "; a motion that keeps the letters is a motion with them ignored, so the check with the "
                          "letters answers: " + with.model_choice;
      r = std::move(with);
    }
  }
  r.seconds = seconds_since(start);
  return r;
}

}  // namespace rigidfold
