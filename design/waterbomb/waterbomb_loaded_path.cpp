#include "design/waterbomb/waterbomb_loaded_path.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/flat_branch_continuation.hpp"
#include "design/waterbomb/waterbomb_force.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::waterbomb {

LoadedPath waterbomb_loaded_path(int n, double theta0, double k_m, double k_v, const std::vector<double>& thetas,
                                 const LoadedPathOptions& options) {
  const WaterbombSprings ws = springs_at_rest_theta(n, theta0, k_m, k_v);
  for (double th : thetas)
    if (!(th > 0.0 && th < theta_limit(n)) || th == kPi / 2)
      throw InputError("theta", "loaded states need theta in (0, theta_limit), not the flat state");
  generators::WaterbombParams wp;
  wp.n = n;
  const CreasePattern p = generators::waterbomb_base(wp);
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  auto per_edge = [&](FoldPair g) { return waterbomb_edge_angles(p, g); };
  const CreaseSprings springs = make_crease_springs(p, stiffness_by_assignment(p, {k_m, k_v, 0.0}), per_edge(ws.rest));
  VertexHeightLoad load;
  load.vertex = 0;
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] == Assignment::Valley) load.support_edges.push_back(e);
  const double r = std::cos(kPi / n);  // the generator's valley (mid-line) crease length

  for (int e : options.flipped_letters)
    if (e < 0 || e >= 2 * n) throw InputError("flipped_letters", "crease " + std::to_string(e) + " is not one of the 2n creases");

  // start: free fold angles; empty = the symmetric closed form at th (near side only).
  Eigen::VectorXd last_x;
  auto solve = [&](double th, const Eigen::VectorXd& start, bool stability = true) {
    LoadedPoint q;
    q.theta = th;
    load.height = r * std::cos(th);
    const Eigen::VectorXd symmetric = per_edge(waterbomb_fold_angles(n, th));
    HeightControlOptions ho;
    ho.compute_stability = stability;
    const HeightControlledEquilibrium eq = vertex_height_equilibrium(
        p, sys, topo, springs, load, start.size() ? start : sys.unknowns_from_edges(symmetric), ho);
    last_x = eq.x;
    const ForcePoint f = waterbomb_force(ws, theta0, r, th);
    q.height = f.height;
    q.deflection = f.deflection;
    q.force = eq.force;
    q.force_closed_form = f.force;
    q.fold_angle_gap = (eq.edge_angles - symmetric).lpNorm<Eigen::Infinity>();
    q.min_eigenvalue = eq.min_eigenvalue;
    q.converged = eq.converged;
    q.stable = eq.stable;
    return q;
  };

  LoadedPath out;
  out.points.resize(thetas.size());
  std::vector<Eigen::VectorXd> xs(thetas.size());  // far side: the solutions, for bisection starts
  std::vector<std::size_t> far;
  for (std::size_t i = 0; i < thetas.size(); ++i) {
    if (thetas[i] > kPi / 2)
      far.push_back(i);
    else
      out.points[i] = solve(thetas[i], Eigen::VectorXd());
  }
  if (!far.empty()) {
    out.crosses_flat = true;
    CreasePattern lettered = p;
    for (int e : options.flipped_letters)
      lettered.assignments[e] = lettered.assignments[e] == Assignment::Mountain ? Assignment::Valley
                                : lettered.assignments[e] == Assignment::Valley ? Assignment::Mountain
                                                                                : lettered.assignments[e];
    out.flat_crossing = waterbomb_flat_crossing(lettered, load.support_edges);
    std::stable_sort(far.begin(), far.end(), [&](std::size_t a, std::size_t b) { return thetas[a] < thetas[b]; });
    for (std::size_t i : far) out.points[i].theta = thetas[i];
    if (!out.flat_crossing.continues) {
      out.stopped_at_flat = true;
      out.stop_message = out.flat_crossing.message;
    } else {
      // Natural continuation from the flat state along the chosen ray (flat_branch_continuation.hpp).
      const FlatBranch& ray = out.flat_crossing.branches[out.flat_crossing.taken];
      LoadedPoint sampled;
      FlatBranchContinuation continuation(
          sys.unknowns_from_edges(ray.direction), ray.height_rate, r, LoadedPathOptions::kMaxHeightStep,
          LoadedPathOptions::kMaxAngleStep, [&](double th, const Eigen::VectorXd& start, bool sample) {
            sampled = solve(th, start, sample);
            return FlatBranchSolve{sampled.converged, last_x};
          });
      bool failed = false;
      for (std::size_t i : far) {
        if (!failed) {
          failed = !continuation.advance_to(thetas[i]).converged;
          if (!failed) {
            out.points[i] = sampled;
            xs[i] = last_x;
          } else if (sampled.theta == thetas[i]) {
            out.points[i] = sampled;  // the sample itself did not converge: its unconverged point
          }
        }
        if (failed && out.stop_message.empty())
          out.stop_message = "the continuation from the flat state did not converge before theta = " +
                             std::to_string(thetas[i] * 180.0 / kPi) + " deg";
      }
    }
  }
  for (std::size_t i = 1; i < out.points.size(); ++i) {
    const LoadedPoint& a = out.points[i - 1];
    const LoadedPoint& b = out.points[i];
    if (!a.converged || !b.converged) continue;
    if ((a.theta < kPi / 2) != (b.theta < kPi / 2)) continue;  // never across the flat state
    if ((a.min_eigenvalue > 0.0) == (b.min_eigenvalue > 0.0)) continue;
    // Far side: start from the mean of the bracket ends' solutions (never the closed form);
    // the bracket shrinks, so the start's error falls as |hi - lo|^2.
    const bool far_pair = a.theta > kPi / 2 && xs[i - 1].size() && xs[i].size();
    Eigen::VectorXd x_lo = xs[i - 1], x_hi = xs[i];
    double lo = a.theta, hi = b.theta;
    const bool lo_positive = a.min_eigenvalue > 0.0;
    while (std::fabs(hi - lo) > 1e-10) {
      const double mid = 0.5 * (lo + hi);
      const LoadedPoint m = solve(mid, far_pair ? Eigen::VectorXd(0.5 * (x_lo + x_hi)) : Eigen::VectorXd());
      if (!m.converged) break;
      const bool to_lo = (m.min_eigenvalue > 0.0) == lo_positive;
      (to_lo ? lo : hi) = mid;
      (to_lo ? x_lo : x_hi) = last_x;
    }
    out.stability_changes.push_back(0.5 * (lo + hi));
  }
  return out;
}

}  // namespace rigidfold::waterbomb
