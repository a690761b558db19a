#include "kernel/analysis/branch_explorer.hpp"
#include "kernel/math/angle_units.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <chrono>
#include <cmath>
#include <deque>
#include <numbers>

#include "kernel/analysis/path_watch.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/facet_interference.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/solve/bifurcation.hpp"
#include "kernel/solve/bordered_determinant.hpp"
#include "kernel/solve/fold_limit_end.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace {


struct Departure {
  int point;
  Eigen::VectorXd direction;  // unit, unknown space
};

// Why continue_one_dof's callback stopped a branch.
enum class Halt { kNone, kBifurcation, kFoldLimit, kKnownPoint };

// The exploration's state: the points found so far (with their unknowns and the directions
// already used there) and the queue of departures. Steps 1-4 of the header.
class Explorer {
 public:
  Explorer(const CreasePattern& pattern, const Topology& topology, const BranchExplorerOptions& opt,
           const ClosureSystem& sys, BranchExploration& out)
      : pattern_(pattern), topology_(topology), opt_(opt), sys_(sys), out_(out),
        reference_(reference_fold_angles(pattern, topology)) {
    cone_ = opt.cone;
    cone_.rank_tolerance = opt.tolerances.cone_rank_cut;
  }

  void run() {
    BranchPoint flat;
    flat.kind = PointKind::kFlat;
    add_point(flat, Eigen::VectorXd::Zero(sys_.num_unknowns()), [](const Eigen::VectorXd&) { return true; });
    while (!queue_.empty() && static_cast<int>(out_.branches.size()) < opt_.max_branches && !out_.budget_exhausted) {
      const Departure dep = queue_.front();
      queue_.pop_front();
      if (is_used(dep.point, dep.direction)) continue;
      used_[dep.point].push_back(dep.direction);
      out_.branches.push_back(trace_branch(dep));
    }
  }

 private:
  int find_point(const Eigen::VectorXd& x) const {
    for (std::size_t i = 0; i < point_x_.size(); ++i)
      if ((point_x_[i] - x).lpNorm<Eigen::Infinity>() <= opt_.same_point) return static_cast<int>(i);
    return -1;
  }

  bool is_used(int p, const Eigen::VectorXd& d) const {
    for (const auto& u : used_[p])
      if (u.dot(d) > opt_.same_direction) return true;
    return false;
  }

  // Adds a point with its tangent cone; enqueues the departures allowed(d) accepts.
  template <class Allowed>
  int add_point(BranchPoint bp, const Eigen::VectorXd& x, Allowed&& allowed) {
    spend();
    const TangentCone cone = tangent_cone(sys_, topology_, x, cone_);
    bp.kernel_dimension = cone.kernel_dimension;
    bp.tangent_lines = static_cast<int>(cone.lines.size());
    bp.angles = sys_.edges_from_unknowns(x);
    bp.residual = sys_.residual(x).lpNorm<Eigen::Infinity>();
    out_.points.push_back(bp);
    point_x_.push_back(x);
    used_.emplace_back();
    const int id = static_cast<int>(out_.points.size()) - 1;
    for (const TangentLine& line : cone.lines)
      for (double side : {1.0, -1.0}) {
        const Eigen::VectorXd d = side * line.direction;
        if (allowed(d)) queue_.push_back({id, d});
      }
    return id;
  }

  // Appends the point x to the branch: path, residual, letters, sign switches (watch) and
  // global facet interference.
  PathWatch::Segment record(TracedBranch& br, PathWatch& watch, const Eigen::VectorXd& x) {
    const Eigen::VectorXd rho = sys_.edges_from_unknowns(x);
    const double res = sys_.residual(x).lpNorm<Eigen::Infinity>();
    const PathWatch::Segment seg = watch.observe(rho);
    br.sign_switches.insert(br.sign_switches.end(), seg.switches.begin(), seg.switches.end());
    PathWatch::mark_letters(seg, br);
    if (opt_.check_global_interference && br.global_interference_index < 0) {
      const FoldedGeometry g = place_faces(pattern_, topology_, rho, reference_);
      const FacetInterference fi = find_facet_interference(pattern_, g.vertices);
      if (!fi.face_pairs.empty()) {
        br.global_interference_index = static_cast<int>(br.path.size());
        br.global_interference_driving = br.driving_edge >= 0 ? rho[br.driving_edge] : 0.0;
        br.global_interference_faces = fi.face_pairs.front();
      }
    }
    br.path.push_back(rho);
    br.max_residual = std::max(br.max_residual, res);
    return seg;
  }

  // Steps 1-3 for one departure: leave the point, trace, and end the branch.
  TracedBranch trace_branch(const Departure& dep) {
    const Eigen::VectorXd xs = point_x_[dep.point];
    TracedBranch br;
    br.id = static_cast<int>(out_.branches.size());
    br.from_point = dep.point;
    Eigen::Index big;
    dep.direction.cwiseAbs().maxCoeff(&big);
    br.driving_edge = sys_.edge_of_unknown(static_cast<int>(big));
    const BranchDeparture leave = leave_singular_point(sys_, xs, dep.direction, opt_.departure_step);
    if (!leave.converged || leave.chord_alignment < 0.9) {
      br.stopped_by = StopReason::kDepartureFailed;
      return br;
    }
    PathWatchOptions wo;
    wo.tolerances = opt_.tolerances;
    wo.skip_first_segment = true;  // from a singular point, near-zero creases have no meaningful sign
    PathWatch watch(pattern_, br.driving_edge, wo);
    record(br, watch, xs);  // the path starts at the point itself
    BorderedDeterminantMonitor monitor;
    Eigen::VectorXd prev_x = xs, before_prev_x = xs, along = dep.direction;
    monitor.step(dense_jacobian(sys_, leave.x), along);
    Halt halt = Halt::kNone;
    double fold_fraction = 1.0;  // where on the last step the end solve starts
    auto accept = [&](const Eigen::VectorXd& x) {
      if ((x - prev_x).norm() > 0) along = (x - prev_x).normalized();
      const PathWatch::Segment seg = record(br, watch, x);
      report_progress(opt_.progress, [&] {
        return "branch explorer: branch " + std::to_string(br.id) + ", " + std::to_string(br.path.size()) +
               " points; " + std::to_string(point_x_.size()) + " branch points found, " +
               std::to_string(queue_.size()) + " departures waiting";
      });
      before_prev_x = prev_x;
      prev_x = x;
      if (spend()) return true;  // halt stays kNone: the branch ends with kMaxPoints
      if (br.path.size() > 2 && monitor.step(dense_jacobian(sys_, x), along).sign_changed) {
        halt = Halt::kBifurcation;
        return true;
      }
      if (seg.fold_limit_crease >= 0) {
        // The crease held at +-pi for the end is the one furthest past the limit, solved from
        // this point (fraction 1): near the fully folded state several creases pass the limit
        // on one step, and the first to cross (PathWatch's crease) can lead the end solve to
        // another branch (seed 001 Type 1M: the interference onset moved from 23.4 to 19.2 deg).
        Eigen::Index e;
        br.path.back().cwiseAbs().maxCoeff(&e);
        halt = Halt::kFoldLimit;
        br.stop_crease = static_cast<int>(e);
        fold_fraction = 1.0;
        return true;
      }
      if (br.path.size() > 3) {
        const int known = find_point(x);
        if (known >= 0 || ((x - xs).norm() < 0.5 * opt_.departure_step)) {
          halt = Halt::kKnownPoint;
          br.to_point = known >= 0 ? known : dep.point;
          return true;
        }
      }
      return static_cast<int>(br.path.size()) >= opt_.max_points_per_branch;
    };
    const ContinuationResult cr = continue_one_dof(sys_, leave.x, dep.direction, accept, opt_.continuation);
    br.linear_solver = cr.linear_solver;
    br.factorizations = cr.stats.factorizations;
    if (br.path.size() == 1) {
      // Not traced (e.g. more than 1 DOF just off the point): keep the departure point and its DOF.
      record(br, watch, leave.x);
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> J;
      sys_.evaluate(leave.x, r, J);
      RankOptions ro;
      ro.relative_tolerance = opt_.tolerances.cone_rank_cut;  // the cut the tangent cones use
      ro.compute_null_space = false;
      br.dof_at_departure = jacobian_rank(J, ro).dof;
    }
    switch (halt) {
      case Halt::kNone:
        if (cr.stopped) {
          br.stopped_by = StopReason::kMaxPoints;
          if (out_.budget_exhausted) br.stop_message = "the explorer's work budget ran out";
        } else {
          br.stopped_by = StopReason::kContinuationFailed;
          br.stop_message = cr.reason;
        }
        break;
      case Halt::kKnownPoint: br.stopped_by = StopReason::kKnownPoint; break;
      case Halt::kBifurcation: end_at_bifurcation(br, before_prev_x, prev_x); break;
      case Halt::kFoldLimit: end_at_fold_limit(br, before_prev_x, prev_x, fold_fraction); break;
    }
    if (br.dof_at_departure < 0) br.dof_at_departure = 1;
    for (const Eigen::VectorXd& rho : br.path) br.max_fold = std::max(br.max_fold, rho.cwiseAbs().maxCoeff());
    br.driving_begin = br.path.front()[br.driving_edge];
    br.driving_end = br.path.back()[br.driving_edge];
    return br;
  }

  // The sign change of the bordered determinant between a and b: locate the bifurcation,
  // add it as a point (or match a known one) and end the branch there.
  void end_at_bifurcation(TracedBranch& br, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    br.stopped_by = StopReason::kBifurcation;
    const LocatedSingularPoint loc = locate_singular_point(sys_, topology_, a, b, opt_.locate_tolerance);
    if (!loc.found) {
      br.stopped_by = StopReason::kBifurcationNotLocated;
      return;
    }
    int p = find_point(loc.x);
    const Eigen::VectorXd incoming = (a - loc.x).normalized();
    if (p < 0) {
      BranchPoint bp;
      bp.kind = PointKind::kBifurcation;
      bp.parameter_edge = br.driving_edge;
      bp.parameter = sys_.edges_from_unknowns(loc.x)[br.driving_edge];
      bp.location_error_bound = loc.error_bound;
      bp.sigma_second_smallest = loc.sigma_second_smallest;
      bp.sigma_max = loc.sigma_max;
      p = add_point(bp, loc.x, [](const Eigen::VectorXd&) { return true; });
    }
    used_[p].push_back(incoming);
    br.to_point = p;
    br.path.back() = sys_.edges_from_unknowns(loc.x);  // the branch's last point is the bifurcation itself
  }

  // A crease passed the fold limit at x (after x_before): solve the point where it is at
  // +-pi and add it as an "interference" or "fully folded" point.
  void end_at_fold_limit(TracedBranch& br, const Eigen::VectorXd& x_before, const Eigen::VectorXd& x,
                         double fraction) {
    br.stopped_by = StopReason::kFoldLimit;
    const auto end = solve_fold_limit_end(sys_, x_before, x, br.stop_crease, fraction, opt_.tolerances.residual);
    if (!end) {
      // Not solved: the point past the limit is no configuration of the sheet; the branch
      // ends at the last point before it.
      br.path.pop_back();
      if (br.global_interference_index >= static_cast<int>(br.path.size())) {
        br.global_interference_index = -1;  // found only at the dropped point
        br.global_interference_faces = {-1, -1};
      }
      br.stop_message = "the point where crease " + std::to_string(br.stop_crease) +
                        " reaches 180 deg was not solved; the branch ends at the last point before it";
      return;
    }
    const Eigen::VectorXd rho = sys_.edges_from_unknowns(end->x);
    bool all_flat_folded = true;
    for (int e = 0; e < rho.size(); ++e) {
      const double a = std::abs(rho[e]);
      if (std::min(a, std::abs(a - kPi)) > 1e-6) all_flat_folded = false;
    }
    int p = find_point(end->x);
    if (p < 0) {
      BranchPoint bp;
      bp.kind = all_flat_folded ? PointKind::kFullyFolded : PointKind::kInterference;
      bp.stop_crease = br.stop_crease;
      bp.parameter_edge = br.stop_crease;
      bp.parameter = rho[br.stop_crease];
      auto folds_back = [&](const Eigen::VectorXd& d) {
        if (!all_flat_folded) return false;
        const Eigen::VectorXd step = sys_.edges_from_unknowns(end->x + 1e-3 * d);
        return step.cwiseAbs().maxCoeff() <= kPi;
      };
      p = add_point(bp, end->x, folds_back);
    }
    used_[p].push_back((x - end->x).normalized());
    br.to_point = p;
    br.path.back() = rho;  // the branch ends at the solved end, not at the point past the limit
    br.max_residual = std::max(br.max_residual, end->residual);
  }

  const CreasePattern& pattern_;
  const Topology& topology_;
  const BranchExplorerOptions& opt_;
  // Counts one dense factorisation of J (BranchExplorerOptions::max_dense_work); true once the
  // budget is spent.
  bool spend() {
    const double n = sys_.num_unknowns();
    out_.dense_work += static_cast<double>(sys_.num_rows()) * n * n;
    if (out_.dense_work > opt_.max_dense_work) out_.budget_exhausted = true;
    return out_.budget_exhausted;
  }

  const ClosureSystem& sys_;
  BranchExploration& out_;
  const Eigen::VectorXd reference_;
  TangentConeOptions cone_;
  std::vector<Eigen::VectorXd> point_x_;            // unknowns of each point
  std::vector<std::vector<Eigen::VectorXd>> used_;  // used unit directions per point
  std::deque<Departure> queue_;
};

}  // namespace

BranchExploration explore_branches(const CreasePattern& pattern, const Topology& topology,
                                   const BranchExplorerOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  BranchExploration out;
  const ClosureSystem sys(pattern, topology);
  const int n = sys.num_unknowns();
  out.num_unknowns = n;
  if (n < 1 || n > opt.max_unknowns) {
    out.why_not = n < 1 ? "no foldable crease" : "more than " + std::to_string(opt.max_unknowns) + " free creases";
    return out;
  }
  out.applicable = true;
  Explorer(pattern, topology, opt, sys, out).run();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rigidfold
