#include "kernel/thick/thick_report.hpp"
#include "kernel/math/angle_units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "kernel/analysis/trace_motion.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/bennett_heights.hpp"
#include "kernel/thick/thick_slabs.hpp"

namespace rigidfold {

namespace {


std::vector<double> placement_heights(const CreasePattern& flat, const Topology& topology, double t, ThickHinges hinges) {
  std::vector<double> h(flat.num_edges(), 0.0);
  for (int e = 0; e < flat.num_edges(); ++e) {
    switch (hinges) {
      case ThickHinges::kTop: h[e] = hinge_height(0.0, t, HingePlacement::kTop); break;
      case ThickHinges::kBottom: h[e] = hinge_height(0.0, t, HingePlacement::kBottom); break;
      case ThickHinges::kMid: h[e] = hinge_height(0.0, t, HingePlacement::kMid); break;
      case ThickHinges::kValley:
        if (!topology.edge_is_hinge[e]) break;
        if (flat.assignments[e] == Assignment::Valley) h[e] = hinge_height(0.0, t, HingePlacement::kTop);
        else if (flat.assignments[e] == Assignment::Mountain) h[e] = hinge_height(0.0, t, HingePlacement::kBottom);
        else throw InputError("hinges", "valley placement needs an M or V letter on every crease; edge " + std::to_string(e) + " has none");
        break;
      case ThickHinges::kBennett: break;
    }
  }
  return h;
}

// Largest wrapped |a - b| over the entries, and where.
double largest_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int& where) {
  double worst = 0.0;
  where = -1;
  for (Eigen::Index e = 0; e < a.size(); ++e) {
    const double d = std::abs(std::remainder(a[e] - b[e], 2 * kPi));
    if (d > worst || where < 0) {
      worst = d;
      where = static_cast<int>(e);
    }
  }
  return worst;
}

void trace_from_flat(const ThickReportRequest& request, ThickReport& report);
void extend_trace(const ThickReportRequest& request, ThickReport& report);
void add_geometry(const CreasePattern& flat, const Topology& topology, const ThickReportRequest& request, ThickReport& report);

}  // namespace

const char* to_string(ThickHinges hinges) {
  switch (hinges) {
    case ThickHinges::kTop: return "top";
    case ThickHinges::kBottom: return "bottom";
    case ThickHinges::kMid: return "mid";
    case ThickHinges::kValley: return "valley";
    case ThickHinges::kBennett: return "bennett";
  }
  return "?";
}

ZeroThicknessSamples zero_thickness_samples(const CreasePattern& flat, const Topology& topology, int steps, double max_drive,
                                            bool reverse) {
  ZeroThicknessSamples out;
  TraceRequest request;
  request.steps = steps;
  MotionTrace trace = trace_motion(flat, topology, request);
  if (reverse && !trace.branches.empty() && trace.branches[0].traced && !trace.branches[0].steps.empty()) {
    const MotionBranch& forward = trace.branches[0];
    request.drive = forward.drive;
    request.to = (forward.to > 0 ? -1.0 : 1.0) * 170.0 * kPi / 180.0;
    trace = trace_motion(flat, topology, request);
  }
  if (trace.branches.empty()) {
    out.note = trace.note.empty() ? "the zero-thickness pattern has no motion to trace" : trace.note;
    return out;
  }
  const MotionBranch& branch = trace.branches[0];
  out.drive = branch.drive;
  if (!branch.traced) {
    out.note = "the zero-thickness motion was not traced: " + branch.message;
    return out;
  }
  for (const MotionStep& step : branch.steps) {
    if (step.drive == 0.0) continue;
    if (!(step.residual <= 1e-10)) break;  // a state that does not pass its own check ends the samples
    if (!(std::abs(step.drive) <= max_drive)) break;
    out.drive_angles.push_back(step.drive);
    out.states.push_back(step.rho);
    out.max_residual = std::max(out.max_residual, step.residual);
  }
  if (out.states.empty()) {
    out.note = "the zero-thickness trace has no state closed to 1e-10 rad within the drive range";
    return out;
  }
  // The same branch to the end (+-180 deg: the flat-folded state where the pattern reaches it)
  // at the same spacing. Its states past the samples are kept only when it passes through
  // every sample (same drive, fold angles within 1e-9 rad): the same branch, not another.
  TraceRequest to_end = request;
  to_end.drive = branch.drive;
  to_end.to = (branch.to > 0 ? 1.0 : -1.0) * kPi;
  to_end.steps = static_cast<int>(std::lround(kPi / std::abs(out.drive_angles[0])));
  const MotionTrace full = trace_motion(flat, topology, to_end);
  if (full.branches.empty() || !full.branches[0].traced) return out;
  const std::vector<MotionStep>& steps_to_end = full.branches[0].steps;
  std::size_t matched = 0;
  for (const MotionStep& step : steps_to_end) {
    if (matched < out.states.size()) {
      if (std::abs(step.drive - out.drive_angles[matched]) <= 1e-12) {
        if (!((step.rho - out.states[matched]).cwiseAbs().maxCoeff() <= 1e-9)) return out;
        ++matched;
      }
      continue;
    }
    if (!(std::abs(step.drive) > std::abs(out.drive_angles.back()))) continue;
    if (!(step.residual <= 1e-10)) break;
    out.further_drive_angles.push_back(step.drive);
    out.further_states.push_back(step.rho);
  }
  if (matched < out.states.size()) {
    out.further_drive_angles.clear();
    out.further_states.clear();
  }
  return out;
}

void require_flat_pattern(const CreasePattern& flat) {
  if (flat.vertices.empty()) return;
  Eigen::Vector3d lo = flat.vertices[0], hi = flat.vertices[0];
  for (const Eigen::Vector3d& v : flat.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double size = (hi - lo).norm();
  for (int v = 0; v < flat.num_vertices(); ++v)
    if (!(std::abs(flat.vertices[v].z()) <= 1e-12 * size))
      throw InputError("pattern", "vertex " + std::to_string(v) +
                                      " is off the plane z = 0: thick panels need the flat crease pattern (a folded form's flat "
                                      "development: rigidfold export)");
}

ThickReport thick_report(const CreasePattern& flat, const Topology& topology, const ThickReportRequest& request) {
  if (!std::isfinite(request.thickness) || !(request.thickness > 0))
    throw InputError("thickness", "must be a finite number > 0");
  require_flat_pattern(flat);
  ThickReport report;
  report.thickness = request.thickness;
  report.hinges = request.hinges;
  const ZeroThicknessSamples& zero = request.zero;
  if (request.hinges == ThickHinges::kBennett) {
    if (zero.states.empty())
      throw InputError("hinges", "bennett needs a folded zero-thickness state to pick each vertex's staircase, and there is none (" +
                                     zero.note + ")");
    // bennett_hinge_heights picks each vertex's staircase as the first start crease that closes
    // at the given state; where two close there (the square twist's vertices), the pick can
    // differ between states and only some picks agree round a cycle. So each sample is tried,
    // the most folded first; the heights found are then checked against every sample (the
    // off-motion test) and by the trace.
    std::string first_failure;
    for (auto it = zero.states.rbegin(); it != zero.states.rend() && report.edge_heights.empty(); ++it) {
      try {
        report.edge_heights = bennett_hinge_heights(flat, topology, *it, request.thickness);
      } catch (const std::invalid_argument& e) {
        if (first_failure.empty()) first_failure = e.what();
      }
    }
    if (report.edge_heights.empty())
      throw InputError("hinges", "no Bennett hinge heights: " + first_failure + " (the most folded of " +
                                     std::to_string(zero.states.size()) +
                                     " zero-thickness states; at every one the staircases picked disagree somewhere, though a "
                                     "vertex where two staircases close leaves picks that were not tried)");
  } else {
    report.edge_heights = placement_heights(flat, topology, request.thickness, request.hinges);
  }
  report.sheet = thick_sheet_from_hinge_heights(flat, topology, report.edge_heights);
  const Eigen::VectorXd flat_state = Eigen::VectorXd::Zero(flat.num_edges());
  report.mobility = thick_mobility(report.sheet, flat_state, zero.states, request.closure_tolerance);
  report.drive = zero.drive;
  trace_from_flat(request, report);
  extend_trace(request, report);
  if (request.check_geometry) add_geometry(flat, topology, request, report);
  return report;
}

namespace {

void trace_from_flat(const ThickReportRequest& request, ThickReport& report) {
  const ZeroThicknessSamples& zero = request.zero;
  const Eigen::VectorXd flat_state = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(report.edge_heights.size()));
  if (report.mobility.dof < 1) {
    report.trace_note = "DOF 0 at the flat state (a regular point when the smallest kept singular value is well above the cut): the thick sheet does not fold";
    return;
  }
  if (zero.states.empty()) {
    report.trace_note = "no zero-thickness states to drive and compare with" + (zero.note.empty() ? std::string() : ": " + zero.note);
    return;
  }

  const ClosureSystem system(report.sheet.pattern, report.sheet.topology, report.sheet.options);
  const int held = system.unknown_of_edge(zero.drive);
  if (held < 0) {
    report.trace_note = "the driving crease " + std::to_string(zero.drive) + " is not free in the thick sheet";
    return;
  }
  auto unknowns = [&](const Eigen::VectorXd& fold) { return system.unknowns_from_edges(report.sheet.sheet_edge_angles(fold)); };
  auto folds = [&](const Eigen::VectorXd& x) { return report.sheet.fold_angles(system.edges_from_unknowns(x)); };
  NewtonOptions newton;
  newton.tolerance = 1e-13;
  newton.held_unknowns = {held};

  // One Newton projection with the drive held at `drive`, from thick state `from` moved by the
  // zero-thickness increment `increment`.
  auto project = [&](const Eigen::VectorXd& from, const Eigen::VectorXd& increment, double drive, Eigen::VectorXd& to) {
    Eigen::VectorXd guess = from + increment;
    guess[zero.drive] = drive;
    const NewtonResult result = newton_project(system, unknowns(guess), newton);
    if (!result.converged) return false;
    to = folds(result.x);
    return true;
  };

  Eigen::VectorXd thick = flat_state, zero_previous = flat_state;
  double drive_previous = 0.0;
  for (std::size_t k = 0; k < zero.states.size(); ++k) {
    const Eigen::VectorXd& target = zero.states[k];
    const double drive = zero.drive_angles[k];
    // Up to 2^5 equal sub-steps between the previous state and this one.
    bool reached = false;
    Eigen::VectorXd next;
    for (int pieces = 1; pieces <= 32 && !reached; pieces *= 2) {
      Eigen::VectorXd at = thick;
      bool ok = true;
      for (int s = 1; s <= pieces && ok; ++s) {
        const double fraction = static_cast<double>(s) / pieces;
        const Eigen::VectorXd increment = (target - zero_previous) / pieces;
        ok = project(at, increment, drive_previous + fraction * (drive - drive_previous), at);
      }
      if (ok) {
        reached = true;
        next = at;
      }
    }
    if (!reached) {
      std::ostringstream note;
      note << "Newton projection did not reach the driving angle " << drive << " rad (from " << drive_previous << ")";
      report.trace_note = note.str();
      break;
    }
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    system.evaluate(unknowns(next), r, J);
    ThickTraceStep step;
    step.drive = drive;
    step.rho = next;
    step.residual = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
    if (!(step.residual <= request.closure_tolerance)) {
      std::ostringstream note;
      note << "the state at driving angle " << drive << " rad closes only to " << step.residual << " (> "
           << request.closure_tolerance << "); the trace ends before it";
      report.trace_note = note.str();
      break;
    }
    step.deviation = largest_difference(next, target, step.worst_edge);
    step.dof = jacobian_rank(J).dof;
    report.max_deviation = std::max(report.max_deviation, step.deviation);
    report.max_trace_residual = std::max(report.max_trace_residual, step.residual);
    report.trace.push_back(step);
    thick = next;
    zero_previous = target;
    drive_previous = drive;
  }
}

void extend_trace(const ThickReportRequest& request, ThickReport& report) {
  const ZeroThicknessSamples& zero = request.zero;
  if (zero.further_states.empty() || report.trace.size() != zero.states.size() ||
      !(report.max_deviation <= request.closure_tolerance))
    return;
  const ClosureSystem system(report.sheet.pattern, report.sheet.topology, report.sheet.options);
  for (std::size_t k = 0; k < zero.further_states.size(); ++k) {
    const Eigen::VectorXd& rho = zero.further_states[k];
    const Eigen::VectorXd r = system.residual(system.unknowns_from_edges(report.sheet.sheet_edge_angles(rho)));
    ThickTraceStep step;
    step.drive = zero.further_drive_angles[k];
    step.rho = rho;
    step.residual = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
    if (!(step.residual <= request.closure_tolerance)) break;
    step.deviation = 0.0;
    step.worst_edge = zero.drive;
    step.dof = -1;
    report.extension.push_back(step);
  }
}

void add_geometry(const CreasePattern& flat, const Topology& topology, const ThickReportRequest& request, ThickReport& report) {
  report.slabs = panel_slabs(flat, topology, report);
  std::vector<double> drives{0.0};
  std::vector<Eigen::VectorXd> states{Eigen::VectorXd::Zero(flat.num_edges())};
  report.end.drive = 0.0;
  report.end.rho = states[0];
  report.end.residual = report.mobility.state_residual;
  report.end.dof = report.mobility.dof;
  for (const std::vector<ThickTraceStep>* part : {&report.trace, &report.extension})
    for (const ThickTraceStep& s : *part) {
      drives.push_back(s.drive);
      states.push_back(s.rho);
      report.end = s;
    }
  report.end_is_extension = !report.extension.empty();
  double thinnest = request.thickness;
  for (const PanelSlab& s : report.slabs) thinnest = std::min(thinnest, s.top - s.bottom);
  const double margin = request.interference_margin > 0 ? request.interference_margin : 1e-4 * thinnest;
  report.interference = slab_interference(flat, topology, report.sheet, report.slabs, drives, states, margin);
  report.stacking = stacking_order(flat, topology, report.sheet, report.slabs, report.end.rho);
}

}  // namespace

ThickTraceStep thick_state_at(const ThickReport& report, double drive, double closure_tolerance) {
  if (report.trace.empty()) throw InputError("at", "there is no traced thick motion to place (" + report.trace_note + ")");
  const double last = report.trace.back().drive;
  if (!std::isfinite(drive) || drive * last < 0 || std::abs(drive) > std::abs(last)) {
    std::ostringstream m;
    m << "the driving crease " << report.drive << " is traced from 0 to " << last * 180 / kPi << " deg; " << drive * 180 / kPi
      << " deg is outside";
    throw InputError("at", m.str());
  }
  const ClosureSystem system(report.sheet.pattern, report.sheet.topology, report.sheet.options);
  Eigen::VectorXd below = Eigen::VectorXd::Zero(report.trace.back().rho.size()), above = below;
  double d_below = 0.0, d_above = 0.0;
  for (const ThickTraceStep& s : report.trace) {
    above = s.rho;
    d_above = s.drive;
    if (std::abs(s.drive) >= std::abs(drive)) break;
    below = s.rho;
    d_below = s.drive;
  }
  const double f = d_above == d_below ? 0.0 : (drive - d_below) / (d_above - d_below);
  Eigen::VectorXd guess = below + f * (above - below);
  guess[report.drive] = drive;
  NewtonOptions newton;
  newton.tolerance = 1e-13;
  newton.held_unknowns = {system.unknown_of_edge(report.drive)};
  const NewtonResult result =
      newton_project(system, system.unknowns_from_edges(report.sheet.sheet_edge_angles(guess)), newton);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(result.x, r, J);
  ThickTraceStep step;
  step.drive = drive;
  step.rho = report.sheet.fold_angles(system.edges_from_unknowns(result.x));
  step.residual = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
  if (!(step.residual <= closure_tolerance)) {
    std::ostringstream m;
    m << "the thick state at driving angle " << drive * 180 / kPi << " deg closes only to " << step.residual << " rad";
    throw NoAnswerError(m.str(), step.residual);
  }
  step.dof = jacobian_rank(J).dof;
  step.deviation = std::nan("");  // no zero-thickness state at this angle
  return step;
}

}  // namespace rigidfold
