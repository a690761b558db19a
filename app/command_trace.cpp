// rigidfold trace PATTERN.fold [--branch ID|all] [--drive EDGE] [--to DEG] [--steps N]
//                [--out FRAMES.fold] [--csv ANGLES.csv] [--json] [--ignore-assignment] [--general]
// Traces a folding motion of a pattern, driven by one crease, at N equally spaced driving
// angles (to*k/N, k = 1..N; the flat state is the key frame, not a step).
//
// Model (DESIGN.md, "Model only what a scene needs"):
//   - multiplier propagation when it applies and the verdict is foldable: the motion is the
//     fold family tan(rho_e/2) = m_e * t_c, one branch per family component c (exact);
//   - otherwise (or with --general) the general loop-closure solver: a start by Newton
//     projection from a small fold of the driving crease (held), 1-DOF pseudo-arclength
//     continuation to the target, then at every driving angle a projection with the driving
//     crease held. One branch (id 0). If the DOF at the start is not 1, it says so and
//     traces nothing (exit 0). With --branch ID|all: every branch through the flat state and
//     the bifurcations (kernel/analysis/branch_explorer.hpp), each traced to its end, steps at
//     the continuation's points; --to / --steps / --drive do not apply there.
//   - a sheet with holes (a tube): the two branches through its given 3D state, traced with
//     the SE(3) hole closures (kernel/analysis/reference_mobility.hpp); the given state is
//     the first step; branch 0 by default, --branch 1|all for the other; --to / --steps /
//     --drive do not apply.
//   - applicable but not foldable (for the assignment, or in any mode with
//     --ignore-assignment): nothing to trace; the obstruction is reported (exit 0).
// Per step: every fold angle, the largest vertex-closure residual |log R_v| (rad), the
// face-placement closure mismatch (length units), and events:
//   "interference:eK"  crease K reaches +-180 deg (local interference limit);
//   "mv_switch:eK"     M/V crease K changes sign against its letter: starts folding against
//                      it (also at step 1 if it starts so) or returns to it;
//   "sign_change:eK"   U crease K changes sign.
// Outputs (all rendered before any is written; each written atomically):
//   --out  FOLD: the pattern as key frame plus one foldedForm frame per step;
//   --csv  step,drive_deg,max_residual_rad,mismatch,events,e0_deg,e1_deg,...
//   With several branches (--branch all) each file gets ".b<ID>" before its extension.
// Bad flags (--drive out of range / not a foldable crease / flat in the family, |--to| > 180
// or 0, --steps < 1, unknown branch) exit 2 naming the flag; no file is written.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include <Eigen/SparseCore>

#include "app/commands.hpp"
#include "kernel/analysis/branch_explorer.hpp"
#include "kernel/analysis/reference_mobility.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/closure/vertex_residuals.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold::cli {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;
constexpr double kInterferenceTol = 1e-9;  // |rho| >= pi - tol counts as reaching 180 deg
constexpr double kSignTol = 1e-9;          // |rho| above this has a sign

struct Event {
  int step = 0;
  std::string kind;  // "interference" or "mv_switch"
  int edge = -1;
  double drive = 0, angle = 0;  // radians
};

struct Step {
  double drive = 0;     // radians
  Eigen::VectorXd rho;  // per edge, radians
  double residual = 0;  // max vertex closure residual, rad
  FoldedGeometry folded;
  std::vector<std::string> events;
};

struct Branch {
  int id = 0;
  int drive = -1;
  double to = 0;            // requested final drive (rad)
  double reached = 0;       // final drive actually traced (rad)
  bool traced = false;
  int dof = -1;             // general model: DOF at the start (-1 unknown)
  std::string stopped_by;   // why the trace ends where it does
  std::string message;      // set when not traced, or a warning
  std::vector<Step> steps;
  std::vector<Event> events;
  double max_residual = 0, max_mismatch = 0;
};

double assigned_sign(Assignment a) { return a == Assignment::Mountain ? -1.0 : 1.0; }

std::string deg_text(double radians) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", radians * kDeg);
  return buf;
}

std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// Fills residual, placement and events of the steps (in order).
void finish_steps(Branch& b, const CreasePattern& p, const Topology& t, const Eigen::VectorXd& ref) {
  std::vector<bool> reached(p.num_edges(), false);
  // Per crease: its last non-zero sign relative to its letter (M/V; +1 with it, the flat
  // state counting as with it) or its last non-zero sign (U).
  std::vector<int> last(p.num_edges(), 0);
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] == Assignment::Mountain || p.assignments[e] == Assignment::Valley) last[e] = 1;
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    Step& s = b.steps[k];
    s.residual = max_vertex_closure_residual(t, s.rho);
    s.folded = place_faces(p, t, s.rho, ref);
    b.max_residual = std::max(b.max_residual, s.residual);
    b.max_mismatch = std::max(b.max_mismatch, s.folded.max_mismatch);
    const int step = static_cast<int>(k + 1);
    for (int e = 0; e < p.num_edges(); ++e) {
      const double r = s.rho[e];
      if (!reached[e] && std::fabs(r) >= kPi - kInterferenceTol) {
        reached[e] = true;
        s.events.push_back("interference:e" + std::to_string(e));
        b.events.push_back({step, "interference", e, s.drive, r});
      }
      if (std::fabs(r) <= kSignTol) continue;
      const int sign = r > 0 ? 1 : -1;
      const Assignment a = p.assignments[e];
      if (a == Assignment::Mountain || a == Assignment::Valley) {
        const int rel = sign * static_cast<int>(assigned_sign(a));
        if (rel != last[e]) {  // starts folding against its letter, or returns to it
          s.events.push_back("mv_switch:e" + std::to_string(e));
          b.events.push_back({step, "mv_switch", e, s.drive, r});
        }
        last[e] = rel;
      } else if (a == Assignment::Unassigned) {
        if (last[e] != 0 && sign != last[e]) {
          s.events.push_back("sign_change:e" + std::to_string(e));
          b.events.push_back({step, "sign_change", e, s.drive, r});
        }
        last[e] = sign;
      }
    }
  }
}

// ---- multiplier model -------------------------------------------------------------------

// rho of every edge of component c at parameter t (t may be +-inf: fully folded).
Eigen::VectorXd family_angles(const FoldFamily& f, int c, double t) {
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(f.component.size()));
  for (std::size_t e = 0; e < f.component.size(); ++e) {
    if (f.component[e] != c || f.multiplier[e] == 0.0) continue;
    rho[e] = std::isinf(t) ? std::copysign(kPi, f.multiplier[e] * t) : 2.0 * std::atan(f.multiplier[e] * t);
  }
  return rho;
}

Branch trace_family(const FoldFamily& f, int c, int drive, double to, int steps) {
  Branch b;
  b.id = c;
  b.drive = drive;
  b.to = b.reached = to;
  b.traced = true;
  b.stopped_by = std::fabs(to) >= kPi ? "driving crease reaches 180 deg (fully folded; local interference limit)"
                                      : "target driving angle reached";
  for (int k = 1; k <= steps; ++k) {
    const double d = to * k / steps;
    const double t = std::fabs(d) >= kPi ? std::copysign(std::numeric_limits<double>::infinity(), d / f.multiplier[drive])
                                         : f.parameter_for(drive, d);
    Step s;
    s.drive = d;
    s.rho = family_angles(f, c, t);
    s.rho[drive] = d;  // exact driving value (the family gives it to rounding)
    b.steps.push_back(std::move(s));
  }
  return b;
}

// ---- general solver ---------------------------------------------------------------------

double max_abs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

Branch trace_general(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& ref, int drive, double to,
                     int steps, bool ignore_assignment) {
  Branch b;
  b.id = 0;
  b.drive = drive;
  b.to = to;
  std::unique_ptr<ClosureSystem> sys;
  try {
    sys = std::make_unique<ClosureSystem>(p, t);
  } catch (const std::runtime_error& e) {
    b.message = std::string("general solver unavailable: ") + e.what();
    return b;
  }
  const int kd = sys->unknown_of_edge(drive);
  const double dir = to > 0 ? 1.0 : -1.0;
  NewtonOptions nopt;
  nopt.held_unknowns = {kd};
  nopt.max_iterations = 60;
  auto project = [&](Eigen::VectorXd x, double d) {
    x[kd] = d;
    return newton_project(*sys, x, nopt);
  };
  // Start: a small fold of the driving crease, the rest projected.
  const Eigen::VectorXd x_ref = sys->unknowns_from_edges(ref);
  const double delta = dir * std::min(std::fabs(to) / steps, 5.0 / kDeg);
  // The initial guess folds every M/V crease a little in its letter's direction (mirrored
  // if the drive goes against its own letter), so that the projection lands on the branch
  // the assignment selects: the flat state is a bifurcation point and a plain minimum-norm
  // step from it picks an arbitrary branch. With the assignment ignored: plain projection.
  Eigen::VectorXd guess = x_ref;
  if (!ignore_assignment) {
    const double mirror = dir * assigned_sign(p.assignments[drive]);
    for (int k = 0; k < sys->num_unknowns(); ++k) {
      const Assignment a = p.assignments[sys->edge_of_unknown(k)];
      if (a == Assignment::Mountain || a == Assignment::Valley) guess[k] += mirror * assigned_sign(a) * std::fabs(delta);
    }
  }
  const NewtonResult start = project(guess, x_ref[kd] + delta);
  if (!start.converged) {
    const double best = *std::min_element(start.residual_history.begin(), start.residual_history.end());
    b.message = "general solver: no folded state found near the reference with crease " + std::to_string(drive) +
                " held at " + deg_text(x_ref[kd] + delta) + " deg (smallest residual " + num(best) +
                " rad after " + std::to_string(start.iterations) +
                " Newton steps); the pattern may not fold from this state (0 DOF)";
    return b;
  }
  {
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys->evaluate(start.x, r, J);
    b.dof = jacobian_rank(J).dof;
  }
  if (b.dof != 1) {
    b.message = "general solver: DOF at the start (crease " + std::to_string(drive) + " at " +
                deg_text(start.x[kd]) + " deg) is " + std::to_string(b.dof) +
                ", not 1; 1-DOF continuation does not apply, nothing traced";
    return b;
  }
  // Continuation to the target (or until a crease reaches 180 deg).
  Eigen::VectorXd direction = Eigen::VectorXd::Zero(sys->num_unknowns());
  direction[kd] = dir;
  auto stop = [&](const Eigen::VectorXd& x) {
    return dir * x[kd] >= std::fabs(to) || max_abs(sys->edges_from_unknowns(x)) >= kPi;
  };
  ContinuationOptions copt;
  copt.max_step = 0.1;
  copt.max_points = 20000;
  const ContinuationResult path = continue_one_dof(*sys, start.x, direction, stop, copt);
  if (path.points.empty()) {
    b.message = "general solver: continuation failed at the start (" + path.reason + ")";
    return b;
  }
  // The usable stretch: the reference, then the path while the drive advances and no crease
  // has reached 180 deg.
  std::vector<Eigen::VectorXd> xs{x_ref};
  std::vector<double> ds{dir * x_ref[kd]};
  b.stopped_by = "target driving angle reached";
  double limit = std::fabs(to);
  bool clamped = false;
  std::optional<Eigen::VectorXd> x_end;  // the located end point, when the trace ends at 180 deg
  for (const auto& pt : path.points) {
    const double d = dir * pt.x[kd];
    if (max_abs(sys->edges_from_unknowns(pt.x)) >= kPi) {
      // Locate where the first crease reaches 180 deg (projections with the drive held).
      auto g = [&](double dd, Eigen::VectorXd& x_out) {
        const double s = std::clamp((dd - ds.back()) / (d - ds.back()), 0.0, 1.0);
        const NewtonResult r = project(xs.back() + s * (pt.x - xs.back()), dir * dd);
        x_out = r.x;
        if (!r.converged) return std::numeric_limits<double>::infinity();
        return max_abs(sys->edges_from_unknowns(r.x)) - kPi;
      };
      double lo = ds.back(), hi = d, g_lo = max_abs(sys->edges_from_unknowns(xs.back())) - kPi;
      Eigen::VectorXd x_lo = xs.back();
      // Bisection (robust where the largest fold meets pi tangentially); the answer is
      // the low end, where every |rho| <= pi. A projection that fails counts as beyond.
      for (int it = 0; it < 80 && hi - lo > 1e-14; ++it) {
        const double mid = 0.5 * (lo + hi);
        Eigen::VectorXd xm;
        const double gm = g(mid, xm);
        if (gm < 0) {
          lo = mid;
          g_lo = gm;
          x_lo = xm;
        } else {
          hi = mid;
        }
      }
      if (lo < limit) {
        limit = lo;
        clamped = true;
        x_end = x_lo;  // near a singular end the projection of another guess may land elsewhere
        if (-g_lo <= kInterferenceTol)
          b.stopped_by = "a crease reaches 180 deg at driving angle " + deg_text(dir * lo) +
                         " deg (local interference limit)" + (std::fabs(to) - lo > 1e-9 ? "; clamped" : "");
        else
          b.stopped_by = "the projections stop converging at driving angle " + deg_text(dir * lo) + " deg, " +
                         deg_text(-g_lo) + " deg short of a crease reaching 180 deg (a singular point, e.g. the "
                         "fully folded state); clamped";
      }
      break;
    }
    if (d <= ds.back()) {
      if (ds.back() < limit) {
        limit = ds.back();
        clamped = true;
        b.stopped_by = "the driving crease turns back at " + deg_text(dir * limit) +
                       " deg (a fold point of the drive; choose another --drive); clamped";
      }
      break;
    }
    xs.push_back(pt.x);
    ds.push_back(d);
  }
  if (!clamped && ds.back() < limit) {
    limit = ds.back();
    clamped = true;
    b.stopped_by = "continuation stopped (" + path.reason + ") at driving angle " + deg_text(dir * limit) +
                   " deg; clamped";
  }
  b.reached = dir * limit;
  int failures = 0;
  double worst_fail = 0;
  for (int k = 1; k <= steps; ++k) {
    const double d = limit * k / steps;
    std::size_t j = 1;
    while (j + 1 < ds.size() && ds[j] < d) ++j;
    Eigen::VectorXd guess;
    if (ds.size() < 2) {
      guess = xs.back();
    } else {
      const double s = std::clamp((d - ds[j - 1]) / (ds[j] - ds[j - 1]), 0.0, 1.0);
      guess = xs[j - 1] + s * (xs[j] - xs[j - 1]);
    }
    if (k == steps && x_end) {
      Step s;
      s.drive = dir * d;
      s.rho = sys->edges_from_unknowns(*x_end);
      b.steps.push_back(std::move(s));
      continue;
    }
    NewtonResult r = project(guess, dir * d);
    {
      // Polish: one or two more steps take ||r||_inf from <= 1e-12 to rounding level, so
      // the per-vertex residual norm reported is <= 1e-12 too.
      NewtonOptions polish = nopt;
      polish.tolerance = 0.0;
      polish.max_iterations = 2;
      const NewtonResult q = newton_project(*sys, r.x, polish);
      if (q.residual_history.back() < r.residual_history.back()) {
        r.x = q.x;
        r.residual_history.push_back(q.residual_history.back());
        r.converged = r.converged || q.residual_history.back() <= nopt.tolerance;
      }
    }
    if (!r.converged) {
      ++failures;
      worst_fail = std::max(worst_fail, r.residual_history.back());
    }
    Step s;
    s.drive = dir * d;
    s.rho = sys->edges_from_unknowns(r.x);
    b.steps.push_back(std::move(s));
  }
  b.traced = true;
  if (failures > 0)
    b.message = std::to_string(failures) + " step(s) did not converge to 1e-12 (worst residual " + num(worst_fail) +
                " rad); their residual is reported as reached";
  return b;
}

// ---- outputs ----------------------------------------------------------------------------

std::string branch_path(const std::string& path, int id, bool several) {
  if (!several) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + ".b" + std::to_string(id) + p.extension().string())).string();
}

std::string csv_text(const Branch& b, int num_edges) {
  std::string s = "step,drive_deg,max_residual_rad,mismatch,events";
  for (int e = 0; e < num_edges; ++e) {
    s += ",e";
    s += std::to_string(e);
    s += "_deg";
  }
  s += "\n";
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    const Step& st = b.steps[k];
    std::string ev;
    for (const auto& x : st.events) {
      if (!ev.empty()) ev += ';';
      ev += x;
    }
    s += std::to_string(k + 1) + "," + num(st.drive * kDeg) + "," + num(st.residual) + "," +
         num(st.folded.max_mismatch) + "," + ev;
    for (int e = 0; e < num_edges; ++e) {
      s += ',';
      s += num(st.rho[e] * kDeg);
    }
    s += "\n";
  }
  return s;
}

std::string frames_text(const Branch& b, const CreasePattern& p) {
  CreasePattern out = p;
  CreasePattern bare = p;
  bare.extra.erase("file_frames");
  if (!out.extra.contains("file_frames")) out.extra["file_frames"] = Json::array();
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    const Step& st = b.steps[k];
    const std::string title = "rigidfold trace: branch " + std::to_string(b.id) + ", step " + std::to_string(k + 1) +
                              ", crease " + std::to_string(b.drive) + " at " + deg_text(st.drive) + " deg";
    CreasePattern one = with_folded_frame(bare, st.folded, st.rho, title);
    Json frame = one.extra["file_frames"].back();
    frame["rigidfold:max_residual_rad"] = st.residual;
    out.extra["file_frames"].push_back(std::move(frame));
  }
  return write_fold_string(out);
}

Json branch_json(const Branch& b, const CreasePattern& p) {
  Json j;
  j["branch"] = b.id;
  j["traced"] = b.traced;
  j["drive_edge"] = b.drive;
  j["drive_assignment"] = std::string(1, assignment_letter(p.assignments[b.drive]));
  j["to_deg"] = b.to * kDeg;
  j["reached_deg"] = b.traced ? Json(b.reached * kDeg) : Json(nullptr);
  j["steps"] = b.steps.size();
  if (b.dof >= 0) j["dof_at_start"] = b.dof;
  j["stopped_by"] = b.stopped_by;
  j["max_residual"] = b.max_residual;
  j["max_mismatch"] = b.max_mismatch;
  Json ev = Json::array();
  for (const auto& e : b.events)
    ev.push_back({{"step", e.step}, {"kind", e.kind}, {"edge", e.edge}, {"drive_deg", e.drive * kDeg},
                  {"angle_deg", e.angle * kDeg}});
  j["events"] = ev;
  j["message"] = b.message;
  return j;
}

// ---- flag checks ------------------------------------------------------------------------

void check_drive(const CreasePattern& p, const Topology& t, int e) {
  if (e < 0 || e >= p.num_edges())
    throw InputError("--drive", "edge index " + std::to_string(e) + " out of range (" + std::to_string(p.num_edges()) +
                                    " edges)");
  if (!t.edge_is_hinge[e])
    throw InputError("--drive", "edge " + std::to_string(e) + " is not a crease between two faces (assignment " +
                                    std::string(1, assignment_letter(p.assignments[e])) + "); it cannot fold");
  if (!is_foldable_crease(p.assignments[e]))
    throw InputError("--drive", "edge " + std::to_string(e) + " is assigned " +
                                    std::string(1, assignment_letter(p.assignments[e])) + " (rigid); it cannot fold");
}

}  // namespace

void add_trace_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("trace", "Trace a folding branch: fold angles, closure residual and events per step");
  struct Args {
    std::string pattern, branch, out, csv;
    std::optional<int> drive;
    std::optional<double> to;
    int steps = 50;
    bool json = false, ignore = false, general = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold)")->required();
  cmd->add_option("--branch", a->branch, "branch id (multiplier model: one per family component) or 'all'");
  cmd->add_option("--drive", a->drive, "driving crease (edge index); default: largest multiplier of the branch");
  cmd->add_option("--to", a->to, "final fold of the driving crease, deg in [-180, 180], not 0; default 170 in its assigned direction");
  cmd->add_option("--steps", a->steps, "number of equally spaced driving angles (default 50)");
  cmd->add_option("--out", a->out, "multi-frame FOLD: key frame plus one foldedForm frame per step");
  cmd->add_option("--csv", a->csv, "CSV: step,drive_deg,max_residual_rad,mismatch,events,e0_deg,...");
  cmd->add_flag("--json", a->json, "print the summary as JSON");
  cmd->add_flag("--ignore-assignment", a->ignore, "ignore the M-V assignment (any signs)");
  cmd->add_flag("--general", a->general, "force the general loop-closure solver");
  cmd->callback([a] {
    const CreasePattern p = read_fold(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    if (a->steps < 1 || a->steps > 1000000) throw InputError("--steps", "must be between 1 and 1000000");
    if (a->to && (!std::isfinite(*a->to) || std::fabs(*a->to) > 180.0))
      throw InputError("--to", "fold angle must be finite and within [-180, 180] deg");
    if (a->to && *a->to == 0.0) throw InputError("--to", "must not be 0 (the flat state is the key frame)");
    if (a->drive) check_drive(p, t, *a->drive);
    const bool all = a->branch == "all";
    std::optional<int> branch_id;
    if (!a->branch.empty() && !all) {
      std::size_t used = 0;
      int id = -1;
      try {
        id = std::stoi(a->branch, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != a->branch.size() || id < 0) throw InputError("--branch", "must be a branch id (0, 1, ...) or 'all'");
      branch_id = id;
    }
    const Eigen::VectorXd ref = reference_fold_angles(p, t);
    auto target = [&](int drive) {
      return a->to ? *a->to / kDeg : assigned_sign(p.assignments[drive]) * 170.0 / kDeg;
    };

    Json j = {{"file", a->pattern}};
    j["assignment"] = a->ignore ? "ignored" : "as given (sign constraints)";
    std::vector<Branch> branches;
    std::string model, note;
    std::optional<FoldabilityVerdict> verdict;
    if (!a->general) {
      const MultiplierApplicability app_ = multiplier_model_applicable(p, t);
      if (app_.applicable) verdict = a->ignore ? verdict_ignoring_assignment(p, t) : verdict_with_assignment(p, t);
      else note = "multiplier model not applicable: " + app_.reason;
    } else {
      note = "general solver forced (--general)";
    }
    int holes = 0;
    for (const Component& c : t.components) holes += c.holes;
    if (holes > 0) {
      // A sheet with holes (a tube): the branches through its given 3D state, traced both
      // ways with the SE(3) hole closures (reference_mobility.hpp); --drive/--to/--steps do
      // not apply. Without --branch: branch 0.
      ReferenceMobilityOptions mo;
      mo.use_assignment = !a->ignore;
      const ReferenceMobility m = reference_mobility(p, t, mo);
      model = "general loop-closure solver with SE(3) hole closures, from the given state";
      note = std::to_string(holes) + " hole(s); DOF " + std::to_string(m.dof) + " at the given state; " + m.reason;
      if (branch_id && *branch_id >= static_cast<int>(m.branches.size()))
        throw InputError("--branch", "branch " + std::to_string(*branch_id) + " does not exist (" +
                                         std::to_string(m.branches.size()) + " branches)");
      for (const MobilityBranch& mb : m.branches) {
        if (branch_id ? mb.id != *branch_id : (!all && mb.id != 0)) continue;
        Branch b;
        b.id = mb.id;
        b.drive = mb.driving_edge;
        b.to = b.reached = mb.driving_end;
        b.dof = m.dof;
        b.traced = !mb.path.empty();
        b.stopped_by = mb.stopped_by;
        b.max_residual = mb.max_residual;  // hole rows included (finish_steps adds the vertex rows)
        if (!b.traced) b.message = "not traced: " + mb.stopped_by;
        Step start;  // the given state is the key frame
        start.rho = ref;
        start.drive = ref[mb.driving_edge];
        b.steps.push_back(std::move(start));
        for (const Eigen::VectorXd& rho : mb.path) {
          Step st;
          st.rho = rho;
          st.drive = rho[mb.driving_edge];
          b.steps.push_back(std::move(st));
        }
        branches.push_back(std::move(b));
      }
    } else if (verdict && verdict->verdict == Verdict::kRigidlyFoldable && verdict->family) {
      model = verdict->model;
      const FoldFamily& f = *verdict->family;
      if (f.num_components == 0) throw std::runtime_error("foldable verdict with an empty family");
      std::vector<int> ids;
      if (all) {
        for (int c = 0; c < f.num_components; ++c) ids.push_back(c);
        if (a->drive && f.num_components > 1)
          throw InputError("--drive", "with --branch all and " + std::to_string(f.num_components) +
                                          " branches, give --branch ID instead (each branch has its own creases)");
      } else if (branch_id) {
        if (*branch_id >= f.num_components)
          throw InputError("--branch", "branch " + std::to_string(*branch_id) + " does not exist (" +
                                           std::to_string(f.num_components) + " branches: 0.." +
                                           std::to_string(f.num_components - 1) + ")");
        ids.push_back(*branch_id);
      } else {
        ids.push_back(a->drive && f.component[*a->drive] >= 0 ? f.component[*a->drive] : 0);
      }
      for (int c : ids) {
        int drive = -1;
        if (a->drive) {
          drive = *a->drive;
          if (f.component[drive] < 0 || f.multiplier[drive] == 0.0)
            throw InputError("--drive", "crease " + std::to_string(drive) + " stays flat in the fold family");
          if (f.component[drive] != c)
            throw InputError("--drive", "crease " + std::to_string(drive) + " belongs to branch " +
                                            std::to_string(f.component[drive]) + ", not " + std::to_string(c));
        } else {
          double best = -1;
          for (int e = 0; e < p.num_edges(); ++e)
            if (f.component[e] == c && std::fabs(f.multiplier[e]) > best) {
              best = std::fabs(f.multiplier[e]);
              drive = e;
            }
        }
        branches.push_back(trace_family(f, c, drive, target(drive), a->steps));
      }
    } else if (verdict && verdict->verdict == Verdict::kNotRigidlyFoldable) {
      model = verdict->model;
      note = "not rigidly foldable" + std::string(a->ignore ? " in any M-V assignment" : " with its M-V assignment") +
             ": " + verdict->reason + (verdict->obstruction ? " (" + verdict->obstruction->message + ")" : "") +
             "; nothing to trace" + (a->ignore ? "" : " (try --ignore-assignment)");
    } else {
      model = "general loop-closure solver";
      if (verdict && verdict->verdict == Verdict::kUndecided) note = "multiplier model undecided: " + verdict->reason;
      if (branch_id || all) {
        // Every branch through the flat state and the bifurcations (branch_explorer.hpp),
        // each traced to its end; --to / --steps / --drive do not apply.
        const BranchExploration x = explore_branches(p, t);
        if (!x.applicable) throw InputError("--branch", "branch exploration does not apply: " + x.why_not);
        model = "general loop-closure solver, branch exploration";
        note = std::to_string(x.branches.size()) + " branches through " + std::to_string(x.points.size()) +
               " points (flat, bifurcations, fold limits); each traced to its end";
        if (branch_id && *branch_id >= static_cast<int>(x.branches.size()))
          throw InputError("--branch", "branch " + std::to_string(*branch_id) + " does not exist (" +
                                           std::to_string(x.branches.size()) + " branches: 0.." +
                                           std::to_string(x.branches.size() - 1) + ")");
        for (const BranchTrace& bt : x.branches) {
          if (branch_id && bt.id != *branch_id) continue;
          Branch b;
          b.id = bt.id;
          b.drive = bt.driving_edge;
          b.to = b.reached = bt.driving_end;
          b.dof = bt.dof_at_departure;
          b.traced = bt.path.size() > 1 && bt.dof_at_departure == 1;
          const std::string from = x.points[bt.from_point].kind + " point " + std::to_string(bt.from_point);
          const std::string to = bt.to_point >= 0 ? x.points[bt.to_point].kind + " point " + std::to_string(bt.to_point) : "open end";
          b.stopped_by = bt.stopped_by + " (from " + from + " to " + to + ")";
          if (!b.traced) b.message = "not traced: " + bt.stopped_by + ", DOF " + std::to_string(bt.dof_at_departure) + " at departure";
          // The flat state is the key frame; a branch from another point starts with it.
          for (std::size_t k = bt.from_point == 0 ? 1 : 0; k < bt.path.size(); ++k) {
            Step st;
            st.rho = bt.path[k];
            st.drive = bt.path[k][bt.driving_edge];
            b.steps.push_back(std::move(st));
          }
          branches.push_back(std::move(b));
        }
      } else {
      int drive = -1;
      if (a->drive) {
        drive = *a->drive;
      } else {
        // Default: the first foldable crease at an interior vertex.
        for (int v : t.interior_vertices) {
          for (int e : t.stars[v].fans[0].edges)
            if (t.edge_is_hinge[e] && is_foldable_crease(p.assignments[e]) && (drive < 0 || e < drive)) drive = e;
        }
        if (drive < 0)
          for (int e = 0; e < p.num_edges() && drive < 0; ++e)
            if (t.edge_is_hinge[e] && is_foldable_crease(p.assignments[e])) drive = e;
        if (drive < 0) throw InputError(a->pattern, "the pattern has no foldable crease to drive");
      }
      branches.push_back(trace_general(p, t, ref, drive, target(drive), a->steps, a->ignore));
      }
    }
    for (Branch& b : branches) finish_steps(b, p, t, ref);

    // Render every output before writing any.
    const bool several = branches.size() > 1;
    std::vector<std::pair<std::string, std::string>> files;
    for (const Branch& b : branches) {
      if (!b.traced) continue;
      if (!a->out.empty()) files.emplace_back(branch_path(a->out, b.id, several), frames_text(b, p));
      if (!a->csv.empty()) files.emplace_back(branch_path(a->csv, b.id, several), csv_text(b, p.num_edges()));
    }
    for (const auto& [path, text] : files) write_text_file_atomically(path, text);

    j["model"] = model;
    j["note"] = note;
    bool traced = !branches.empty();
    for (const Branch& b : branches) traced = traced && b.traced;
    j["traced"] = traced;
    Json bj = Json::array();
    double max_res = 0, max_mis = 0;
    for (const Branch& b : branches) {
      bj.push_back(branch_json(b, p));
      max_res = std::max(max_res, b.max_residual);
      max_mis = std::max(max_mis, b.max_mismatch);
    }
    j["max_residual"] = max_res;
    j["max_mismatch"] = max_mis;
    if (branches.size() == 1)
      for (const char* key : {"branch", "drive_edge", "to_deg", "reached_deg", "steps", "stopped_by", "events", "message"})
        j[key] = bj[0][key];
    j["branches"] = bj;
    Json outs = Json::array();
    for (const auto& f : files) outs.push_back(f.first);
    j["outputs"] = outs;
    if (a->json) {
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::cout << a->pattern << ": model " << model << "\n";
    if (!note.empty()) std::cout << "  " << note << "\n";
    for (const Branch& b : branches) {
      std::cout << "  branch " << b.id << ": drive crease " << b.drive << " to " << deg_text(b.to) << " deg";
      if (!b.traced) {
        std::cout << ": not traced\n    " << b.message << "\n";
        continue;
      }
      std::cout << ", " << b.steps.size() << " steps to " << deg_text(b.reached) << " deg (" << b.stopped_by << ")\n";
      std::cout << "    max closure residual " << b.max_residual << " rad, max face-placement mismatch " << b.max_mismatch
                << "\n";
      for (const auto& e : b.events)
        std::cout << "    step " << e.step << ": " << e.kind << " at crease " << e.edge << " (drive " << deg_text(e.drive)
                  << " deg, crease " << deg_text(e.angle) << " deg)\n";
      if (!b.message.empty()) std::cout << "    " << b.message << "\n";
    }
    for (const auto& f : files) std::cout << "  wrote " << f.first << "\n";
  });
}

}  // namespace rigidfold::cli
