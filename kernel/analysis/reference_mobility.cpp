#include "kernel/analysis/reference_mobility.hpp"

#include <algorithm>
#include <chrono>
#include <numbers>
#include <cmath>

#include "kernel/geometry/facet_interference.hpp"
#include "kernel/analysis/path_watch.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/fold_limit_end.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace {

// Checks one accepted point of a branch (PathWatch, path_watch.hpp); returns true when the
// branch must stop there.
class BranchWatch {
 public:
  BranchWatch(const CreasePattern& p, const Topology& t, const ClosureSystem& sys, const Eigen::VectorXd& reference,
              const ReferenceMobilityOptions& o, TracedBranch& b)
      : p_(p), t_(t), sys_(sys), reference_(reference), o_(o), b_(b),
        watch_(p, b.driving_edge, watch_options(o), movable(p, sys)), previous_x_(sys.unknowns_from_edges(reference)) {
    // The given state seeds the signs; it may itself fold a crease against its letter.
    PathWatch::mark_letters(watch_.observe(reference), b);
  }

  Eigen::VectorXd angles(const Eigen::VectorXd& x) const {
    Eigen::VectorXd rho = sys_.edges_from_unknowns(x);
    for (int e = 0; e < p_.num_edges(); ++e)
      if (sys_.unknown_of_edge(e) < 0) rho[e] = reference_[e];  // F/J hinges keep their reference angle
    return rho;
  }

  bool stop_at(const Eigen::VectorXd& x) {
    const Eigen::VectorXd rho = angles(x);
    b_.path.push_back(rho);
    b_.max_fold = std::max(b_.max_fold, rho.cwiseAbs().maxCoeff());
    const PathWatch::Segment seg = watch_.observe(rho);
    // A point past a fold limit is not physical: the branch ends at the limit itself, solved
    // with the first crease to cross it held at +-pi (the state where the layers close).
    if (seg.fold_limit_crease >= 0) {
      const auto end = solve_fold_limit_end(sys_, previous_x_, x, seg.fold_limit_crease, seg.fold_limit_fraction,
                                            o_.tolerances.residual, kUnboundedDistance);
      if (end) {
        b_.max_residual = std::max(b_.max_residual, end->residual);
        b_.path.back() = angles(end->x);
      } else {
        b_.path.back() = angles(previous_x_);  // not solved: the previous point ends the branch
        b_.stop_message = "end at 180 deg not solved; the previous point ends the branch";
      }
      b_.max_fold = std::max(b_.max_fold, b_.path.back().cwiseAbs().maxCoeff());
      return finish(StopReason::kFoldLimit, seg.fold_limit_crease);
    }
    for (const SignSwitch& s : seg.switches) {
      b_.sign_switches.push_back(s);
      if (s.against_assignment && b_.signs_match_assignment) {
        b_.signs_match_assignment = false;
        b_.first_wrong_crease = s.crease;
      }
      if (s.against_assignment && o_.use_assignment) return finish(StopReason::kSignSwitch, s.crease);
    }
    previous_x_ = x;
    const bool letters_ok = !o_.use_assignment || b_.signs_match_assignment;
    const FoldedGeometry g = place_faces(p_, t_, rho, reference_);
    const FacetInterference fi = find_facet_interference(p_, g.vertices);
    if (!fi.face_pairs.empty()) {
      b_.global_interference_faces = fi.face_pairs.front();
      b_.global_interference_index = static_cast<int>(b_.path.size()) - 1;
      b_.global_interference_driving = rho[b_.driving_edge];
      return finish(StopReason::kGlobalInterference, -1);
    }
    if (letters_ok) b_.valid_points = static_cast<int>(b_.path.size());
    if (b_.path.size() > 10 && (rho - reference_).cwiseAbs().maxCoeff() < 0.5 * o_.max_step)
      return finish(StopReason::kClosedLoop, -1);
    return false;
  }

 private:
  // The end solve may move far from the interpolated start (a coarse step near the limit).
  static constexpr double kUnboundedDistance = 1e300;

  static PathWatchOptions watch_options(const ReferenceMobilityOptions& o) {
    PathWatchOptions w;
    w.tolerances = o.tolerances;
    return w;
  }
  static std::vector<bool> movable(const CreasePattern& p, const ClosureSystem& sys) {
    std::vector<bool> m(p.num_edges());
    for (int e = 0; e < p.num_edges(); ++e) m[e] = sys.unknown_of_edge(e) >= 0;
    return m;
  }

  bool finish(StopReason why, int crease) {
    b_.stopped_by = why;
    b_.stop_crease = crease;
    return true;
  }
  const CreasePattern& p_;
  const Topology& t_;
  const ClosureSystem& sys_;
  const Eigen::VectorXd& reference_;
  const ReferenceMobilityOptions& o_;
  TracedBranch& b_;
  PathWatch watch_;
  Eigen::VectorXd previous_x_;  // unknowns of the last accepted point
};

}  // namespace

ReferenceMobility reference_mobility(const CreasePattern& p, const Topology& t, const ReferenceMobilityOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  ReferenceMobility m;
  ClosureOptions co;
  co.close_holes = true;
  const ClosureSystem sys(p, t, co);
  m.holes = sys.num_holes();
  const Eigen::VectorXd reference = reference_fold_angles(p, t);
  const Eigen::VectorXd x0 = sys.unknowns_from_edges(reference);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(x0, r, J);
  m.reference_residual = r.size() ? r.lpNorm<Eigen::Infinity>() : 0.0;
  RankOptions ro;
  ro.relative_tolerance = o.tolerances.rank_cut;
  const RankResult rank = jacobian_rank(J, ro);
  m.dof = rank.dof;
  m.dof_method = rank.method;
  m.sigma_kept = rank.sigma_kept;
  m.sigma_dropped = rank.sigma_dropped;
  if (m.dof == 0) {
    m.verdict = Verdict::kNotRigidlyFoldable;
    m.reason = "the reference state is first-order rigid (closure Jacobian of full column rank), hence rigid";
  } else {
    // The crease that moves most along the first null direction drives (and names) both branches.
    const Eigen::VectorXd null_edges = sys.edges_from_unknowns(rank.null_space.col(0));
    int drive = 0;
    null_edges.cwiseAbs().maxCoeff(&drive);
    for (int sense : {1, -1}) {
      TracedBranch b;
      b.id = static_cast<int>(m.branches.size());
      b.sense = sense;
      b.driving_edge = drive;
      b.driving_begin = reference[drive];
      b.dof_at_departure = m.dof;
      b.valid_points = 0;
      BranchWatch watch(p, t, sys, reference, o, b);
      if (m.dof == 1) {
        ContinuationOptions copt;
        copt.max_step = o.max_step;
        copt.initial_step = std::min(copt.initial_step, o.max_step);
        copt.max_points = o.max_points;
        copt.tolerance = o.tolerances.residual;
        const Eigen::VectorXd direction = sense * rank.null_space.col(0);
        const ContinuationResult cr = continue_one_dof(
            sys, x0, direction, [&](const Eigen::VectorXd& x) { return watch.stop_at(x); }, copt);
        for (const ContinuationPoint& pt : cr.points) b.max_residual = std::max(b.max_residual, pt.residual);
        b.linear_solver = cr.linear_solver;
        b.factorizations = cr.stats.factorizations;
        if (b.stopped_by == StopReason::kNone) {
          b.stopped_by = cr.stopped ? StopReason::kMaxPoints : StopReason::kContinuationFailed;
          b.stop_message = cr.reason;
        }
      } else {
        NewtonOptions no;
        no.tolerance = o.tolerances.residual;
        no.held_unknowns = {sys.unknown_of_edge(drive)};
        Eigen::VectorXd x = x0;
        double h = o.driven_step;
        for (int k = 0; k < o.max_points; ++k) {
          Eigen::VectorXd trial = x;
          trial[no.held_unknowns[0]] += sense * h;
          const NewtonResult nr = newton_project(sys, trial, no);
          if (!nr.converged) {
            h *= 0.5;
            if (h < 1e-6) {
              b.stopped_by = StopReason::kCorrectorFailed;
              break;
            }
            continue;
          }
          x = nr.x;
          b.max_residual = std::max(b.max_residual, nr.residual_history.back());
          if (watch.stop_at(x)) break;
        }
        if (b.stopped_by == StopReason::kNone) b.stopped_by = StopReason::kMaxPoints;
      }
      if (!b.path.empty()) b.driving_end = b.path.back()[drive];
      m.max_residual = std::max(m.max_residual, b.max_residual);
      m.branches.push_back(std::move(b));
    }
    bool moved = false;
    for (const TracedBranch& b : m.branches)
      for (int k = 0; k < b.valid_points; ++k)
        if (std::abs(b.path[k][drive] - reference[drive]) >= o.min_motion) moved = true;
    if (moved) {
      m.verdict = Verdict::kRigidlyFoldable;
      m.reason = "DOF " + std::to_string(m.dof) + " at the reference state; a traced branch moves crease " +
                 std::to_string(drive) + " by at least " + std::to_string(o.min_motion) + " rad" +
                 (o.use_assignment ? " with every letter kept" : "");
    } else {
      m.verdict = Verdict::kUndecided;
      m.reason = "DOF " + std::to_string(m.dof) +
                 " at the reference state (first-order), but no traced branch moved far enough with every letter kept";
    }
  }
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

}  // namespace rigidfold
