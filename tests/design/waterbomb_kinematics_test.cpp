// Closed-form waterbomb kinematics (design/waterbomb/waterbomb_kinematics.hpp) against the
// seed's printed forms, against the kernel's loop closure, and against the general solver.
#include <gtest/gtest.h>

#include <cmath>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/support/input_error_place.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using waterbomb::FoldPair;

double closure(int n, FoldPair g) {
  std::vector<double> sectors(2 * n, kPi / n), rho(2 * n);
  for (int i = 0; i < 2 * n; ++i) rho[i] = i % 2 == 0 ? g.gamma_v : g.gamma_m;
  return vertex_closure_residual(sectors, rho).norm();
}

// The stable forms close the vertex loop over the whole range, including within 1e-9 rad of
// flat and of both contact limits (where the printed acos forms lose digits).
TEST(WaterbombKinematics, ClosesTheLoopEverywhere) {
  for (int n : {3, 4, 5, 6, 10, 24}) {
    const double lim = waterbomb::theta_limit(n);
    std::vector<double> thetas = {0.0, 1e-9, 1e-4, kPi / 2 - 1e-9, kPi / 2, kPi / 2 + 1e-9, lim - 1e-9, lim};
    for (int i = 1; i < 40; ++i) thetas.push_back(lim * i / 40);
    for (double th : thetas) {
      const FoldPair g = waterbomb::waterbomb_fold_angles(n, th);
      // Bound: the rounding of the 2n-rotation loop product itself, ~4 ulp per rotation.
      EXPECT_LE(closure(n, g), 8 * n * 2.2e-16) << "n " << n << " theta " << th;
      EXPECT_LE(g.gamma_m, 0.0);
      EXPECT_GE(g.gamma_v, 0.0);
    }
    // Ends: theta = 0 -> (-pi, pi - 2pi/n); theta = pi - pi/n -> valleys at pi; flat at pi/2.
    const FoldPair g0 = waterbomb::waterbomb_fold_angles(n, 0.0);
    EXPECT_NEAR(g0.gamma_m, -kPi, 1e-15);
    EXPECT_NEAR(g0.gamma_v, kPi - 2 * kPi / n, 1e-14);
    EXPECT_NEAR(waterbomb::waterbomb_fold_angles(n, lim).gamma_v, kPi, 1e-14);
    const FoldPair gf = waterbomb::waterbomb_fold_angles(n, kPi / 2);
    EXPECT_NEAR(gf.gamma_m, 0.0, 1e-15);
    EXPECT_NEAR(gf.gamma_v, 0.0, 1e-15);
  }
}

// The printed seed forms (2.6)-(2.8) for n = 4 and (3.4)-(3.6) for any n agree with the
// stable forms away from where their acos/asin arguments approach +-1 (none was found wrong).
TEST(WaterbombKinematics, AgreesWithSeedPrintedForms) {
  for (double deg = 5.0; deg <= 130.0; deg += 2.5) {
    if (std::fabs(deg - 90.0) < 1.0) continue;
    const double th = to_radians(deg);
    const FoldPair s = waterbomb::waterbomb_fold_angles(4, th);
    const FoldPair t = waterbomb::seed_traditional_fold_angles(th);
    EXPECT_NEAR(t.gamma_m, s.gamma_m, 1e-9) << deg;
    EXPECT_NEAR(t.gamma_v, s.gamma_v, 1e-9) << deg;
  }
  for (int n : {3, 4, 6, 10}) {
    const double lim = to_degrees(waterbomb::theta_limit(n));
    for (double deg = 5.0; deg <= lim - 5.0; deg += 2.5) {
      if (std::fabs(deg - 90.0) < 1.0) continue;
      const FoldPair s = waterbomb::waterbomb_fold_angles(n, to_radians(deg));
      const FoldPair p = waterbomb::seed_general_fold_angles(n, to_radians(deg));
      EXPECT_NEAR(p.gamma_m, s.gamma_m, 1e-9) << n << " " << deg;
      EXPECT_NEAR(p.gamma_v, s.gamma_v, 1e-9) << n << " " << deg;
    }
  }
}

// Derivatives: central differences of the closed form, the printed (3.11)/(3.12), and the
// one-sided slopes at flat, -2 tan(45 - a/2) and +2 cot(45 - a/2).
TEST(WaterbombKinematics, DerivativesMatchDifferencesAndSeed311) {
  for (int n : {3, 4, 7}) {
    const double lim = waterbomb::theta_limit(n);
    for (int i = 1; i < 30; ++i) {
      const double th = lim * i / 30;
      if (std::fabs(th - kPi / 2) < 0.02) continue;
      const double h = 1e-6;
      const FoldPair d = waterbomb::waterbomb_fold_angle_derivatives(n, th);
      const FoldPair a = waterbomb::waterbomb_fold_angles(n, th + h), b = waterbomb::waterbomb_fold_angles(n, th - h);
      EXPECT_NEAR(d.gamma_m, (a.gamma_m - b.gamma_m) / (2 * h), 1e-7);
      EXPECT_NEAR(d.gamma_v, (a.gamma_v - b.gamma_v) / (2 * h), 1e-7);
      EXPECT_NEAR(d.gamma_v, waterbomb::seed_gamma_v_derivative(n, th), 1e-9) << n << " " << th;
    }
    const double al = kPi / n;
    EXPECT_NEAR(waterbomb::waterbomb_fold_angle_derivatives(n, kPi / 2, -1).gamma_v, -2 * std::tan(kPi / 4 - al / 2), 1e-14);
    EXPECT_NEAR(waterbomb::waterbomb_fold_angle_derivatives(n, kPi / 2, +1).gamma_v, 2 / std::tan(kPi / 4 - al / 2), 1e-14);
    EXPECT_EQ(waterbomb::waterbomb_fold_angle_derivatives(n, kPi / 2, -1).gamma_m, 2.0);
    EXPECT_EQ(waterbomb::waterbomb_fold_angle_derivatives(n, kPi / 2, +1).gamma_m, -2.0);
  }
}

// Independent computation: the general corrector on the generated base with the symmetry
// imposed as equality rows (every M equal to crease 1, every V to crease 0) and the
// mountains held at gamma_m gives the closed-form gamma_v on both sides of flat.
TEST(WaterbombKinematics, AgreesWithGeneralSolver) {
  for (int n : {3, 4, 6}) {
    generators::WaterbombParams wp;
    wp.n = n;
    const CreasePattern p = generators::waterbomb_base(wp);
    const Topology topo = build_topology(p);
    for (double deg : {30.0, 70.0, 100.0, 120.0}) {
      if (deg >= to_degrees(waterbomb::theta_limit(n)) - 1) continue;
      const FoldPair want = waterbomb::waterbomb_fold_angles(n, to_radians(deg));
      ClosureOptions opt;
      for (int e = 0; e < 2 * n; ++e) {
        if (p.assignments[e] == Assignment::Mountain) opt.fixed.push_back({e, want.gamma_m});
        else if (e != 0) opt.equalities.push_back({e, 0, 1.0});
      }
      const ClosureSystem sys(p, topo, opt);
      ASSERT_EQ(sys.num_unknowns(), n);
      // Start 0.05 rad off on the same side (both sides share gamma_m: the branch is picked by the start).
      Eigen::VectorXd edges = Eigen::VectorXd::Zero(p.num_edges());
      for (int e = 0; e < 2 * n; e += 2) edges[e] = want.gamma_v + 0.05;
      // Closed to round-off (the default 1e-12 rad residual leaves ~2e-12 rad in the angle at
      // n = 3, whose residual-to-angle gain is > 1 there).
      NewtonOptions no;
      no.tolerance = 1e-15;
      const NewtonResult r = newton_project(sys, sys.unknowns_from_edges(edges), no);
      ASSERT_TRUE(r.converged);
      const Eigen::VectorXd got = sys.edges_from_unknowns(r.x);
      for (int e = 0; e < 2 * n; e += 2) EXPECT_NEAR(got[e], want.gamma_v, 1e-12) << n << " " << deg;
    }
  }
}

TEST(WaterbombKinematics, ValidityLimitsAreReported) {
  auto place_of = [](auto&& f) { return test::input_error_place(f); };
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_fold_angles(4, -1e-12); }), "theta");
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_fold_angles(4, waterbomb::theta_limit(4) + 1e-12); }), "theta");
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_fold_angles(4, NAN); }), "theta");
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_fold_angles(2, 1.0); }), "n");
  EXPECT_NEAR(waterbomb::theta_limit(4), to_radians(135.0), 1e-15);
}

}}  // namespace
}  // namespace rigidfold
