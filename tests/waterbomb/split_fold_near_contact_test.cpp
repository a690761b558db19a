// Split fold n = 3 with wide split facets (b = 45 deg): the loaded path near theta_max was
// reported as "leaving the symmetric path" (--curve exit 3). It does not: the symmetric
// loaded states there are stable (reduced-Hessian eigenvalues > 0, rising); the height
// control's Newton started its plane normal from the mean face normal, which is far from the
// support plane's normal when the big valley split facets are folded nearly shut.
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/split_fold_bistability.hpp"
#include "design/waterbomb/split_fold_kinematics.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::waterbomb {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(SplitFoldNearContact, WideSplitFacetsStaySymmetricAndStableUpToThetaMax) {
  const int n = 3;
  const double b = to_radians(45.0);
  const SplitFoldSprings s = split_fold_springs(n, b, to_radians(60.0), 1.0, 1.0);
  const CreasePattern p = split_fold_base(n, b);
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  auto per_edge = [&](FoldPair g) {
    Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
    for (int i = 0; i < 4 * n; ++i) rho[i] = (i % 4 < 2) ? g.gamma_v : g.gamma_m;
    return rho;
  };
  const CreaseSprings springs = make_crease_springs(p, Eigen::VectorXd::Ones(p.num_edges()), per_edge(s.rest));
  VertexHeightLoad load;
  load.vertex = 0;
  for (int i = 0; i < 4 * n; ++i)
    if (i % 4 < 2) load.support_edges.push_back(i);
  const double r = std::cos(b / 2);
  double previous = 0.0;
  // theta_max = 148.553 deg; at 146 deg and beyond the old start normal failed.
  for (double deg : {140.0, 146.0, 147.0, 148.0, 148.5}) {
    SCOPED_TRACE(deg);
    const double th = to_radians(deg);
    ASSERT_LT(th, s.range.theta_max);
    load.height = r * std::cos(th);
    const Eigen::VectorXd printed = per_edge(split_fold_angles_printed(n, b, th));
    const HeightControlledEquilibrium eq =
        vertex_height_equilibrium(p, sys, topo, springs, load, sys.unknowns_from_edges(printed));
    ASSERT_TRUE(eq.converged) << eq.message;
    EXPECT_LE(eq.iterations, 2);  // the start is the solution: no wandering
    EXPECT_LE((eq.edge_angles - printed).lpNorm<Eigen::Infinity>(), 1e-9);
    EXPECT_GT(eq.min_eigenvalue, previous);  // stable and stiffening: no symmetry breaking
    previous = eq.min_eigenvalue;
  }
  // The curve is then checked everywhere (it exited 3 before).
  const SplitFoldCurve c = split_fold_curve(n, b, to_radians(60.0), 1.0, 1.0, 41);
  EXPECT_EQ(c.unchecked, 0);
}

}}  // namespace
}  // namespace rigidfold::waterbomb
