// Equilibria of the crease-spring energy on the loop-closure manifold, no symmetry imposed
// (kernel/energy/constrained_equilibrium.hpp), checked on the waterbomb base against the
// seed-004 closed forms (design/waterbomb).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <random>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "design/waterbomb/waterbomb_energy.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct Base {
  CreasePattern pattern;
  Topology topology;
  ClosureSystem system;
  CreaseSprings springs;
  Base(int n, waterbomb::FoldPair rest, double k_m, double k_v)
      : pattern(make(n)), topology(build_topology(pattern)), system(pattern, topology),
        springs(make_crease_springs(pattern, stiffness_by_assignment(pattern, {k_m, k_v, 0.0}), per_edge(rest))) {}
  static CreasePattern make(int n) {
    generators::WaterbombParams wp;
    wp.n = n;
    return generators::waterbomb_base(wp);
  }
  Eigen::VectorXd per_edge(waterbomb::FoldPair g) const { return waterbomb::waterbomb_edge_angles(pattern, g); }
  // The closed-form state at theta plus an asymmetric random perturbation of `size` rad.
  Eigen::VectorXd perturbed_start(int n, double theta, double size, unsigned seed) const {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-size, size);
    Eigen::VectorXd x = system.unknowns_from_edges(per_edge(waterbomb::waterbomb_fold_angles(n, theta)));
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += u(rng);
    return x;
  }
};

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

// Largest spread of the mountain (valley) fold angles: 0 for a symmetric state.
double asymmetry(const Base& b, const Eigen::VectorXd& rho) {
  double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
  for (int e = 0; e < b.pattern.num_edges(); ++e) {
    const int t = b.pattern.assignments[e] == Assignment::Mountain ? 0 : b.pattern.assignments[e] == Assignment::Valley ? 1 : -1;
    if (t < 0) continue;
    lo[t] = std::min(lo[t], rho[e]);
    hi[t] = std::max(hi[t], rho[e]);
  }
  return std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

// The far-side (theta > 90 deg) minimum of the closed-form path.
waterbomb::PathEquilibrium far_minimum(const waterbomb::WaterbombSprings& s) {
  for (const auto& e : waterbomb::waterbomb_path_equilibria(s))
    if (e.kind == waterbomb::EquilibriumKind::kMinimum && e.theta > kPi / 2 && !e.at_validity_limit) return e;
  ADD_FAILURE() << "no far-side minimum";
  return {};
}

// Seed 004 Fig 2.9: n = 4, theta0 = 60 deg, equal k. The general
// minimiser (2n - 3 = 5 DOF, no symmetry), started on the far side of flat from a perturbed
// state, finds the second stable state near theta = 99 deg, (gamma_m, gamma_v) near
// (-18, 43) deg (the figure's reading), equal to the closed form to 1e-9 rad and 1e-9 in
// energy.
TEST(EnergyEquilibrium, Fig29SecondStableStateWithoutSymmetry) {
  const int n = 4;
  const auto ws = waterbomb::springs_at_rest_theta(n, to_radians(60.0), 1.0, 1.0);
  const waterbomb::PathEquilibrium closed = far_minimum(ws);
  EXPECT_NEAR(to_degrees(closed.theta), 99.0, 1.0);
  EXPECT_NEAR(to_degrees(closed.angles.gamma_m), -18.0, 2.0);
  EXPECT_NEAR(to_degrees(closed.angles.gamma_v), 43.0, 2.0);

  const Base b(n, ws.rest, 1.0, 1.0);
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::VectorXd x0 = b.perturbed_start(n, to_radians(120.0), 0.05, seed);
    ASSERT_GT(asymmetry(b, b.system.edges_from_unknowns(x0)), 0.01);
    const Equilibrium eq = find_equilibrium(b.system, b.topology, b.springs, x0);
    ASSERT_TRUE(eq.converged) << eq.message;
    EXPECT_TRUE(eq.stable);
    EXPECT_GT(eq.min_eigenvalue, 0.0);
    EXPECT_EQ(eq.tangent_dimension, 2 * n - 3);
    EXPECT_LE(eq.closure_residual, 1e-12);
    EXPECT_LT(eq.iterations, 30);
    for (int e = 0; e < b.pattern.num_edges(); ++e) {
      const double want = b.pattern.assignments[e] == Assignment::Mountain ? closed.angles.gamma_m
                          : b.pattern.assignments[e] == Assignment::Valley ? closed.angles.gamma_v
                                                                            : 0.0;
      EXPECT_NEAR(eq.edge_angles[e], want, 1e-9) << "edge " << e << " seed " << seed;
    }
    EXPECT_NEAR(eq.energy, closed.energy, 1e-9 * closed.energy);
    // The measured gaps, recorded in the XML report (--gtest_output=xml).
    RecordProperty("angle_gap_rad_seed" + std::to_string(seed),
                   sci((eq.edge_angles - b.per_edge(closed.angles)).lpNorm<Eigen::Infinity>()));
    RecordProperty("energy_gap_rel_seed" + std::to_string(seed),
                   sci(std::fabs(eq.energy - closed.energy) / closed.energy));
    EXPECT_NEAR(eq.energy, waterbomb::waterbomb_energy(ws, closed.theta), 1e-9 * closed.energy);
  }
  // Started near the rest state, the minimiser returns to it (state 1, zero energy).
  const Equilibrium first = find_equilibrium(b.system, b.topology, b.springs, b.perturbed_start(n, to_radians(50.0), 0.05, 9));
  ASSERT_TRUE(first.converged) << first.message;
  EXPECT_TRUE(first.stable);
  EXPECT_LT((first.edge_angles - b.per_edge(ws.rest)).lpNorm<Eigen::Infinity>(), 1e-9);
  EXPECT_LT(first.energy, 1e-18);
}

// The same for other degrees and unequal stiffnesses: the unsymmetric minimiser from a
// perturbed far-side start lands on the closed-form state 2.
TEST(EnergyEquilibrium, FarSideMinimumMatchesClosedFormForEveryDegree) {
  for (int n : {3, 5, 6, 8})
    for (double ratio : {0.5, 2.0}) {
      const auto ws = waterbomb::springs_at_rest_theta(n, to_radians(55.0), ratio, 1.0);
      const waterbomb::PathEquilibrium closed = far_minimum(ws);
      const Base b(n, ws.rest, ratio, 1.0);
      const double start = std::min(closed.theta + 0.2, 0.5 * (closed.theta + waterbomb::theta_limit(n)));
      const Equilibrium eq = find_equilibrium(b.system, b.topology, b.springs, b.perturbed_start(n, start, 0.03, n));
      ASSERT_TRUE(eq.converged) << eq.message << " n " << n << " ratio " << ratio;
      EXPECT_TRUE(eq.stable) << n << " " << ratio;
      EXPECT_LT((eq.edge_angles - b.per_edge(closed.angles)).lpNorm<Eigen::Infinity>(), 1e-9) << n << " " << ratio;
      EXPECT_NEAR(eq.energy, closed.energy, 1e-9 * closed.energy) << n << " " << ratio;
    }
}

// stable_states collects the two states of the bistable base, in order of energy.
TEST(EnergyEquilibrium, StableStatesListsBothStates) {
  const int n = 4;
  const auto ws = waterbomb::springs_at_rest_theta(n, to_radians(60.0), 1.0, 1.0);
  const Base b(n, ws.rest, 1.0, 1.0);
  std::vector<Eigen::VectorXd> starts;
  for (double th : {45.0, 70.0, 110.0, 125.0}) starts.push_back(b.perturbed_start(n, to_radians(th), 0.03, 5));
  const std::vector<Equilibrium> states = stable_states(b.system, b.topology, b.springs, starts);
  ASSERT_EQ(states.size(), 2u);
  EXPECT_LT(states[0].energy, 1e-18);
  EXPECT_NEAR(states[1].energy, far_minimum(ws).energy, 1e-9 * states[1].energy);
}

// The reduced Hessian against an independent second derivative: the symmetric path through
// state 2 is one curve on the manifold, so by Rayleigh eigmin |t|^2 <= V''(theta) (t the
// path tangent; exact at a KKT point, where the multipliers carry the manifold's curvature).
// Off the equilibrium the stationarity residual (the projected gradient) is not 0.
TEST(EnergyEquilibrium, ReducedHessianBoundsPathCurvature) {
  const int n = 4;
  const auto ws = waterbomb::springs_at_rest_theta(n, to_radians(60.0), 1.0, 1.0);
  const Base b(n, ws.rest, 1.0, 1.0);
  const waterbomb::PathEquilibrium closed = far_minimum(ws);
  const Eigen::VectorXd x = b.system.unknowns_from_edges(b.per_edge(closed.angles));
  const Equilibrium eq = analyse_equilibrium(b.system, b.topology, b.springs, x);
  ASSERT_TRUE(eq.converged);
  // Path tangent t = d rho / d theta (unknown space) and the second difference of V(theta):
  // by Rayleigh, eigmin |t|^2 <= t^T H_r t = V''(theta) at an equilibrium.
  const waterbomb::FoldPair d = waterbomb::waterbomb_fold_angle_derivatives(n, closed.theta);
  const Eigen::VectorXd t = b.system.unknowns_from_edges(b.per_edge(d));
  const double h = 1e-4;
  const double v2 = (waterbomb::waterbomb_energy(ws, closed.theta + h) - 2 * closed.energy +
                     waterbomb::waterbomb_energy(ws, closed.theta - h)) / (h * h);
  EXPECT_GT(v2, 0.0);
  EXPECT_LE(eq.min_eigenvalue * t.squaredNorm(), v2 * (1 + 1e-6));
  EXPECT_GT(eq.min_eigenvalue, 0.0);
  // Off the equilibrium (state 2 moved along the path) the stationarity residual is the
  // projected gradient, not 0.
  const Eigen::VectorXd x1 = b.system.unknowns_from_edges(b.per_edge(waterbomb::waterbomb_fold_angles(n, closed.theta + 0.1)));
  const Equilibrium off = analyse_equilibrium(b.system, b.topology, b.springs, x1);
  EXPECT_FALSE(off.converged);
  EXPECT_GT(off.stationarity_residual, 1e-3);
}

}}  // namespace
}  // namespace rigidfold
