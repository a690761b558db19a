// Split-fold waterbomb bistability (design/waterbomb/split_fold_bistability.hpp): equilibria
// confirmed on the general 4n-crease model, compared with an independent unsymmetric
// minimisation, with the plain waterbomb in the limit b -> 0, and the seed's claims.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "design/waterbomb/split_fold_bistability.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using waterbomb::EquilibriumKind;

TEST(WaterbombSplitFoldBistability, TwoStableStatesAndTheFlatCusp) {
  const int n = 4;
  const double b = to_radians(5.0), th0 = to_radians(60.0);
  const auto r = waterbomb::split_fold_bistability(n, b, th0, 1.0, 1.0);
  const auto stable = r.stable_states();
  ASSERT_EQ(stable.size(), 2u);
  // State 1 is the rest state (V = 0).
  EXPECT_NEAR(stable[0].path.theta, th0, 1e-9);
  EXPECT_LE(stable[0].path.energy, 1e-20);
  EXPECT_GT(stable[1].path.theta, kPi / 2);
  EXPECT_GT(stable[1].path.energy, 0.0);
  EXPECT_GT(stable[1].min_reduced_eigenvalue, 0.0);
  bool cusp = false;
  for (const auto& e : r.equilibria) cusp = cusp || (e.path.kind == EquilibriumKind::kCuspMaximum);
  EXPECT_TRUE(cusp);
  ASSERT_EQ(r.symmetric_path_barriers().size(), 2u);
  for (const auto& bar : r.symmetric_path_barriers()) EXPECT_GT(bar.height, 0.0);

  // Independent: the unsymmetric minimiser on the same 16-crease vertex, from a perturbed
  // start on the far side of flat, reaches the same state 2.
  const CreasePattern p = waterbomb::split_fold_base(n, b);
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  auto per_edge = [&](waterbomb::FoldPair g) {
    Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
    for (int i = 0; i < 4 * n; ++i) rho[i] = (i % 4 < 2) ? g.gamma_v : g.gamma_m;
    return rho;
  };
  Eigen::VectorXd k = Eigen::VectorXd::Zero(p.num_edges());
  k.head(4 * n).setOnes();
  const CreaseSprings springs = make_crease_springs(p, k, per_edge(r.springs.rest));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  Eigen::VectorXd x0 = sys.unknowns_from_edges(per_edge(waterbomb::split_fold_angles_printed(n, b, to_radians(120.0))));
  for (Eigen::Index i = 0; i < x0.size(); ++i) x0[i] += u(rng);
  const Equilibrium eq = find_equilibrium(sys, topo, springs, x0);
  ASSERT_TRUE(eq.converged) << eq.message;
  EXPECT_NEAR(eq.edge_angles[0], stable[1].path.angles.gamma_v, 1e-9);
  EXPECT_NEAR(eq.edge_angles[2], stable[1].path.angles.gamma_m, 1e-9);
  EXPECT_NEAR(eq.energy, stable[1].path.energy, 1e-9 * eq.energy);
  RecordProperty("split_n4_b5_state2_theta_deg", std::to_string(to_degrees(stable[1].path.theta)));
}

// With equal stiffnesses the equilibria do not depend on k (seed 004 claim).
TEST(WaterbombSplitFoldBistability, EqualStiffnessScaleFree) {
  const double b = to_radians(5.0), th0 = to_radians(55.0);
  const auto a = waterbomb::split_fold_bistability(3, b, th0, 1.0, 1.0).stable_states();
  const auto c = waterbomb::split_fold_bistability(3, b, th0, 37.0, 37.0).stable_states();
  ASSERT_EQ(a.size(), c.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].path.theta, c[i].path.theta, 1e-9);
    EXPECT_NEAR(37.0 * a[i].path.energy, c[i].path.energy, 1e-9 * std::max(1.0, c[i].path.energy));
  }
}

// b -> 0: the split fold tends to the plain waterbomb with every fold halved, so its
// equilibria tend to the plain base's (closed forms, waterbomb_bistability) and its energy
// to half of it.
TEST(WaterbombSplitFoldBistability, SmallSplitTendsToThePlainBase) {
  const int n = 4;
  const double th0 = to_radians(60.0);
  const auto plain = waterbomb::waterbomb_bistability(n, th0, 1.0, 1.0).stable_states();
  ASSERT_EQ(plain.size(), 2u);
  double previous = INFINITY;
  for (double bdeg : {1.0, 0.1, 0.01}) {
    const auto split = waterbomb::split_fold_bistability(n, to_radians(bdeg), th0, 1.0, 1.0).stable_states();
    ASSERT_EQ(split.size(), 2u) << bdeg;
    const double gap = std::fabs(split[1].path.theta - plain[1].path.theta);
    EXPECT_LT(gap, previous) << bdeg;  // converges as b shrinks
    previous = gap;
    EXPECT_NEAR(split[1].path.energy / plain[1].path.energy, 0.5, 0.05) << bdeg;
  }
  EXPECT_LT(previous, 1e-3);
}

// Split folds lower the energy: state 2's energy and the flat barrier of the SFWB are below
// the plain base's of the same n and theta0 (seed 004 ch. 3).
TEST(WaterbombSplitFoldBistability, SplitFoldsLowerTheEnergy) {
  for (int n : {3, 4, 6}) {
    const double th0 = to_radians(55.0);
    const auto plain = waterbomb::waterbomb_bistability(n, th0, 1.0, 1.0);
    const auto split = waterbomb::split_fold_bistability(n, to_radians(5.0), th0, 1.0, 1.0);
    ASSERT_EQ(plain.stable_states().size(), 2u);
    ASSERT_EQ(split.stable_states().size(), 2u);
    EXPECT_LT(split.stable_states()[1].path.energy, plain.stable_states()[1].path.energy) << n;
    EXPECT_LT(split.symmetric_path_barriers()[0].height, plain.symmetric_path_barriers()[0].height) << n;
  }
}

TEST(WaterbombSplitFoldBistability, BadInputNamesThePlace) {
  auto place = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.place();
    }
    return std::string("no error");
  };
  EXPECT_EQ(place([] { waterbomb::split_fold_bistability(4, to_radians(45.0), 1.0, 1, 1); }), "b");
  EXPECT_EQ(place([] { waterbomb::split_fold_bistability(4, 0.0, 1.0, 1, 1); }), "b");
  EXPECT_EQ(place([] { waterbomb::split_fold_bistability(2, 0.01, 1.0, 1, 1); }), "n");
  EXPECT_EQ(place([] { waterbomb::split_fold_bistability(4, to_radians(20.0), to_radians(5.0), 1, 1); }), "theta0");
  EXPECT_EQ(place([] { waterbomb::split_fold_bistability(4, to_radians(5.0), 1.0, -1, 1); }), "k_m");
  EXPECT_EQ(place([] { waterbomb::split_fold_curve(4, to_radians(5.0), 1.0, 1, 1, 2); }), "samples");
}

// The curve: the general model's reaction force equals dV/dh of the printed energy, it pushes
// (F > 0) between the rest state and flat, and V(theta) matches the energy at state 2.
TEST(WaterbombSplitFoldBistability, CurveCheckedOnTheGeneralModel) {
  const int n = 4;
  const double b = to_radians(5.0), th0 = to_radians(60.0);
  const auto c = waterbomb::split_fold_curve(n, b, th0, 1.0, 1.0, 61);
  EXPECT_EQ(c.unchecked, 0);
  double worst = 0.0;
  for (const auto& s : c.samples) {
    if (!s.checked) continue;
    worst = std::max(worst, std::fabs(s.force - s.force_closed_form) / std::max(1.0, std::fabs(s.force)));
    if (s.theta > th0 + 1e-6 && s.theta < kPi / 2) {
      EXPECT_GT(s.force, 0.0) << to_degrees(s.theta);
    }
    if (s.theta < th0 - 1e-6) {
      EXPECT_LT(s.force, 0.0) << to_degrees(s.theta);
    }
  }
  RecordProperty("split_curve_worst_force_gap", std::to_string(worst));
}

}}  // namespace
}  // namespace rigidfold

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// Switching force of the split fold: as b -> 0 it tends to half the plain base's on a base
// with unit valley creases (every fold halved: V_SF -> V_WB / 2; r = cos(b/2) -> 1), and it is
// the largest push: no sampled general-model force between theta0 and flat exceeds it.
TEST(WaterbombSplitFoldBistability, SwitchingForceTendsToHalfThePlainBase) {
  for (int n : {3, 4, 6})
    for (double t0deg : {50.0, 70.0}) {
      const double th0 = to_radians(t0deg);
      const double plain = waterbomb::switching_force(waterbomb::springs_at_rest_theta(n, th0, 1.0, 1.0), th0, 1.0).force;
      double previous = INFINITY;
      for (double bdeg : {0.5, 0.05, 0.005}) {
        const auto sw = waterbomb::split_fold_switching_force(n, to_radians(bdeg), th0, 1.0, 1.0);
        const double gap = std::fabs(sw.force / (plain / 2) - 1.0);
        EXPECT_LT(gap, previous) << n << " " << t0deg << " " << bdeg;
        previous = gap;
      }
      EXPECT_LT(previous, 1e-3) << n << " " << t0deg;
    }
  const auto sw = waterbomb::split_fold_switching_force(4, to_radians(5.0), to_radians(60.0), 2.0, 1.0);
  const auto curve = waterbomb::split_fold_curve(4, to_radians(5.0), to_radians(60.0), 2.0, 1.0, 101);
  for (const auto& s : curve.samples) {
    if (s.checked && s.theta > to_radians(60.0) && s.theta < kPi / 2) {
      EXPECT_LE(s.force, sw.force * (1 + 1e-9)) << to_degrees(s.theta);
    }
  }
  EXPECT_THROW(waterbomb::split_fold_switching_force(4, to_radians(5.0), to_radians(100.0), 1.0, 1.0), InputError);
}

}}  // namespace
}  // namespace rigidfold
