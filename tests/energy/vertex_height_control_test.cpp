// Displacement control of the waterbomb vertex with the reaction force as Lagrange
// multipliers (kernel/energy/vertex_height_control.hpp), no symmetry imposed, against the
// virtual-work closed form of seed 004 eq. 3.9 (design/waterbomb/waterbomb_force.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/waterbomb_force.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace {

TEST(EnergyHeightControl, ReactionForceEqualsVirtualWork) {
  for (int n : {3, 4, 6}) {
    generators::WaterbombParams wp;
    wp.n = n;
    const CreasePattern p = generators::waterbomb_base(wp);
    const Topology topo = build_topology(p);
    const ClosureSystem sys(p, topo);
    const double th0 = to_radians(60.0), km = 1.5, kv = 1.0;
    const auto ws = waterbomb::springs_at_rest_theta(n, th0, km, kv);
    auto per_edge = [&](waterbomb::FoldPair g) {
      Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
      for (int e = 0; e < 2 * n; ++e) rho[e] = p.assignments[e] == Assignment::Mountain ? g.gamma_m : g.gamma_v;
      return rho;
    };
    const CreaseSprings springs = make_crease_springs(p, stiffness_by_assignment(p, {km, kv, 0.0}), per_edge(ws.rest));
    VertexHeightLoad load;
    load.vertex = 0;
    for (int e = 0; e < 2 * n; ++e)
      if (p.assignments[e] == Assignment::Valley) load.support_edges.push_back(e);
    const double r = std::cos(kPi / n);  // the generator's mid-line (valley) crease length
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
    }
  }
}

}  // namespace
}  // namespace rigidfold
