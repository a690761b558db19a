// Displacement control of the waterbomb vertex with the reaction force as Lagrange
// multipliers (kernel/energy/vertex_height_control.hpp), no symmetry imposed, against the
// virtual-work closed form of seed 004 eq. 3.9 (design/waterbomb/waterbomb_force.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "design/waterbomb/waterbomb_force.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// The generated waterbomb base of n mountain creases, its springs at rest at theta0 (k_m,
// k_v), pressed at its vertex with the valley creases' ends on the support plane.
struct LoadedWaterbomb {
  int n;
  CreasePattern p;
  Topology topo;
  ClosureSystem sys;
  waterbomb::WaterbombSprings ws;
  CreaseSprings springs;
  VertexHeightLoad load;
  double r;  // the generator's mid-line (valley) crease length

  LoadedWaterbomb(int n_, double theta0, double km, double kv)
      : n(n_), p(base(n_)), topo(build_topology(p)), sys(p, topo), ws(waterbomb::springs_at_rest_theta(n, theta0, km, kv)),
        springs(make_crease_springs(p, stiffness_by_assignment(p, {km, kv, 0.0}), per_edge(ws.rest))),
        r(std::cos(kPi / n)) {
    load.vertex = 0;
    for (int e = 0; e < 2 * n; ++e)
      if (p.assignments[e] == Assignment::Valley) load.support_edges.push_back(e);
  }
  Eigen::VectorXd per_edge(waterbomb::FoldPair g) const { return waterbomb::waterbomb_edge_angles(p, g); }
  static CreasePattern base(int n) {
    generators::WaterbombParams wp;
    wp.n = n;
    return generators::waterbomb_base(wp);
  }
};

TEST(EnergyHeightControl, ReactionForceEqualsVirtualWork) {
  for (int n : {3, 4, 6}) {
    const double th0 = to_radians(60.0), km = 1.5, kv = 1.0;
    LoadedWaterbomb wb(n, th0, km, kv);
    auto& [nn, p, topo, sys, ws, springs, load, r] = wb;  // load.height is set per state
    auto per_edge = [&](waterbomb::FoldPair g) { return wb.per_edge(g); };
    std::mt19937_64 rng(n);
    std::uniform_real_distribution<double> u(-0.02, 0.02);
    for (double deg : {60.0, 70.0, 85.0, 95.0, 110.0}) {
      const double th = to_radians(deg);
      load.height = r * std::cos(th);
      Eigen::VectorXd x0 = sys.unknowns_from_edges(per_edge(waterbomb::waterbomb_fold_angles(n, th)));
      for (Eigen::Index i = 0; i < x0.size(); ++i) x0[i] += u(rng);
      const HeightControlledEquilibrium eq = vertex_height_equilibrium(p, sys, topo, springs, load, x0);
      ASSERT_TRUE(eq.converged) << eq.message << " n " << n << " theta " << deg;
      EXPECT_LE(eq.iterations, 15);
      const Eigen::VectorXd want = per_edge(waterbomb::waterbomb_fold_angles(n, th));
      EXPECT_LT((eq.edge_angles - want).lpNorm<Eigen::Infinity>(), 1e-9) << n << " " << deg;
      const double F = waterbomb::waterbomb_force(ws, th0, r, th).force;
      EXPECT_NEAR(eq.force, F, 1e-9 * std::max(1.0, std::fabs(F))) << n << " " << deg;
      // Equal share at every support of the symmetric state.
      for (Eigen::Index s = 0; s < eq.support_reactions.size(); ++s)
        EXPECT_NEAR(eq.support_reactions[s], -F / n, 1e-9 * std::max(1.0, std::fabs(F))) << n << " " << deg;
      if (deg == 60.0) {
        // The multipliers are as accurate as the stationarity (1e-12 x k), divided by the
        // support geometry's conditioning: the same 1e-9 bound as the force rows above.
        EXPECT_NEAR(eq.force, 0.0, 1e-9);
        EXPECT_TRUE(eq.stable);  // the rest state under its own height
      }
      EXPECT_EQ(eq.tangent_dimension, (2 * n - 3) + 3 - n - 1);
      // Reactions of order 1: the stationarity test is the plain 1e-12 x max(k).
      EXPECT_EQ(eq.stationarity_bound, 1e-12 * km) << n << " " << deg;
    }
  }
}

// Near the flat state the reactions are large (n = 60, theta = 0.177 deg: F = -1.6e5), and
// the rounding of grad L's own evaluation exceeds 1e-12 x k: at the exact closed-form state
// it evaluates to 3e-11 (the bound on that rounding is 2.6e-9), Newton's steps lowered it to
// 9e-12 but no further, and after 50 iterations the sample was refused (`waterbomb --n 60
// --samples 3 --curve` exited 3 after 8 s). With the rounding bound in the test it converges,
// and its force and fold angles agree with the closed form.
TEST(EnergyHeightControl, LargeReactionsNearFlatConvergeToTheRoundingBound) {
  const int n = 60;
  const double th0 = to_radians(60.0);
  LoadedWaterbomb wb(n, th0, 1.0, 1.0);
  auto& [nn, p, topo, sys, ws, springs, load, r] = wb;
  const double th = to_radians(0.177);
  load.height = r * std::cos(th);
  const Eigen::VectorXd want = wb.per_edge(waterbomb::waterbomb_fold_angles(n, th));
  HeightControlOptions ho;
  ho.compute_stability = false;
  // From the closed form, as the curve starts its near-side samples: the exact state, whose
  // gradient evaluates to ~3e-11 by rounding alone.
  const Eigen::VectorXd x0 = sys.unknowns_from_edges(want);
  const HeightControlledEquilibrium eq = vertex_height_equilibrium(p, sys, topo, springs, load, x0, ho);
  ASSERT_TRUE(eq.converged) << eq.message << ": stationarity " << eq.stationarity_residual << " against "
                            << eq.stationarity_bound << ", constraints " << eq.constraint_residual << ", "
                            << eq.iterations << " iterations";
  const double F = waterbomb::waterbomb_force(ws, th0, r, th).force;
  EXPECT_LT(F, -1e5);
  EXPECT_GT(eq.stationarity_bound, 1e-12);             // the rounding bound is the one in force
  EXPECT_LE(eq.stationarity_bound, 1e-13 * std::fabs(F));  // ... tiny against the force (2.6e-9 here)
  std::printf("n = 60, theta = 0.177 deg: stationarity %.2e (bound %.2e), %d iterations, force %.10g\n",
              eq.stationarity_residual, eq.stationarity_bound, eq.iterations, eq.force);
  EXPECT_NEAR(eq.force, F, 1e-9 * std::fabs(F));
  EXPECT_LT((eq.edge_angles - want).lpNorm<Eigen::Infinity>(), 1e-9);
}

// Exact derivatives: on the closure manifold, the constraint Jacobian and the Hessian of the
// Lagrangian equal central differences of the rows and of the gradient (random normal and
// multipliers, n = 5, an asymmetric state).
TEST(EnergyHeightControl, KktDerivativesMatchCentralDifferences) {
  const int n = 5;
  generators::WaterbombParams wp;
  wp.n = n;
  const CreasePattern p = generators::waterbomb_base(wp);
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  std::mt19937_64 rng(55);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd k(p.num_edges()), rest(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) {
    k[e] = 1.0 + 0.5 * u(rng);
    rest[e] = 0.5 * u(rng);
  }
  const CreaseSprings springs = make_crease_springs(p, k, rest);
  VertexHeightLoad load;
  load.vertex = 0;
  load.support_edges = {0, 4, 6};
  load.height = 0.3;
  // An asymmetric point on the manifold: the closed form at 70 deg, perturbed, projected.
  Eigen::VectorXd edges = Eigen::VectorXd::Zero(p.num_edges());
  const auto g = waterbomb::waterbomb_fold_angles(n, to_radians(70.0));
  for (int e = 0; e < 2 * n; ++e) edges[e] = (p.assignments[e] == Assignment::Mountain ? g.gamma_m : g.gamma_v) + 0.05 * u(rng);
  const NewtonResult proj = newton_project(sys, sys.unknowns_from_edges(edges));
  ASSERT_TRUE(proj.converged);
  const Eigen::VectorXd x = proj.x;
  const Eigen::Vector3d nu = Eigen::Vector3d(u(rng), u(rng), 1.0).normalized();
  Eigen::VectorXd w(sys.num_rows() + 3 + 1);
  for (Eigen::Index i = 0; i < w.size(); ++i) w[i] = u(rng);
  const HeightControlKkt at = height_control_kkt(p, sys, topo, springs, load, x, nu, w);
  const int nx = sys.num_unknowns();
  const double h = 1e-6;
  for (int j = 0; j < nx + 3; ++j) {
    Eigen::VectorXd xp = x, xm = x;
    Eigen::Vector3d np = nu, nm = nu;
    if (j < nx) {
      xp[j] += h;
      xm[j] -= h;
    } else {
      np[j - nx] += h;
      nm[j - nx] -= h;
    }
    const HeightControlKkt a = height_control_kkt(p, sys, topo, springs, load, xp, np, w);
    const HeightControlKkt b = height_control_kkt(p, sys, topo, springs, load, xm, nm, w);
    const Eigen::VectorXd dc = (a.constraints - b.constraints) / (2 * h);
    const Eigen::VectorXd dg = (a.gradient - b.gradient) / (2 * h);
    EXPECT_LT((dc - at.jacobian.col(j)).lpNorm<Eigen::Infinity>(), 1e-8) << "column " << j;
    EXPECT_LT((dg - at.hessian.col(j)).lpNorm<Eigen::Infinity>(), 1e-7) << "column " << j;
  }
  EXPECT_LT((at.hessian - at.hessian.transpose()).lpNorm<Eigen::Infinity>(), 1e-12);
}

}}  // namespace
}  // namespace rigidfold
