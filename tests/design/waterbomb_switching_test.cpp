// Switching force of the waterbomb base and the mountain stiffness that sets it
// (design/waterbomb/waterbomb_switching.hpp): the maximum is checked against a dense scan of
// the closed-form force, the design against the forward switching force and against the
// general model's reaction force at the maximum (waterbomb_loaded_path.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/waterbomb_force.hpp"
#include "design/waterbomb/waterbomb_loaded_path.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombSwitching, IsTheLargestPushBeforeFlat) {
  for (auto [n, theta0_deg, k_m] : {std::tuple{4, 60.0, 1.0}, std::tuple{3, 45.0, 0.2}, std::tuple{10, 45.0, 3.0}}) {
    const double theta0 = to_radians(theta0_deg), r = std::cos(kPi / n);
    const auto springs = waterbomb::springs_at_rest_theta(n, theta0, k_m, 1.0);
    const auto sw = waterbomb::switching_force(springs, theta0, r);
    double scan = 0.0;
    for (int i = 1; i <= 20000; ++i) {
      const double th = theta0 + (kPi / 2 - theta0) * i / 20000.0;
      scan = std::max(scan, waterbomb::waterbomb_force(springs, theta0, r, th, i == 20000 ? -1 : 0).force);
    }
    EXPECT_GE(sw.force, scan * (1 - 1e-12)) << n;          // no sampled push is larger
    EXPECT_LE(sw.force, scan * (1 + 1e-6)) << n;           // and the scan comes close to it
    EXPECT_GT(sw.force, 0.0);
    if (sw.at_flat) {
      EXPECT_DOUBLE_EQ(sw.theta, kPi / 2);
    }
  }
}

TEST(WaterbombSwitching, StiffnessForATargetForceIsCheckedForwardAndOnTheGeneralModel) {
  const int n = 4;
  const double theta0 = to_radians(60.0), r = std::cos(kPi / n);
  const double base = waterbomb::switching_force(waterbomb::springs_at_rest_theta(n, theta0, 1.0, 1.0), theta0, r).force;
  const double target = 1.5 * base;
  const double k_m = waterbomb::mountain_stiffness_for_switching_force(n, theta0, 1.0, target, r);
  EXPECT_GT(k_m, 1.0);  // a stiffer mountain switches later
  const auto sw = waterbomb::switching_force(waterbomb::springs_at_rest_theta(n, theta0, k_m, 1.0), theta0, r);
  EXPECT_NEAR(sw.force, target, 1e-10 * target);
  // The general model's reaction force near the maximum (the flat corner is singular: just
  // before it) agrees with the closed form there.
  const double th = sw.at_flat ? kPi / 2 - 1e-4 : sw.theta;
  const auto loaded = waterbomb::waterbomb_loaded_path(n, theta0, k_m, 1.0, {th});
  ASSERT_TRUE(loaded.points[0].converged);
  EXPECT_NEAR(loaded.points[0].force, loaded.points[0].force_closed_form, 1e-9 * target);
  EXPECT_NEAR(loaded.points[0].force, target, 1e-2 * target);  // 1e-4 rad before the corner
  const auto checked = waterbomb::switching_force_checked(n, theta0, k_m, 1.0);
  EXPECT_NEAR(checked.force, target, 1e-10 * target);
  EXPECT_LE(checked.general_gap, 1e-9 * target);
  EXPECT_NEAR(checked.general_force, target, 1e-2 * target);  // 1e-4 rad before the corner
}

TEST(WaterbombSwitching, RefusesWhatNoStiffnessCanDo) {
  const int n = 4;
  const double theta0 = to_radians(60.0), r = std::cos(kPi / n);
  const double at_zero = waterbomb::switching_force(waterbomb::springs_at_rest_theta(n, theta0, 0.0, 1.0), theta0, r).force;
  EXPECT_THROW(waterbomb::mountain_stiffness_for_switching_force(n, theta0, 1.0, 0.5 * at_zero, r), NoAnswerError);
  EXPECT_THROW(waterbomb::mountain_stiffness_for_switching_force(n, theta0, 1.0, -1.0, r), InputError);
  EXPECT_THROW(waterbomb::switching_force(waterbomb::springs_at_rest_theta(n, to_radians(100.0), 1.0, 1.0), to_radians(100.0), r),
               InputError);
}

}}  // namespace
}  // namespace rigidfold
