#include "design/waterbomb/waterbomb_bistability.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "data/generators/waterbomb.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold::waterbomb {

std::vector<WaterbombBistability::Barrier> WaterbombBistability::symmetric_path_barriers() const {
  std::vector<Barrier> out;
  for (const CheckedEquilibrium& cusp : equilibria)
    if (cusp.path.kind == EquilibriumKind::kCuspMaximum)
      for (const CheckedEquilibrium& s : stable_states()) out.push_back({s.path.theta, cusp.path.energy - s.path.energy});
  return out;
}

std::vector<CheckedEquilibrium> WaterbombBistability::stable_states() const {
  std::vector<CheckedEquilibrium> out;
  for (const CheckedEquilibrium& e : equilibria)
    if (e.path.kind == EquilibriumKind::kMinimum && !e.path.at_validity_limit && e.stable_unrestricted)
      out.push_back(e);
  return out;
}

WaterbombBistability waterbomb_bistability(int n, double theta0, double k_m, double k_v) {
  WaterbombBistability out;
  out.springs = springs_at_rest_theta(n, theta0, k_m, k_v);
  out.theta0 = theta0;

  generators::WaterbombParams wp;
  wp.n = n;
  const CreasePattern pattern = generators::waterbomb_base(wp);
  const Topology topology = build_topology(pattern);
  const ClosureSystem system(pattern, topology);
  Eigen::VectorXd rest = Eigen::VectorXd::Zero(pattern.num_edges());
  for (int e = 0; e < pattern.num_edges(); ++e) {
    if (pattern.assignments[e] == Assignment::Mountain) rest[e] = out.springs.rest.gamma_m;
    if (pattern.assignments[e] == Assignment::Valley) rest[e] = out.springs.rest.gamma_v;
  }
  const CreaseSprings springs =
      make_crease_springs(pattern, stiffness_by_assignment(pattern, {k_m, k_v, 0.0}), rest);
  const double scale = std::max(k_m, k_v);
  const std::vector<double> sectors(2 * n, kPi / n);

  for (const PathEquilibrium& p : waterbomb_path_equilibria(out.springs)) {
    CheckedEquilibrium c;
    c.path = p;
    std::vector<double> rho(2 * n);
    Eigen::VectorXd edge_angles = Eigen::VectorXd::Zero(pattern.num_edges());
    for (int i = 0; i < 2 * n; ++i) {
      // Crease i of the generated base: even = mid-line (V), odd = corner (M), CCW.
      rho[i] = (pattern.assignments[i] == Assignment::Mountain) ? p.angles.gamma_m : p.angles.gamma_v;
      edge_angles[i] = rho[i];
    }
    c.closure_residual = vertex_closure_residual(sectors, rho).norm();
    if (!(c.closure_residual <= 1e-12))
      throw NoAnswerError("waterbomb state at theta = " + std::to_string(to_degrees(p.theta)) +
                              " deg does not close its vertex loop (closure residual, rad)",
                          c.closure_residual);
    const bool cusp = p.kind == EquilibriumKind::kCuspMaximum || p.kind == EquilibriumKind::kCuspMinimum;
    if (cusp || p.at_validity_limit) {
      c.min_reduced_eigenvalue = std::nan("");
      out.equilibria.push_back(c);
      continue;
    }
    if (!(p.slope_residual <= 1e-10 * scale))
      throw NoAnswerError("waterbomb equilibrium at theta = " + std::to_string(to_degrees(p.theta)) +
                              " deg: dV/dtheta is not 0 (slope residual, energy/rad)",
                          p.slope_residual);
    const Equilibrium general = analyse_equilibrium(system, topology, springs, system.unknowns_from_edges(edge_angles));
    c.stationarity_residual = general.stationarity_residual;
    c.min_reduced_eigenvalue = general.min_eigenvalue;
    c.stable_unrestricted = general.stable;
    if (!(general.stationarity_residual <= 1e-10 * scale))
      throw NoAnswerError("waterbomb state at theta = " + std::to_string(to_degrees(p.theta)) +
                              " deg is not an equilibrium of the unsymmetric problem (stationarity, energy/rad)",
                          general.stationarity_residual);
    out.equilibria.push_back(c);
  }
  return out;
}

}  // namespace rigidfold::waterbomb
