// The sampled energy and force-deflection curves of the waterbomb base
// (design/waterbomb/waterbomb_curve.hpp): every sample checked on the general model, the force
// equal to the slope of the sampled energy against the deflection (an independent difference
// quotient), the force jump at the flat state, and the stability of the loaded states.
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/waterbomb_curve.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombCurve, ForceIsTheSlopeOfTheEnergyAndJumpsAtTheFlatState) {
  const auto c = waterbomb::waterbomb_curve(4, to_radians(60.0), 1.0, 1.0, 241);
  ASSERT_EQ(c.unchecked, 0);
  ASSERT_GE(c.samples.size(), 240u);
  // The general model's reaction force (Lagrange multipliers) against dV/d(delta) by central
  // differences of the energy and the deflection in theta (step 1e-5 rad: truncation ~1e-9,
  // round-off ~1e-11 relative).
  const auto springs = waterbomb::springs_at_rest_theta(4, to_radians(60.0), 1.0, 1.0);
  const double r = std::cos(kPi / 4), eps = 1e-5;
  auto deflection = [&](double th) { return r * (std::cos(to_radians(60.0)) - std::cos(th)); };
  int compared = 0;
  for (std::size_t i = 0; i < c.samples.size(); ++i) {
    const auto& b = c.samples[i];
    ASSERT_TRUE(b.checked);
    if (i > 0) {
      EXPECT_LT(c.samples[i - 1].theta, b.theta);
    }
    EXPECT_NEAR(b.deflection, deflection(b.theta), 1e-14);
    const double slope = (waterbomb::waterbomb_energy(springs, b.theta + eps) - waterbomb::waterbomb_energy(springs, b.theta - eps)) /
                         (deflection(b.theta + eps) - deflection(b.theta - eps));
    EXPECT_NEAR(b.force, slope, 1e-6 * std::max(1.0, std::fabs(b.force))) << to_degrees(b.theta);
    ++compared;
  }
  EXPECT_GT(compared, 200);
  // Around the flat state the force changes sign: a push just before it (toward the second
  // stable state at 99.04 deg), a pull just after (V falls from the cusp to state 2).
  const waterbomb::CurveSample* below = nullptr;
  const waterbomb::CurveSample* above = nullptr;
  for (const auto& s : c.samples) {
    if (s.theta < kPi / 2) below = &s;
    if (s.theta > kPi / 2 && !above) above = &s;
  }
  ASSERT_TRUE(below && above);
  EXPECT_GT(below->force, 0.0);
  EXPECT_LT(above->force, 0.0);
  // Under displacement control the push toward flat stays symmetric and stable.
  for (const auto& s : c.samples)
    if (s.theta > to_radians(30.0) && s.theta < kPi / 2) {
      EXPECT_TRUE(s.stable) << to_degrees(s.theta);
    }
}

TEST(WaterbombCurve, RefusesBadSampleCounts) {
  for (int k : {2, 0, -5, 2002}) {
    try {
      waterbomb::waterbomb_curve(4, to_radians(60.0), 1.0, 1.0, k);
      ADD_FAILURE() << k;
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), "samples");
    }
  }
}

}}  // namespace
}  // namespace rigidfold
