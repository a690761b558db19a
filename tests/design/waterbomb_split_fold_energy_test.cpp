// Split-fold waterbomb on the general model: the minimiser on the 4n-crease closure manifold
// (no symmetry imposed) finds a second stable state that lies on the printed split-fold path
// (seed 004 eqs 3.13-3.30) and is a minimum along it; and split folds lower the energy
// (seed 004 ch. 3 claim), checked on the flat barrier.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "design/waterbomb/split_fold_kinematics.hpp"
#include "design/waterbomb/waterbomb_energy.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using waterbomb::FoldPair;

double split_energy(int n, double b, FoldPair rest, double theta) {
  const FoldPair g = waterbomb::split_fold_angles_printed(n, b, theta);
  // 2n half-mountains and 2n half-valleys, each 1/2 k (gamma - gamma0)^2, k = 1 (eq. 3.31).
  return n * ((g.gamma_m - rest.gamma_m) * (g.gamma_m - rest.gamma_m) + (g.gamma_v - rest.gamma_v) * (g.gamma_v - rest.gamma_v));
}

TEST(WaterbombSplitFoldEnergy, GeneralMinimumLiesOnPrintedPath) {
  const int n = 4;
  const double b = to_radians(5.0), a = kPi / n - b, th0 = to_radians(60.0);
  std::vector<double> dirs;
  for (int k = 0; k < n; ++k) {
    const double s = k * 2 * kPi / n;
    dirs.insert(dirs.end(), {s, s + b, s + b + a, s + 2 * b + a});
  }
  CreasePattern p = testing::single_vertex_pattern(dirs);
  for (int i = 0; i < 4 * n; ++i) p.assignments[i] = (i % 4 < 2) ? Assignment::Valley : Assignment::Mountain;
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  const FoldPair rest = waterbomb::split_fold_angles_printed(n, b, th0);
  auto per_edge = [&](FoldPair g) {
    Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
    for (int i = 0; i < 4 * n; ++i) rho[i] = p.assignments[i] == Assignment::Valley ? g.gamma_v : g.gamma_m;
    return rho;
  };
  Eigen::VectorXd k = Eigen::VectorXd::Zero(p.num_edges());
  k.head(4 * n).setOnes();
  const CreaseSprings springs = make_crease_springs(p, k, per_edge(rest));
  ASSERT_LE(topo.interior_vertices.size(), 1u);
  ASSERT_LT((Eigen::VectorXd(sys.residual(sys.unknowns_from_edges(per_edge(rest))))).norm(), 1e-10);

  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  Eigen::VectorXd x0 = sys.unknowns_from_edges(per_edge(waterbomb::split_fold_angles_printed(n, b, to_radians(115.0))));
  for (Eigen::Index i = 0; i < x0.size(); ++i) x0[i] += u(rng);
  const Equilibrium eq = find_equilibrium(sys, topo, springs, x0);
  ASSERT_TRUE(eq.converged) << eq.message;
  EXPECT_TRUE(eq.stable);
  // Symmetric: every half-valley equal, every half-mountain equal.
  const double gv = eq.edge_angles[0], gm = eq.edge_angles[2];
  for (int i = 0; i < 4 * n; ++i) EXPECT_NEAR(eq.edge_angles[i], (i % 4 < 2) ? gv : gm, 1e-9) << i;
  // theta on the far side with the printed gamma_m = the general one (bisection; gamma_m
  // rises toward 0 as theta falls to flat), then gamma_v must match too.
  double lo = kPi / 2 + 1e-6, hi = to_radians(130.0);
  ASSERT_GT(waterbomb::split_fold_angles_printed(n, b, lo).gamma_m, gm);
  ASSERT_LT(waterbomb::split_fold_angles_printed(n, b, hi).gamma_m, gm);
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (waterbomb::split_fold_angles_printed(n, b, mid).gamma_m > gm ? lo : hi) = mid;
  }
  const double th = 0.5 * (lo + hi);
  EXPECT_NEAR(waterbomb::split_fold_angles_printed(n, b, th).gamma_v, gv, 1e-9);
  EXPECT_NEAR(split_energy(n, b, rest, th), eq.energy, 1e-9 * eq.energy);
  // A minimum along the path too.
  EXPECT_GT(split_energy(n, b, rest, th + 1e-3), eq.energy);
  EXPECT_GT(split_energy(n, b, rest, th - 1e-3), eq.energy);
  RecordProperty("split_state2_theta_deg", std::to_string(to_degrees(th)));
}

// Split folds lower the energy: the flat-state barrier (every fold at 0) of the SFWB is below
// the WB's of the same degree and rest theta0, k = 1 everywhere.
TEST(WaterbombSplitFoldEnergy, SplitFoldsLowerTheBarrier) {
  for (int n : {3, 4, 10}) {
    const double th0 = to_radians(55.0);
    const auto wb = waterbomb::springs_at_rest_theta(n, th0, 1.0, 1.0);
    const double wb_barrier = waterbomb::waterbomb_energy(wb, kPi / 2);
    for (double bdeg : {1.0, 5.0}) {
      const FoldPair rest = waterbomb::split_fold_angles_printed(n, to_radians(bdeg), th0);
      const double sf_barrier = n * (rest.gamma_m * rest.gamma_m + rest.gamma_v * rest.gamma_v);
      EXPECT_LT(sf_barrier, wb_barrier) << n << " " << bdeg;
      EXPECT_GT(sf_barrier, 0.0);
    }
  }
}

}}  // namespace
}  // namespace rigidfold
