// Rest-angle design (design/waterbomb/waterbomb_rest_design.hpp): the theta0 that puts the
// second stable state at a target, checked forward with the independent bistability analysis
// (path equilibria confirmed on the unsymmetric 2n-crease model) to 1e-9 rad.
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_rest_design.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// The stable state past flat of the forward analysis.
double state2(int n, double theta0, double k_m, double k_v) {
  const auto r = waterbomb::waterbomb_bistability(n, theta0, k_m, k_v);
  for (const auto& s : r.stable_states())
    if (s.path.theta > kPi / 2) return s.path.theta;
  return NAN;
}

// Forward then back: the state 2 of a known rest angle, designed for, gives that rest angle
// back; and the designed rest angle, analysed forward, puts state 2 at the target.
TEST(WaterbombRestDesign, RoundTripThroughTheForwardAnalysis) {
  for (int n : {3, 4, 6, 10})
    for (double t0deg : {45.0, 60.0, 75.0})
      for (double ratio : {0.5, 1.0, 2.5}) {
        const double theta0 = to_radians(t0deg);
        const double theta2 = state2(n, theta0, ratio, 1.0);
        ASSERT_TRUE(std::isfinite(theta2)) << n << " " << t0deg << " " << ratio;
        const auto d = waterbomb::rest_angle_for_state2(n, theta2, ratio, 1.0);
        EXPECT_NEAR(d.theta0, theta0, 1e-9) << n << " " << t0deg << " " << ratio;
        EXPECT_GT(d.curvature, 0.0);
        EXPECT_NEAR(state2(n, d.theta0, ratio, 1.0), theta2, 1e-9) << n << " " << t0deg << " " << ratio;
      }
}

// A target chosen directly (not from a forward run), checked forward; equal stiffnesses of
// any size give the same rest angle (only the ratio matters).
TEST(WaterbombRestDesign, ChosenTargetIsReachedForward) {
  for (double t2deg : {95.0, 100.0, 110.0}) {
    const double theta2 = to_radians(t2deg);
    const auto d = waterbomb::rest_angle_for_state2(4, theta2, 1.0, 1.0);
    EXPECT_LT(d.theta0, kPi / 2);
    EXPECT_NEAR(state2(4, d.theta0, 1.0, 1.0), theta2, 1e-9) << t2deg;
    EXPECT_NEAR(waterbomb::rest_angle_for_state2(4, theta2, 40.0, 40.0).theta0, d.theta0, 1e-12);
  }
  // k_v = 0: only the mountains count and gamma_m(theta) = gamma_m(pi - theta): theta0 = pi - theta2.
  const auto m = waterbomb::rest_angle_for_state2(5, to_radians(120.0), 1.0, 0.0);
  EXPECT_NEAR(m.theta0, kPi - to_radians(120.0), 1e-12);
}

TEST(WaterbombRestDesign, BadInputAndNoAnswer) {
  auto place = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return e.place();
    }
    return std::string("no error");
  };
  EXPECT_EQ(place([] { waterbomb::rest_angle_for_state2(4, to_radians(90.0), 1, 1); }), "theta2");
  EXPECT_EQ(place([] { waterbomb::rest_angle_for_state2(4, to_radians(135.0), 1, 1); }), "theta2");
  EXPECT_EQ(place([] { waterbomb::rest_angle_for_state2(4, NAN, 1, 1); }), "theta2");
  EXPECT_EQ(place([] { waterbomb::rest_angle_for_state2(2, 2.0, 1, 1); }), "n");
  EXPECT_EQ(place([] { waterbomb::rest_angle_for_state2(4, 2.0, -1, 1); }), "k_m");
  EXPECT_EQ(place([] { waterbomb::rest_angle_for_state2(4, 2.0, 0, 0); }), "k_m");
  // Valleys only, target near the valley limit: gamma_v there exceeds gamma_v(0) = 180 - 360/n,
  // so no rest angle pulls the valleys far enough.
  EXPECT_THROW(waterbomb::rest_angle_for_state2(4, to_radians(134.0), 0.0, 1.0), NoAnswerError);
}

}}  // namespace
}  // namespace rigidfold

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// The rest angle for a target switching force: forward from known rest angles and back, the
// designed angle's switching force on the general model equal to the target to 1e-9, and the
// switching force falling as theta0 rises (the monotonicity the solver relies on).
TEST(WaterbombRestDesign, RestAngleForSwitchingForceRoundTrip) {
  for (int n : {3, 4, 8})
    for (double ratio : {0.5, 2.0}) {
      const double r = std::cos(kPi / n);
      double previous = INFINITY;
      for (double t0deg : {20.0, 45.0, 70.0, 85.0}) {
        const double theta0 = to_radians(t0deg);
        const double force = waterbomb::switching_force(waterbomb::springs_at_rest_theta(n, theta0, ratio, 1.0), theta0, r).force;
        EXPECT_LT(force, previous) << n << " " << t0deg;
        previous = force;
        const double designed = waterbomb::rest_angle_for_switching_force(n, force, ratio, 1.0, r);
        EXPECT_NEAR(designed, theta0, 1e-9) << n << " " << ratio << " " << t0deg;
        const auto checked = waterbomb::switching_force_checked(n, designed, ratio, 1.0);
        EXPECT_NEAR(checked.force, force, 1e-9 * force);
      }
    }
  const double r = std::cos(kPi / 4);
  const double top = waterbomb::switching_force(waterbomb::springs_at_rest_theta(4, 0.0, 1.0, 1.0), 0.0, r).force;
  EXPECT_THROW(waterbomb::rest_angle_for_switching_force(4, 1.01 * top, 1.0, 1.0, r), NoAnswerError);
  EXPECT_THROW(waterbomb::rest_angle_for_switching_force(4, -1.0, 1.0, 1.0, r), InputError);
  EXPECT_THROW(waterbomb::rest_angle_for_switching_force(4, NAN, 1.0, 1.0, r), InputError);
}

}}  // namespace
}  // namespace rigidfold
