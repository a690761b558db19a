// Seed 004's bistability claims on the closed-form path, each equilibrium checked on the
// unrestricted 2n-crease problem (design/waterbomb/waterbomb_bistability.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/support/input_error_place.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using waterbomb::EquilibriumKind;

const waterbomb::CheckedEquilibrium* far_state(const std::vector<waterbomb::CheckedEquilibrium>& s) {
  for (const auto& e : s)
    if (e.path.theta > kPi / 2) return &e;
  return nullptr;
}

// Fig 2.9 (n = 4, theta0 = 60 deg): state 1 at theta0 with zero energy, the flat cusp as the
// barrier between them, state 2 on the far side; V(flat) = (n/2)(k gm0^2 + k gv0^2).
TEST(WaterbombBistability, Fig29Landscape) {
  const auto r = waterbomb::waterbomb_bistability(4, to_radians(60.0), 1.0, 1.0);
  const auto stable = r.stable_states();
  ASSERT_EQ(stable.size(), 2u);
  EXPECT_NEAR(stable[0].path.theta, to_radians(60.0), 1e-12);
  EXPECT_LT(stable[0].path.energy, 1e-24);
  EXPECT_GT(stable[1].path.theta, kPi / 2);
  EXPECT_GT(stable[1].path.energy, 0.0);
  // The two stable states are not mirror images (seed 004 claim).
  EXPECT_GT(std::fabs(stable[1].path.angles.gamma_m + stable[0].path.angles.gamma_v), 0.1);
  bool cusp = false;
  for (const auto& e : r.equilibria)
    if (e.path.kind == EquilibriumKind::kCuspMaximum) {
      cusp = true;
      EXPECT_EQ(e.path.theta, kPi / 2);
      const auto g0 = r.springs.rest;
      EXPECT_NEAR(e.path.energy, 2.0 * (g0.gamma_m * g0.gamma_m + g0.gamma_v * g0.gamma_v), 1e-14);
      EXPECT_GT(e.path.slope_below, 0.0);
      EXPECT_LT(e.path.slope_above, 0.0);
      EXPECT_GT(e.path.energy, stable[1].path.energy);
    }
  EXPECT_TRUE(cusp);
  for (const auto& e : stable) {
    EXPECT_LE(e.closure_residual, 1e-12);
    EXPECT_GT(e.min_reduced_eigenvalue, 0.0);
  }
}

// With equal stiffnesses the equilibria do not depend on k; energies scale with k.
TEST(WaterbombBistability, EqualStiffnessEquilibriaIndependentOfK) {
  for (int n : {3, 4, 6}) {
    const auto a = waterbomb::waterbomb_bistability(n, to_radians(55.0), 1.0, 1.0).stable_states();
    const auto b = waterbomb::waterbomb_bistability(n, to_radians(55.0), 0.00455, 0.00455).stable_states();
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), 2u);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(a[i].path.theta, b[i].path.theta, 1e-12) << n;
      if (a[i].path.energy > 0) {
        EXPECT_NEAR(b[i].path.energy / a[i].path.energy, 0.00455, 1e-9 * 0.00455);
      }
    }
    // Unequal stiffnesses do move state 2 (the claim is about equal k only).
    const auto c = waterbomb::waterbomb_bistability(n, to_radians(55.0), 2.0, 1.0).stable_states();
    ASSERT_NE(far_state(c), nullptr);
    EXPECT_GT(std::fabs(far_state(c)->path.theta - far_state(a)->path.theta), 1e-3);
  }
}

// Lower n puts state 2 nearer the flat state (seed 004 ch. 3).
TEST(WaterbombBistability, LowerDegreeLiesNearerFlat) {
  double previous = 0.0;
  for (int n : {3, 4, 5, 6, 8, 10}) {
    const auto s = waterbomb::waterbomb_bistability(n, to_radians(60.0), 1.0, 1.0).stable_states();
    const auto* f = far_state(s);
    ASSERT_NE(f, nullptr) << n;
    const double distance = f->path.theta - kPi / 2;
    EXPECT_GT(distance, previous) << n;
    previous = distance;
  }
}

// Every minimum found with symmetry imposed is a minimum of the unrestricted problem: a KKT
// point with positive definite reduced Hessian on the 2n - 3 dimensional tangent space.
TEST(WaterbombBistability, SymmetricMinimaAreUnrestrictedMinima) {
  int checked = 0;
  for (int n : {3, 4, 5, 6, 8})
    for (double deg : {40.0, 60.0, 75.0})
      for (double ratio : {0.5, 1.0, 2.0}) {
        const auto r = waterbomb::waterbomb_bistability(n, to_radians(deg), ratio, 1.0);
        for (const auto& e : r.equilibria) {
          if (e.path.kind != EquilibriumKind::kMinimum || e.path.at_validity_limit) continue;
          EXPECT_TRUE(e.stable_unrestricted) << n << " " << deg << " " << ratio << " theta " << e.path.theta;
          EXPECT_GT(e.min_reduced_eigenvalue, 0.0);
          EXPECT_LE(e.stationarity_residual, 1e-10 * std::max(ratio, 1.0));
          ++checked;
        }
      }
  EXPECT_GE(checked, 2 * 5 * 3 * 3 - 5);  // nearly every case is bistable
}

// Seed 004 Table 2.2, predicted row: the rest state (-76, 32) deg is theta0 = 52 deg; the
// joints have the Table 2.1 stiffness (equal k). The seed reads state 2 off its energy plot
// as (-24, 57) deg; the digest (section 3, note 3) accepts +-1 deg in gamma_m1 (theta read to
// +-0.5 deg, gamma_m' = -2) and +-2 deg in gamma_v1.
TEST(WaterbombBistability, Table22PredictedStates) {
  const double k = flexure_stiffness(93e9, 50e-3, 0.02032e-3, 0.714e-3);
  const auto r = waterbomb::waterbomb_bistability(4, to_radians(52.0), k, k);
  EXPECT_NEAR(to_degrees(r.springs.rest.gamma_m), -76.0, 1e-12);
  EXPECT_NEAR(to_degrees(r.springs.rest.gamma_v), 32.0, 0.5);
  const auto stable = r.stable_states();
  ASSERT_EQ(stable.size(), 2u);
  EXPECT_NEAR(to_degrees(stable[1].path.angles.gamma_m), -24.0, 1.0);
  EXPECT_NEAR(to_degrees(stable[1].path.angles.gamma_v), 57.0, 2.0);
  EXPECT_GT(stable[1].min_reduced_eigenvalue, 0.0);
}

TEST(WaterbombBistability, BadInputNamesTheParameter) {
  auto place_of = [](auto&& f) { return test::input_error_place(f); };
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_bistability(2, 1.0, 1, 1); }), "n");
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_bistability(4, 3.0, 1, 1); }), "theta0");
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_bistability(4, 1.0, -1, 1); }), "k_m");
  EXPECT_EQ(place_of([] { waterbomb::waterbomb_bistability(4, 1.0, 1, NAN); }), "k_v");
}

}}  // namespace
}  // namespace rigidfold
