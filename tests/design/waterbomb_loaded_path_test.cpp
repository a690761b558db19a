// The waterbomb under displacement control on the general model (design/waterbomb/
// waterbomb_loaded_path.hpp): reaction force = virtual work along the whole path, and the
// stability changes of the loaded symmetric state located.
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/waterbomb_loaded_path.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/sanitized.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombLoadedPath, ForceMatchesVirtualWorkAndStabilityChangesAreLocated) {
  std::vector<double> thetas;
  for (double deg = 20.0; deg <= 130.0; deg += 5.0)
    if (deg != 90.0) thetas.push_back(to_radians(deg));
  const auto path = waterbomb::waterbomb_loaded_path(4, to_radians(60.0), 1.0, 1.0, thetas);
  ASSERT_EQ(path.points.size(), thetas.size());
  for (const auto& q : path.points) {
    ASSERT_TRUE(q.converged) << to_degrees(q.theta);
    EXPECT_NEAR(q.force, q.force_closed_form, 1e-9 * std::max(1.0, std::fabs(q.force_closed_form))) << to_degrees(q.theta);
    EXPECT_LT(q.fold_angle_gap, 1e-9);
    if (q.theta < kPi / 2) {
      EXPECT_TRUE(q.stable) << to_degrees(q.theta);  // the push toward flat stays symmetric
    }
  }
  // Every located change sits between points of opposite stability and is a zero of the
  // smallest eigenvalue: just either side of it the signs differ.
  ASSERT_FALSE(path.stability_changes.empty());
  for (std::size_t i = 0; i < path.stability_changes.size(); ++i) {
    const double tc = path.stability_changes[i];
    EXPECT_GT(tc, kPi / 2);
    const auto near = waterbomb::waterbomb_loaded_path(4, to_radians(60.0), 1.0, 1.0, {tc - 1e-6, tc + 1e-6});
    EXPECT_NE(near.points[0].min_eigenvalue > 0.0, near.points[1].min_eigenvalue > 0.0) << to_degrees(tc);
    RecordProperty("stability_change_deg_" + std::to_string(i), std::to_string(to_degrees(tc)));
  }
}

// Next to the far limit (theta -> 180 - 180/n) the height flattens (dh/dtheta = -r sin theta):
// the continuation's predictor is a secant in acos(h / r), with hidden steps bounded in it, so
// the sample 1e-3 of the range from the limit is reached and lands on the closed form (a
// secant in h overshot there and the n = 60 curve stopped before it). n = 60 costs ~4 s in
// Release and 480 s under AddressSanitizer, which runs n = 12 (the same path, 33 ms in Release).
TEST(WaterbombLoadedPath, ContinuationReachesTheFarLimit) {
  const int n = test::kSlowSanitizedBuild ? 12 : 60;
  const double limit = kPi - kPi / n;
  const double theta = limit - 1e-3 * limit;
  const auto path = waterbomb::waterbomb_loaded_path(n, to_radians(60.0), 1.0, 1.0, {theta});
  ASSERT_FALSE(path.stopped_at_flat) << path.stop_message;
  EXPECT_TRUE(path.stop_message.empty()) << path.stop_message;
  ASSERT_TRUE(path.points[0].converged);
  EXPECT_LE(path.points[0].fold_angle_gap, 1e-9);
  EXPECT_NEAR(path.points[0].force, path.points[0].force_closed_form, 1e-9 * std::max(1.0, std::fabs(path.points[0].force_closed_form)));
}

}}  // namespace
}  // namespace rigidfold
