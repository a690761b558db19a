#include "kernel/analysis/branch_explorer.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <chrono>
#include <cmath>
#include <deque>
#include <numbers>

#include "kernel/analysis/facet_interference.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/solve/bifurcation.hpp"
#include "kernel/solve/bordered_determinant.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace {

constexpr double kPi = std::numbers::pi;

struct Departure {
  int point;
  Eigen::VectorXd direction;  // unit, unknown space
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
  std::vector<int> sign(pattern.num_edges(), 0);
  for (int e = 0; e < pattern.num_edges(); ++e) sign[e] = assigned_fold_sign(pattern.assignments[e]);
  const Eigen::VectorXd reference = reference_fold_angles(pattern, topology);
  std::vector<Eigen::VectorXd> point_x;                  // unknowns of each point
  std::vector<std::vector<Eigen::VectorXd>> used;        // used unit directions per point
  std::deque<Departure> queue;

  auto find_point = [&](const Eigen::VectorXd& x) {
    for (std::size_t i = 0; i < point_x.size(); ++i)
      if ((point_x[i] - x).lpNorm<Eigen::Infinity>() <= opt.same_point) return static_cast<int>(i);
    return -1;
  };
  auto is_used = [&](int p, const Eigen::VectorXd& d) {
    for (const auto& u : used[p])
      if (u.dot(d) > opt.same_direction) return true;
    return false;
  };
  // Adds a point with its cone; enqueues departures (allowed(d) filters them).
  auto add_point = [&](BranchPoint bp, const Eigen::VectorXd& x, auto&& allowed) {
    const TangentCone cone = tangent_cone(sys, topology, x, opt.cone);
    bp.kernel_dimension = cone.kernel_dimension;
    bp.tangent_lines = static_cast<int>(cone.lines.size());
    bp.angles = sys.edges_from_unknowns(x);
    bp.residual = sys.residual(x).lpNorm<Eigen::Infinity>();
    out.points.push_back(bp);
    point_x.push_back(x);
    used.emplace_back();
    const int id = static_cast<int>(out.points.size()) - 1;
    for (const TangentLine& line : cone.lines)
      for (double side : {1.0, -1.0}) {
        const Eigen::VectorXd d = side * line.direction;
        if (allowed(d)) queue.push_back({id, d});
      }
    return id;
  };
  BranchPoint flat;
  flat.kind = "flat";
  add_point(flat, Eigen::VectorXd::Zero(n), [](const Eigen::VectorXd&) { return true; });

  while (!queue.empty() && static_cast<int>(out.branches.size()) < opt.max_branches) {
    const Departure dep = queue.front();
    queue.pop_front();
    if (is_used(dep.point, dep.direction)) continue;
    used[dep.point].push_back(dep.direction);
    const Eigen::VectorXd xs = point_x[dep.point];
    BranchTrace br;
    br.id = static_cast<int>(out.branches.size());
    br.from_point = dep.point;
    Eigen::Index big;
    dep.direction.cwiseAbs().maxCoeff(&big);
    br.driving_edge = sys.edge_of_unknown(static_cast<int>(big));
    const BranchDeparture leave = leave_singular_point(sys, xs, dep.direction, opt.departure_step);
    if (!leave.converged || leave.chord_alignment < 0.9) {
      br.stopped_by = "departure failed";
      out.branches.push_back(std::move(br));
      continue;
    }
    // Path: the point itself, then the traced points.
    auto record = [&](const Eigen::VectorXd& x) {
      const Eigen::VectorXd rho = sys.edges_from_unknowns(x);
      const double res = sys.residual(x).lpNorm<Eigen::Infinity>();
      if (!br.path.empty()) {
        const Eigen::VectorXd& prev = br.path.back();
        for (int e = 0; e < rho.size(); ++e) {
          const bool was = prev[e] > opt.zero_tolerance, was_neg = prev[e] < -opt.zero_tolerance;
          const bool now = rho[e] > opt.zero_tolerance, now_neg = rho[e] < -opt.zero_tolerance;
          if (br.path.size() > 1 && ((was && now_neg) || (was_neg && now))) {
            const double f = prev[e] / (prev[e] - rho[e]);
            SignSwitch s;
            s.crease = e;
            s.driving_value = prev[br.driving_edge] + f * (rho[br.driving_edge] - prev[br.driving_edge]);
            s.against_assignment = sign[e] != 0 && sign[e] * rho[e] < 0;
            br.sign_switches.push_back(s);
          }
        }
      }
      for (int e = 0; e < rho.size(); ++e)
        if (sign[e] != 0 && sign[e] * rho[e] < -opt.zero_tolerance && br.signs_match_assignment) {
          br.signs_match_assignment = false;
          br.first_wrong_crease = e;
        }
      if (opt.check_global_interference && br.global_interference_index < 0) {
        const FoldedGeometry g = place_faces(pattern, topology, rho, reference);
        const FacetInterference fi = find_facet_interference(pattern, g.vertices);
        if (!fi.face_pairs.empty()) {
          br.global_interference_index = static_cast<int>(br.path.size());
          br.global_interference_driving = br.driving_edge >= 0 ? rho[br.driving_edge] : 0.0;
          br.global_interference_faces = fi.face_pairs.front();
        }
      }
      br.path.push_back(rho);
      br.residuals.push_back(res);
      br.max_residual = std::max(br.max_residual, res);
      br.max_fold = std::max(br.max_fold, rho.cwiseAbs().maxCoeff());
    };
    record(xs);
    BorderedDeterminantMonitor monitor;
    Eigen::VectorXd prev_x = xs, along = dep.direction;
    monitor.step(dense_jacobian(sys, leave.x), along);
    int stop_kind = 0;  // 1 bifurcation, 2 fold limit, 3 known point
    Eigen::VectorXd bif_a, bif_b;
    auto accept = [&](const Eigen::VectorXd& x) {
      if ((x - prev_x).norm() > 0) along = (x - prev_x).normalized();
      record(x);
      const Eigen::VectorXd& rho = br.path.back();
      if (br.path.size() > 2 && monitor.step(dense_jacobian(sys, x), along).sign_changed) {
        stop_kind = 1;
        bif_a = prev_x;
        bif_b = x;
        prev_x = x;
        return true;
      }
      prev_x = x;
      Eigen::Index e;
      if (rho.cwiseAbs().maxCoeff(&e) >= opt.fold_limit) {
        stop_kind = 2;
        br.stop_crease = static_cast<int>(e);
        return true;
      }
      if (br.path.size() > 3) {
        const int known = find_point(x);
        if (known >= 0 || ((x - xs).norm() < 0.5 * opt.departure_step)) {
          stop_kind = 3;
          br.to_point = known >= 0 ? known : dep.point;
          return true;
        }
      }
      return static_cast<int>(br.path.size()) >= opt.max_points_per_branch;
    };
    const ContinuationResult cr = continue_one_dof(sys, leave.x, dep.direction, accept, opt.continuation);
    if (br.path.size() == 1) {
      // Not traced (e.g. more than 1 DOF just off the point): keep the departure point and its DOF.
      record(leave.x);
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> J;
      sys.evaluate(leave.x, r, J);
      RankOptions ro;
      ro.relative_tolerance = opt.cone.rank_tolerance;  // the cut the tangent cones use
      ro.compute_null_space = false;
      br.dof_at_departure = jacobian_rank(J, ro).dof;
    }
    if (stop_kind == 0) br.stopped_by = cr.stopped ? "max points" : cr.reason;
    if (stop_kind == 3) br.stopped_by = "reached a known point";
    if (stop_kind == 1) {
      br.stopped_by = "bifurcation";
      const LocatedSingularPoint loc = locate_singular_point(sys, bif_a, bif_b, opt.locate_tolerance);
      if (loc.found) {
        int p = find_point(loc.x);
        const Eigen::VectorXd incoming = (bif_a - loc.x).normalized();
        if (p < 0) {
          BranchPoint bp;
          bp.kind = "bifurcation";
          bp.parameter_edge = br.driving_edge;
          bp.parameter = sys.edges_from_unknowns(loc.x)[br.driving_edge];
          bp.parameter_uncertainty = loc.parameter_uncertainty;
          bp.sigma_second_smallest = loc.sigma_second_smallest;
          bp.sigma_max = loc.sigma_max;
          p = add_point(bp, loc.x, [](const Eigen::VectorXd&) { return true; });
        }
        used[p].push_back(incoming);
        br.to_point = p;
        // The branch's last point is the bifurcation itself.
        br.path.back() = sys.edges_from_unknowns(loc.x);
      } else {
        br.stopped_by = "bifurcation (not located)";
      }
    }
    if (stop_kind == 2) {
      br.stopped_by = "fold limit";
      // Solve for the configuration with the stopping crease exactly at +-pi.
      const int k = sys.unknown_of_edge(br.stop_crease);
      if (k >= 0) {
        Eigen::VectorXd guess = prev_x;
        guess[k] = guess[k] > 0 ? kPi : -kPi;
        NewtonOptions nopt;
        nopt.held_unknowns = {k};
        const NewtonResult nr = newton_project(sys, guess, nopt);
        if (nr.converged && (nr.x - prev_x).lpNorm<Eigen::Infinity>() < 0.1) {
          const Eigen::VectorXd rho = sys.edges_from_unknowns(nr.x);
          bool all_flat_folded = true;
          for (int e = 0; e < rho.size(); ++e) {
            const double a = std::abs(rho[e]);
            if (std::min(a, std::abs(a - kPi)) > 1e-6) all_flat_folded = false;
          }
          int p = find_point(nr.x);
          if (p < 0) {
            BranchPoint bp;
            bp.kind = all_flat_folded ? "fully folded" : "interference";
            bp.stop_crease = br.stop_crease;
            bp.parameter_edge = br.stop_crease;
            bp.parameter = guess[k];
            auto folds_back = [&](const Eigen::VectorXd& d) {
              if (!all_flat_folded) return false;
              const Eigen::VectorXd step = sys.edges_from_unknowns(nr.x + 1e-3 * d);
              return step.cwiseAbs().maxCoeff() <= kPi;
            };
            p = add_point(bp, nr.x, folds_back);
          }
          used[p].push_back((prev_x - nr.x).normalized());
          br.to_point = p;
        }
      }
    }
    if (br.dof_at_departure < 0) br.dof_at_departure = 1;
    br.driving_begin = br.path.front()[br.driving_edge];
    br.driving_end = br.path.back()[br.driving_edge];
    out.branches.push_back(std::move(br));
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rigidfold
