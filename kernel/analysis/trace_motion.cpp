#include "kernel/analysis/trace_motion.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>

#include "kernel/analysis/path_watch.hpp"
#include "kernel/pattern/coordinate_precision.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/closure/vertex_residuals.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/fold_limit_end.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace {

double max_abs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

// The direction a crease folds by default: its letter's, valley for a crease without one.
double default_direction(Assignment a) { return assigned_fold_sign(a) != 0 ? assigned_fold_sign(a) : 1.0; }

// Residual, placement and events of every step, in order.
void finish_steps(MotionBranch& b, const CreasePattern& p, const Topology& t, const Eigen::VectorXd& ref,
                  const Tolerances& tol) {
  PathWatchOptions wo;
  wo.tolerances = tol;
  wo.letters_from_start = true;
  PathWatch watch(p, b.drive, wo);
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    MotionStep& s = b.steps[k];
    s.residual = max_vertex_closure_residual(t, s.rho);
    s.folded = place_faces(p, t, s.rho, ref);
    b.max_residual = std::max(b.max_residual, s.residual);
    b.max_mismatch = std::max(b.max_mismatch, s.folded.max_mismatch);
    const int step = static_cast<int>(k + 1);
    const PathWatch::Segment seg = watch.observe(s.rho);
    for (int e : seg.reached_180) s.events.push_back({step, MotionEvent::Kind::kAt180, e, s.drive, s.rho[e]});
    for (const SignSwitch& sw : seg.switches) {
      const auto kind = has_fold_sign(p.assignments[sw.crease]) ? MotionEvent::Kind::kMvSwitch
                                                                 : MotionEvent::Kind::kSignChange;
      s.events.push_back({step, kind, sw.crease, s.drive, s.rho[sw.crease]});
    }
    b.events.insert(b.events.end(), s.events.begin(), s.events.end());
  }
}

// ---- multiplier model -------------------------------------------------------------------

MotionBranch trace_family(const FoldFamily& f, int c, int drive, double to, int steps) {
  MotionBranch b;
  b.id = c;
  b.drive = drive;
  b.to = b.reached = to;
  b.traced = true;
  b.stop = std::fabs(to) >= kPi ? StopReason::kFoldLimit : StopReason::kTargetReached;
  b.stopped_by = std::fabs(to) >= kPi ? "driving crease reaches 180 deg (fully folded; local interference limit)"
                                      : "target driving angle reached";
  b.tan_half_ratio.assign(f.multiplier.size(), 0.0);
  for (std::size_t e = 0; e < f.multiplier.size(); ++e)
    if (f.component[e] == c) b.tan_half_ratio[e] = f.multiplier[e] / f.multiplier[drive];
  for (int k = 1; k <= steps; ++k) {
    const double d = to * k / steps;
    const double t = std::fabs(d) >= kPi ? std::copysign(std::numeric_limits<double>::infinity(), d / f.multiplier[drive])
                                         : f.parameter_for(drive, d);
    MotionStep s;
    s.drive = d;
    s.rho = f.component_angles(c, t);
    s.rho[drive] = d;  // exact driving value (the family gives it to rounding)
    b.steps.push_back(std::move(s));
  }
  return b;
}

std::vector<MotionBranch> trace_families(const CreasePattern& p, const FoldFamily& f, const TraceRequest& rq) {
  if (f.num_components == 0) throw std::logic_error("foldable verdict with an empty family");
  std::vector<int> ids;
  if (rq.all_branches) {
    for (int c = 0; c < f.num_components; ++c) ids.push_back(c);
    if (rq.drive && f.num_components > 1)
      throw InputError("drive", "with --branch all and " + std::to_string(f.num_components) +
                                    " branches, give --branch ID instead (each branch has its own creases)");
  } else if (rq.branch) {
    if (*rq.branch >= f.num_components)
      throw InputError("branch", "branch " + std::to_string(*rq.branch) + " does not exist (" +
                                     std::to_string(f.num_components) + " branches: 0.." +
                                     std::to_string(f.num_components - 1) + ")");
    ids.push_back(*rq.branch);
  } else {
    ids.push_back(rq.drive && f.component[*rq.drive] >= 0 ? f.component[*rq.drive] : 0);
  }
  std::vector<MotionBranch> out;
  for (int c : ids) {
    int drive = -1;
    if (rq.drive) {
      drive = *rq.drive;
      if (f.component[drive] < 0 || f.multiplier[drive] == 0.0)
        throw InputError("drive", "crease " + std::to_string(drive) + " stays flat in the fold family");
      if (f.component[drive] != c)
        throw InputError("drive", "crease " + std::to_string(drive) + " belongs to branch " +
                                      std::to_string(f.component[drive]) + ", not " + std::to_string(c));
    } else {
      drive = f.fastest_crease(c);
    }
    const double to = rq.to ? *rq.to : default_direction(p.assignments[drive]) * to_radians(170.0);
    out.push_back(trace_family(f, c, drive, to, rq.steps));
  }
  return out;
}

// ---- general solver ---------------------------------------------------------------------

// The general tracer's state for one driving crease: the closure system, the projection
// with the drive held, and the continuation's usable stretch (unknowns xs at driving values
// ds, measured along dir).
class GeneralTracer {
 public:
  GeneralTracer(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& ref, const TraceRequest& rq,
                int drive, double to)
      : p_(p), t_(t), ref_(ref), rq_(rq), sys_(p, t), kd_(sys_.unknown_of_edge(drive)), dir_(to > 0 ? 1.0 : -1.0) {
    b_.id = 0;
    b_.drive = drive;
    b_.to = to;
    nopt_.held_unknowns = {kd_};
    nopt_.max_iterations = 60;
    nopt_.tolerance = rq.tolerances.residual;
  }

  MotionBranch run() {
    report_progress(rq_.progress, [&] {
      return "trace: first folded point (" + std::to_string(sys_.num_unknowns()) + " unknowns)";
    });
    const std::optional<Eigen::VectorXd> start = find_start();
    if (!start) return b_;
    report_progress(rq_.progress, [] { return std::string("trace: DOF at the first point (rank of the Jacobian)"); });
    if (!dof_is_one(*start)) return b_;
    if (!continue_to_target(*start)) return b_;
    sample_steps();
    return b_;
  }

 private:
  NewtonResult project(Eigen::VectorXd x, double d) const {
    x[kd_] = d;
    return newton_project(sys_, x, nopt_);
  }

  // A small fold of the driving crease, the rest projected. The initial guess folds every
  // M/V crease a little in its letter's direction (mirrored if the drive goes against its
  // own letter), so that the projection lands on the branch the assignment selects: the
  // flat state is a bifurcation point and a plain minimum-norm step from it picks an
  // arbitrary branch. With the letters ignored: plain projection.
  std::optional<Eigen::VectorXd> find_start() {
    const Eigen::VectorXd x_ref = sys_.unknowns_from_edges(ref_);
    const double delta = dir_ * std::min(std::fabs(b_.to) / rq_.steps, to_radians(5.0));
    Eigen::VectorXd guess = x_ref;
    if (rq_.use_assignment) {
      const double mirror = dir_ * default_direction(p_.assignments[b_.drive]);
      for (int k = 0; k < sys_.num_unknowns(); ++k)
        guess[k] += mirror * assigned_fold_sign(p_.assignments[sys_.edge_of_unknown(k)]) * std::fabs(delta);
    }
    const NewtonResult start = project(guess, x_ref[kd_] + delta);
    if (!start.converged) {
      const double best = *std::min_element(start.residual_history.begin(), start.residual_history.end());
      b_.message = "general solver: no folded state found near the reference with crease " + std::to_string(b_.drive) +
                   " held at " + degrees_text(x_ref[kd_] + delta) + " deg (smallest residual " + round_trip_text(best) + " rad after " +
                   std::to_string(start.iterations) + " Newton steps); the pattern may not fold from this state (0 DOF)";
      return std::nullopt;
    }
    xs_ = {x_ref};
    ds_ = {dir_ * x_ref[kd_]};
    return start.x;
  }

  bool dof_is_one(const Eigen::VectorXd& x) {
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys_.evaluate(x, r, J);
    RankOptions ro;
    ro.relative_tolerance = rq_.tolerances.rank_cut;
    ro.compute_null_space = false;
    b_.dof = jacobian_rank(J, ro).dof;
    if (b_.dof == 1) return true;
    b_.message = "general solver: DOF at the start (crease " + std::to_string(b_.drive) + " at " + degrees_text(x[kd_]) +
                 " deg) is " + std::to_string(b_.dof) + ", not 1; 1-DOF continuation does not apply, nothing traced";
    return false;
  }

  void clamp_at(double limit, StopReason why, std::string text) {
    if (limit >= limit_) return;
    limit_ = limit;
    b_.stop = why;
    b_.stopped_by = std::move(text);
  }

  // Continuation to the target, or until a crease passes the fold limit (its end then
  // solved at +-pi). Keeps the stretch where the drive advances.
  bool continue_to_target(const Eigen::VectorXd& start) {
    const double fold_limit = rq_.tolerances.fold_limit();
    Eigen::VectorXd direction = Eigen::VectorXd::Zero(sys_.num_unknowns());
    direction[kd_] = dir_;
    int points = 0;
    auto stop = [&](const Eigen::VectorXd& x) {
      ++points;
      report_progress(rq_.progress, [&] {
        return "trace: continuation, crease " + std::to_string(b_.drive) + " at " + progress_degrees(x[kd_]) + " of " +
               progress_degrees(b_.to) + " deg (" + std::to_string(points) + " points)";
      });
      return dir_ * x[kd_] >= std::fabs(b_.to) || max_abs(sys_.edges_from_unknowns(x)) >= fold_limit;
    };
    ContinuationOptions copt;
    // Steps of at most 0.2 rad in any crease, whatever the pattern's size (a fixed arclength
    // took ~3,700 points on a 100 x 100 Miura), landing exactly on the output steps' driving
    // values so that they need no projection of their own.
    copt.max_angle_step = 0.2;
    copt.initial_step = std::numeric_limits<double>::infinity();  // the first step at the cap
    copt.max_points = 20000;
    copt.tolerance = rq_.tolerances.residual;
    copt.curved_predictor = true;
    copt.landing_unknown = kd_;
    // Not at the fold limit itself: a crease there is the fold-limit end's job (it holds every
    // crease that reaches +-pi there, so that none passes it by a rounding error).
    for (int k = 1; k <= rq_.steps; ++k)
      if (std::fabs(b_.to * k / rq_.steps) < fold_limit) copt.landing_values.push_back(b_.to * k / rq_.steps);
    const ContinuationResult path = continue_one_dof(sys_, start, direction, stop, copt);
    b_.linear_solver = path.linear_solver;
    b_.continuation = path.stats;
    b_.continuation_points = path.points.size();
    if (path.points.empty()) {
      b_.message = "general solver: continuation failed at the start (" + path.reason + ")";
      return false;
    }
    limit_ = std::fabs(b_.to);
    b_.stop = StopReason::kTargetReached;
    b_.stopped_by = "target driving angle reached";
    PathWatchOptions wo;
    wo.tolerances = rq_.tolerances;
    PathWatch watch(p_, b_.drive, wo);
    watch.observe(ref_);
    bool ended = false;
    for (const ContinuationPoint& pt : path.points) {
      const double d = dir_ * pt.x[kd_];
      const PathWatch::Segment seg = watch.observe(sys_.edges_from_unknowns(pt.x));
      if (seg.fold_limit_crease >= 0) {
        end_at_fold_limit(pt.x, seg);
        ended = true;
        break;
      }
      if (d <= ds_.back()) {
        clamp_at(ds_.back(), StopReason::kTurningPoint,
                 "the driving crease turns back at " + degrees_text(dir_ * ds_.back()) +
                     " deg (a fold point of the drive; choose another --drive); clamped");
        ended = true;
        break;
      }
      xs_.push_back(pt.x);
      ds_.push_back(d);
      if (pt.landing >= 0) landed_[pt.landing + 1] = pt.x;
    }
    if (!ended && ds_.back() < limit_)
      clamp_at(ds_.back(), StopReason::kContinuationFailed,
               "continuation stopped (" + path.reason + ") at driving angle " + degrees_text(dir_ * ds_.back()) +
                   " deg; clamped");
    b_.reached = dir_ * limit_;
    return true;
  }

  // A crease passed the fold limit on the segment ending at x: the end where it is at
  // +-pi, solved once (solve_fold_limit_end); if that fails, the previous point ends it.
  void end_at_fold_limit(const Eigen::VectorXd& x, const PathWatch::Segment& seg) {
    const auto end = solve_fold_limit_end(sys_, xs_.back(), x, seg.fold_limit_crease, seg.fold_limit_fraction,
                                          rq_.tolerances.residual);
    if (end && dir_ * end->x[kd_] > ds_.back()) {
      const double d_end = dir_ * end->x[kd_];
      // A target at 180 deg itself: the solved end is the last step too (its creases held at
      // +-pi), even if the drive ends there a rounding error past the target; limit_ stays.
      const bool at_target = d_end >= limit_ && d_end - limit_ <= rq_.tolerances.at_fold_limit;
      if (d_end < limit_ || at_target) {
        std::string text = "a crease reaches 180 deg at driving angle " + degrees_text(dir_ * d_end) +
                           " deg (local interference limit)" + (std::fabs(b_.to) - d_end > 1e-9 ? "; clamped" : "");
        if (at_target) {
          b_.stop = StopReason::kFoldLimit;
          b_.stopped_by = std::move(text);
        } else {
          clamp_at(d_end, StopReason::kFoldLimit, std::move(text));
        }
        xs_.push_back(end->x);
        ds_.push_back(d_end);
        x_end_ = end->x;
      }
      return;
    }
    clamp_at(ds_.back(), StopReason::kFoldLimit,
             "crease " + std::to_string(seg.fold_limit_crease) + " passes the fold limit after driving angle " +
                 degrees_text(dir_ * ds_.back()) +
                 " deg, and the point where it is at 180 deg was not solved (a singular end, e.g. the fully folded "
                 "state); clamped at the last point before it");
  }

  // The steps: equally spaced driving values up to the limit, each projected from the
  // stretch's interpolation with the drive held, then polished.
  void sample_steps() {
    int failures = 0;
    double worst_fail = 0;
    for (int k = 1; k <= rq_.steps; ++k) {
      report_progress(rq_.progress, [&] {
        return "trace: output step " + std::to_string(k) + " of " + std::to_string(rq_.steps);
      });
      const double d = limit_ * k / rq_.steps;
      MotionStep s;
      s.drive = dir_ * d;
      if (k == rq_.steps && x_end_) {
        s.rho = sys_.edges_from_unknowns(*x_end_);
        b_.steps.push_back(std::move(s));
        continue;
      }
      // A point the continuation landed on (its drive is exactly this step's, its residual
      // within the tolerance): used as it is unless its per-vertex residual is above the
      // tolerance, when the projection below polishes it.
      if (limit_ == std::fabs(b_.to)) {
        const auto hit = landed_.find(k);
        if (hit != landed_.end()) {
          const Eigen::VectorXd rho = sys_.edges_from_unknowns(hit->second);
          if (max_vertex_closure_residual(t_, rho) <= nopt_.tolerance) {
            s.rho = rho;
            b_.steps.push_back(std::move(s));
            continue;
          }
        }
      }
      std::size_t j = 1;
      while (j + 1 < ds_.size() && ds_[j] < d) ++j;
      Eigen::VectorXd guess = xs_.back();
      if (ds_.size() >= 2) {
        const double f = std::clamp((d - ds_[j - 1]) / (ds_[j] - ds_[j - 1]), 0.0, 1.0);
        guess = xs_[j - 1] + f * (xs_[j] - xs_[j - 1]);
      }
      NewtonResult r = project(guess, dir_ * d);
      // Polish: one or two more steps take ||r||_inf from <= the tolerance to rounding
      // level, so the per-vertex residual norm reported is within the tolerance too.
      NewtonOptions polish = nopt_;
      polish.tolerance = 0.0;
      polish.max_iterations = 2;
      const NewtonResult q = newton_project(sys_, r.x, polish);
      if (q.residual_history.back() < r.residual_history.back()) {
        r.x = q.x;
        r.residual_history.push_back(q.residual_history.back());
        r.converged = r.converged || q.residual_history.back() <= nopt_.tolerance;
      }
      if (!r.converged) {
        ++failures;
        worst_fail = std::max(worst_fail, r.residual_history.back());
      }
      s.rho = sys_.edges_from_unknowns(r.x);
      b_.steps.push_back(std::move(s));
    }
    b_.traced = true;
    if (failures > 0)
      b_.message = std::to_string(failures) + " step(s) did not converge to " + round_trip_text(nopt_.tolerance) +
                   " (worst residual " + round_trip_text(worst_fail) + " rad); their residual is reported as reached";
  }

  const CreasePattern& p_;
  const Topology& t_;
  const Eigen::VectorXd& ref_;
  const TraceRequest& rq_;
  const ClosureSystem sys_;
  const int kd_;
  const double dir_;
  NewtonOptions nopt_;
  MotionBranch b_;
  std::vector<Eigen::VectorXd> xs_;  // the usable stretch: unknowns ...
  std::vector<double> ds_;           // ... and driving values along dir_
  double limit_ = 0.0;               // driving value (along dir_) the steps reach
  std::optional<Eigen::VectorXd> x_end_;  // the solved end at 180 deg, when the trace ends there
  std::map<int, Eigen::VectorXd> landed_;  // output step k (1-based) -> the continuation point landed on it
};

// Default driving crease of the general tracer: the first foldable crease at an interior
// vertex, else the first foldable crease.
int default_general_drive(const CreasePattern& p, const Topology& t) {
  int drive = -1;
  for (int v : t.interior_vertices)
    for (int e : t.stars[v].fans[0].edges)
      if (t.edge_is_hinge[e] && is_foldable_crease(p.assignments[e]) && (drive < 0 || e < drive)) drive = e;
  for (int e = 0; e < p.num_edges() && drive < 0; ++e)
    if (t.edge_is_hinge[e] && is_foldable_crease(p.assignments[e])) drive = e;
  return drive;
}

MotionBranch trace_general(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& ref,
                           const TraceRequest& rq) {
  const int drive = rq.drive ? *rq.drive : default_general_drive(p, t);
  if (drive < 0) throw InputError("", "the pattern has no foldable crease to drive");
  const double to = rq.to ? *rq.to : default_direction(p.assignments[drive]) * to_radians(170.0);
  try {
    return GeneralTracer(p, t, ref, rq, drive, to).run();
  } catch (const std::runtime_error& e) {  // ClosureSystem: a sheet this solver cannot express
    MotionBranch b;
    b.drive = drive;
    b.to = to;
    b.message = std::string("general solver unavailable: ") + e.what();
    return b;
  }
}

// A branch traced elsewhere (explorer, given state) as steps at its points. skip_first: the
// flat state is the key frame, not a step.
MotionBranch steps_of(const TracedBranch& tb, bool skip_first) {
  MotionBranch b;
  b.id = tb.id;
  b.drive = tb.driving_edge;
  b.to = b.reached = tb.driving_end;
  b.dof = tb.dof_at_departure;
  b.stop = tb.stopped_by;
  for (std::size_t k = skip_first ? 1 : 0; k < tb.path.size(); ++k) {
    MotionStep st;
    st.rho = tb.path[k];
    st.drive = tb.path[k][tb.driving_edge];
    b.steps.push_back(std::move(st));
  }
  return b;
}

void check_branch_id(const TraceRequest& rq, std::size_t count) {
  if (rq.branch && *rq.branch >= static_cast<int>(count))
    throw InputError("branch", "branch " + std::to_string(*rq.branch) + " does not exist (" + std::to_string(count) +
                                   " branches" +
                                   (count > 0 ? ": 0.." + std::to_string(count - 1) : std::string()) + ")");
}

bool wanted(const TraceRequest& rq, int id) { return rq.all_branches || (rq.branch ? id == *rq.branch : id == 0); }

// Every branch through the flat state and the bifurcations, each to its end.
void trace_explored(const CreasePattern& p, const Topology& t, const TraceRequest& rq, MotionTrace& out) {
  BranchExplorerOptions xo;
  xo.tolerances = rq.tolerances;
  xo.progress = rq.progress;
  const BranchExploration x = explore_branches(p, t, xo);
  if (!x.applicable) throw InputError("branch", "branch exploration does not apply: " + x.why_not);
  out.model_name = "general loop-closure solver, branch exploration";
  out.note = std::to_string(x.branches.size()) + " branches through " + std::to_string(x.points.size()) +
             " points (flat, bifurcations, fold limits); each traced to its end";
  check_branch_id(rq, x.branches.size());
  for (const TracedBranch& tb : x.branches) {
    if (!wanted(rq, tb.id)) continue;
    MotionBranch b = steps_of(tb, tb.from_point == 0);
    b.traced = tb.path.size() > 1 && tb.dof_at_departure == 1;
    const std::string from = std::string(to_string(x.points[tb.from_point].kind)) + " point " + std::to_string(tb.from_point);
    const std::string to = tb.to_point >= 0 ? std::string(to_string(x.points[tb.to_point].kind)) + " point " +
                                                  std::to_string(tb.to_point)
                                            : "open end";
    b.stopped_by = tb.stop_text() + " (from " + from + " to " + to + ")";
    if (!b.traced) b.message = "not traced: " + tb.stop_text() + ", DOF " + std::to_string(tb.dof_at_departure) + " at departure";
    out.branches.push_back(std::move(b));
  }
}

// A sheet with holes: both ways from the given state (check_foldability's given-state model).
void trace_given_state(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& ref, const TraceRequest& rq,
                       const ModelChoice& choice, MotionTrace& out) {
  FoldabilityOptions fo;
  fo.use_assignment = rq.use_assignment;
  fo.tolerances = rq.tolerances;
  fo.coordinate_tolerance = rq.coordinate_tolerance;
  fo.progress = rq.progress;
  const FoldabilityReport r = check_foldability(p, t, fo);
  out.model_name = r.model_name;
  out.note = std::to_string(choice.holes) + " hole(s); DOF " + std::to_string(r.dof) + " at the given state; " + r.reason;
  check_branch_id(rq, r.branches.size());
  for (const TracedBranch& tb : r.branches) {
    if (!wanted(rq, tb.id)) continue;
    MotionBranch b = steps_of(tb, false);
    b.traced = !tb.path.empty();
    b.stopped_by = tb.stop_text();
    b.max_residual = tb.max_residual;  // hole rows included (finish_steps adds the vertex rows)
    if (!b.traced) b.message = "not traced: " + tb.stop_text();
    MotionStep given;  // the given state is the first step
    given.rho = ref;
    given.drive = ref[tb.driving_edge];
    b.steps.insert(b.steps.begin(), std::move(given));
    out.branches.push_back(std::move(b));
  }
}

}  // namespace

const char* to_string(MotionEvent::Kind k) {
  switch (k) {
    case MotionEvent::Kind::kAt180: return "interference";
    case MotionEvent::Kind::kMvSwitch: return "mv_switch";
    case MotionEvent::Kind::kSignChange: return "sign_change";
  }
  return "?";
}

MotionTrace trace_motion(const CreasePattern& p, const Topology& t, const TraceRequest& rq) {
  if (rq.steps < 1) throw InputError("steps", "must be at least 1");
  if (rq.to && (!std::isfinite(*rq.to) || std::fabs(*rq.to) > kPi))
    throw InputError("to", "fold angle must be finite and within [-180, 180] deg");
  if (rq.to && *rq.to == 0.0) throw InputError("to", "must not be 0 (the flat state is the key frame)");
  if (rq.drive) {
    const int e = *rq.drive;
    if (e < 0 || e >= p.num_edges())
      throw InputError("drive", "edge index " + std::to_string(e) + " out of range (" + std::to_string(p.num_edges()) +
                                    " edges)");
    if (!t.edge_is_hinge[e])
      throw InputError("drive", "edge " + std::to_string(e) + " is not a crease between two faces (assignment " +
                                    std::string(1, assignment_letter(p.assignments[e])) + "); it cannot fold");
    if (!is_foldable_crease(p.assignments[e]))
      throw InputError("drive", "edge " + std::to_string(e) + " is assigned " +
                                    std::string(1, assignment_letter(p.assignments[e])) + " (rigid); it cannot fold");
  }
  FoldabilityOptions fo;
  fo.use_assignment = rq.use_assignment;
  fo.force_general = rq.force_general;
  fo.tolerances = rq.tolerances;
  if (rq.coordinate_tolerance && !(*rq.coordinate_tolerance >= 0 && std::isfinite(*rq.coordinate_tolerance)))
    throw InputError("tolerance", "must be a finite number >= 0");
  fo.coordinate_tolerance = rq.coordinate_tolerance;
  report_progress(rq.progress, [] { return std::string("trace: choosing the model"); });
  const ModelChoice choice = choose_model(p, t, fo);
  const Eigen::VectorXd ref = reference_fold_angles(p, t);
  MotionTrace out;
  out.coordinate_precision = describe_input_precision(p, rq.coordinate_tolerance);
  out.model = choice.model;
  const std::optional<FoldabilityVerdict>& v = choice.multiplier;
  if (choice.model == FoldabilityModel::kGivenStateHoleClosure) {
    trace_given_state(p, t, ref, rq, choice, out);
  } else if (v && v->verdict == Verdict::kRigidlyFoldable && v->family) {
    out.model_name = v->model;
    if (choice.flat_witness) {
      out.model_name += " (on a flat-foldable witness within the input's precision)";
      out.note = "within the input's precision: " + choice.why;
    }
    out.branches = trace_families(p, *v->family, rq);
  } else if (v && v->verdict == Verdict::kNotRigidlyFoldable) {
    out.model_name = v->model;
    out.note = "not rigidly foldable" + std::string(rq.use_assignment ? " with its M-V assignment" : " in any M-V assignment") +
               ": " + v->reason + (v->obstruction ? " (" + v->obstruction->message + ")" : "") + "; nothing to trace" +
               (rq.use_assignment ? " (try --ignore-assignment)" : "");
    if (choice.flat_witness)
      out.note = "the flat-foldable witness within the input's precision (" + choice.why + ") is " + out.note;
  } else {
    out.model = FoldabilityModel::kGeneralLoopClosure;
    out.model_name = "general loop-closure solver";
    out.note = v ? "multiplier model undecided: " + v->reason
                 : (rq.force_general ? "general solver forced (--general)" : "multiplier model not applicable: " + choice.why);
    if (rq.branch || rq.all_branches) trace_explored(p, t, rq, out);
    else out.branches.push_back(trace_general(p, t, ref, rq));
  }
  report_progress(rq.progress, [] { return std::string("trace: placing the faces of every step"); });
  // On a flat-foldable witness within the file's rounding the steps are the witness's: its
  // closure residuals and faces (coordinates within the rounding of the file's).
  const bool on_witness = choice.flat_witness && choice.model == FoldabilityModel::kMultiplierPropagation;
  const CreasePattern& placed = on_witness ? choice.flat_witness->witness : p;
  const Topology& placed_topology = on_witness ? choice.flat_witness->witness_topology : t;
  for (MotionBranch& b : out.branches) finish_steps(b, placed, placed_topology, ref, rq.tolerances);
  return out;
}

}  // namespace rigidfold
