#pragma once
// Shared by the flat-crossing tests of the plain and the split-fold waterbomb curves: a
// curve whose loaded path stops at the flat state has every sample before flat
// (theta < pi/2) checked against the general model and none after it, and counts the
// latter as unchecked.
#include <gtest/gtest.h>

#include <numbers>

namespace rigidfold::test {

template <class Curve>
void expect_only_the_near_side_checked(const Curve& curve) {
  EXPECT_TRUE(curve.stopped_at_flat);
  int near = 0, far = 0;
  for (const auto& s : curve.samples) {
    if (s.theta < std::numbers::pi / 2) {
      EXPECT_TRUE(s.checked) << "theta " << s.theta;
      ++near;
    } else {
      EXPECT_FALSE(s.checked) << "theta " << s.theta;
      ++far;
    }
  }
  EXPECT_GT(near, 0);
  EXPECT_GT(far, 0);
  EXPECT_EQ(curve.unchecked, far);
}

}  // namespace rigidfold::test
