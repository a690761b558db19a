#include "design/waterbomb/waterbomb_loaded_path.hpp"

#include <cmath>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/waterbomb_force.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::waterbomb {

LoadedPath waterbomb_loaded_path(int n, double theta0, double k_m, double k_v, const std::vector<double>& thetas) {
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

  auto solve = [&](double th) {
    LoadedPoint q;
    q.theta = th;
    load.height = r * std::cos(th);
    const Eigen::VectorXd symmetric = per_edge(waterbomb_fold_angles(n, th));
    const HeightControlledEquilibrium eq =
        vertex_height_equilibrium(p, sys, topo, springs, load, sys.unknowns_from_edges(symmetric));
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
  for (double th : thetas) out.points.push_back(solve(th));
  for (std::size_t i = 1; i < out.points.size(); ++i) {
    const LoadedPoint& a = out.points[i - 1];
    const LoadedPoint& b = out.points[i];
    if (!a.converged || !b.converged) continue;
    if ((a.theta < kPi / 2) != (b.theta < kPi / 2)) continue;  // never across the flat state
    if ((a.min_eigenvalue > 0.0) == (b.min_eigenvalue > 0.0)) continue;
    double lo = a.theta, hi = b.theta;
    const bool lo_positive = a.min_eigenvalue > 0.0;
    while (std::fabs(hi - lo) > 1e-10) {
      const double mid = 0.5 * (lo + hi);
      const LoadedPoint m = solve(mid);
      if (!m.converged) break;
      ((m.min_eigenvalue > 0.0) == lo_positive ? lo : hi) = mid;
    }
    out.stability_changes.push_back(0.5 * (lo + hi));
  }
  return out;
}

}  // namespace rigidfold::waterbomb
