// Inverse design: the stiffness ratio for a target second stable state
// (design/waterbomb/waterbomb_design.hpp), checked by the forward bistability analysis.
#include <gtest/gtest.h>

#include <cmath>

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_design.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombDesign, RatioPutsStateTwoWhereAsked) {
  int designed = 0;
  for (int n : {3, 4, 6})
    for (double target_deg : {100.0, 105.0, 110.0}) {
      const double th0 = to_radians(60.0), th2 = to_radians(target_deg);
      double ratio;
      try {
        ratio = waterbomb::stiffness_ratio_for_state2(n, th0, th2);
      } catch (const NoAnswerError&) {
        continue;  // no non-negative ratio for this target: allowed, counted below
      }
      ++designed;
      const auto stable = waterbomb::waterbomb_bistability(n, th0, ratio, 1.0).stable_states();
      bool found = false;
      for (const auto& e : stable)
        if (std::fabs(e.path.theta - th2) < 1e-9) {
          found = true;
          EXPECT_GT(e.min_reduced_eigenvalue, 0.0);  // also a minimum of the unsymmetric problem
        }
      EXPECT_TRUE(found) << n << " " << target_deg << " ratio " << ratio;
    }
  EXPECT_GE(designed, 6);
  // Raising k_m / k_v moves state 2 away from flat (seed 004 Fig 2.17, digest 2.5).
  EXPECT_GT(waterbomb::stiffness_ratio_for_state2(4, to_radians(60.0), to_radians(110.0)),
            waterbomb::stiffness_ratio_for_state2(4, to_radians(60.0), to_radians(100.0)));
  EXPECT_THROW(waterbomb::stiffness_ratio_for_state2(4, to_radians(60.0), to_radians(80.0)), InputError);
  EXPECT_THROW(waterbomb::stiffness_ratio_for_state2(4, to_radians(95.0), to_radians(100.0)), InputError);
}

}}  // namespace
}  // namespace rigidfold
