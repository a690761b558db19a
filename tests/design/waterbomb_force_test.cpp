// Waterbomb force-deflection by virtual work (design/waterbomb/waterbomb_force.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/waterbomb_force.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// F = dV/d(delta): against a central difference of V in the deflection, on both sides of flat.
TEST(WaterbombForce, IsTheEnergySlopeInDeflection) {
  for (int n : {3, 4, 6}) {
    const auto s = waterbomb::springs_at_rest_theta(n, to_radians(55.0), 1.3, 0.7);
    const double r = 0.071, th0 = to_radians(55.0);
    for (double deg : {40.0, 70.0, 85.0, 95.0, 110.0}) {
      const double th = to_radians(deg);
      const auto f = waterbomb::waterbomb_force(s, th0, r, th);
      const double h = 1e-6;
      const double dV = waterbomb::waterbomb_energy(s, th + h) - waterbomb::waterbomb_energy(s, th - h);
      const double dd = r * (std::cos(th - h) - std::cos(th + h));
      EXPECT_NEAR(f.force, dV / dd, 1e-6 * std::max(1.0, std::fabs(f.force))) << n << " " << deg;
      EXPECT_NEAR(f.deflection, r * (std::cos(th0) - std::cos(th)), 1e-15);
    }
    EXPECT_NEAR(waterbomb::waterbomb_force(s, th0, r, th0).force, 0.0, 1e-12);
  }
}

// The snap thresholds at flat equal the digest's closed forms (section 2.6):
//   F(90-) r/n = 2 k_m |gm0| + 2 k_v tan(45 - a/2) gv0,  F(90+) r/n = -[2 k_m |gm0| + 2 k_v cot(45 - a/2) gv0].
TEST(WaterbombForce, SnapThresholdsAtFlat) {
  for (int n : {3, 4, 10}) {
    const double km = 2.0, kv = 0.5, r = 1.7, a = kPi / n;
    const auto s = waterbomb::springs_at_rest_theta(n, to_radians(60.0), km, kv);
    const double gm0 = s.rest.gamma_m, gv0 = s.rest.gamma_v;
    const double below = waterbomb::waterbomb_force(s, to_radians(60.0), r, kPi / 2, -1).force;
    const double above = waterbomb::waterbomb_force(s, to_radians(60.0), r, kPi / 2, +1).force;
    EXPECT_NEAR(below * r / n, 2 * km * std::fabs(gm0) + 2 * kv * std::tan(kPi / 4 - a / 2) * gv0, 1e-13);
    EXPECT_NEAR(above * r / n, -(2 * km * std::fabs(gm0) + 2 * kv / std::tan(kPi / 4 - a / 2) * gv0), 1e-13);
    EXPECT_GT(below, 0.0);
    EXPECT_LT(above, 0.0);
  }
  const auto s = waterbomb::springs_at_rest_theta(4, 1.0, 1, 1);
  EXPECT_THROW(waterbomb::waterbomb_force(s, 1.0, -1.0, 1.2), InputError);
  EXPECT_THROW(waterbomb::waterbomb_force(s, 1.0, 1.0, 0.0), InputError);
}

}}  // namespace
}  // namespace rigidfold
