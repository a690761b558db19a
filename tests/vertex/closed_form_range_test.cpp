// The closed forms over the ends of their documented ranges: every answer the
// checked entry points return passes its own closure check, the Miura vertex is accurate at
// alpha = 1e-300 deg .. 90 - 1e-12 deg and theta up to its limit, and the checks themselves
// reject a wrong state.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <vector>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/solve/portable_random.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "reference/miura_reference.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// Ends and interior of --alpha1/--alpha2 (degrees): [1e-300, 90 - 1e-12].
const std::vector<double> kAlphaDeg{1e-300, 1e-170, 1e-30, 1e-12, 1e-6, 0.5, 30, 45, 60, 89, 90 - 1e-6, 90 - 1e-12};

std::vector<double> theta_grid(double limit) {
  std::vector<double> out{0.0};
  for (double t : {1e-300, 1e-150, 1e-12, 0.25 * limit, 0.5 * limit, 0.9 * limit, limit * (1 - 1e-12), limit}) {
    out.push_back(t);
    out.push_back(-t);
  }
  return out;
}

TEST(ClosedFormRange, MiuraVertexPassesItsCheckOverTheWholeClosedRange) {
  double worst = 0;
  int n = 0;
  for (double d1 : kAlphaDeg)
    for (double d2 : kAlphaDeg) {
      const double a1 = to_radians(d1), a2 = to_radians(d2);
      for (double th : theta_grid(miura_theta_limit(a1, a2))) {
        MiuraVertexState st;
        ASSERT_NO_THROW(st = miura_vertex_checked(a1, a2, th)) << d1 << ", " << d2 << ", " << th;
        const MiuraVertexCheck c = check_miura_vertex(st);
        EXPECT_TRUE(c.passed());
        worst = std::max(worst, c.closure_residual);
        ++n;
      }
    }
  std::cout << "[ worst ] closure residual " << worst << " rad over " << n << " states\n";
  EXPECT_LE(worst, 1e-14);
}

// As alpha1 -> 0, b lies on a: the vertex is the straight line a-c (sectors pi, pi) with d
// flat, so rho_a + rho_b = rho_c: rho_b -> 4 theta, rho_d -> 0 (a regression case: rho_b = 0
// was once printed there, 80 deg off, with a closure residual of 1.4 rad).
TEST(ClosedFormRange, TinyAlphaTendsToTheStraightLineLimit) {
  for (double d1 : {1e-300, 1e-170, 1e-100}) {
    const double th = to_radians(20);
    const MiuraVertexState st = miura_vertex_checked(to_radians(d1), to_radians(60), th);
    EXPECT_NEAR(st.fold_angles[kMiuraPeripheral1], 4 * th, 1e-14) << d1;
    EXPECT_LE(std::fabs(st.fold_angles[kMiuraPeripheral2]), 1e-13) << d1;
    EXPECT_GT(st.fold_angles[kMiuraPeripheral2], 0.0) << d1;  // valley, like theta, and not underflowed
    // Mirror: a tiny alpha2 gives the limit on the other side.
    const MiuraVertexState mirror = miura_vertex_checked(to_radians(60), to_radians(d1), th);
    EXPECT_NEAR(mirror.fold_angles[kMiuraPeripheral2], 4 * th, 1e-14) << d1;
  }
}

// Against the cone-intersection reference in 400 bits where it still has digits to spare
// (its cancellation is ~alpha^2): tiny alphas to 1e-30 rad, both tiny, and near 90 deg.
TEST(ClosedFormRange, TinyAndNearRightAlphasMatchTheReference) {
  using Real400 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<400>>;
  struct Case {
    double a1, a2, th;
  };
  const std::vector<Case> cases{{1e-30, to_radians(60), 0.35},          {1e-12, to_radians(30), -0.6},
                                {to_radians(75), 1e-20, 0.2},          {1e-25, 3e-25, 0.4},
                                {1e-25, 1e-25, 1.2},                   {to_radians(90 - 1e-12), to_radians(40), 0.5},
                                {to_radians(90 - 1e-12), to_radians(90 - 1e-12), 1.5}};
  for (const auto& c : cases) {
    const MiuraVertexState st = miura_vertex_checked(c.a1, c.a2, c.th);
    const auto ref = test::miura_reference<Real400>(c.a1, c.a2, c.th);
    for (int i = 0; i < 4; ++i) {
      const double r = static_cast<double>(ref.rho[i]);
      EXPECT_LE(std::fabs(st.fold_angles[i] - r), 1e-13 * std::max(std::fabs(r), 1e-300) + 1e-300)
          << "crease " << i << " at " << c.a1 << ", " << c.a2 << ", " << c.th;
    }
    EXPECT_LE(std::fabs(st.phi - static_cast<double>(ref.phi)), 1e-13 * std::fabs(static_cast<double>(ref.phi)) + 1e-300);
  }
}

TEST(ClosedFormRange, MiuraCheckRejectsAWrongState) {
  MiuraVertexState st = miura_vertex(to_radians(40), to_radians(60), 0.3);
  ASSERT_TRUE(check_miura_vertex(st).passed());
  MiuraVertexState moved = st;
  moved.fold_angles[kMiuraPeripheral1] += 1e-6;
  EXPECT_FALSE(check_miura_vertex(moved).passed());
  EXPECT_GT(check_miura_vertex(moved).closure_residual, kMiuraClosureTolerance);
  // The mirror branch (every fold angle negated) closes the loop too, but contradicts theta's sign.
  MiuraVertexState mirrored = st;
  for (double& r : mirrored.fold_angles) r = -r;
  EXPECT_LE(check_miura_vertex(mirrored).closure_residual, 1e-14);
  EXPECT_FALSE(check_miura_vertex(mirrored).passed());
}

// Spherical 4R: random twists over [-360, 360] deg including the ends and the degenerate
// values (0, 180, 360), inputs over [-180, 180] including both ends and the motion limits
// +-1e-12. Every branch returned passes the closure check; the checked form refines the
// double roots at the motion limits instead of failing.
TEST(ClosedFormRange, S4RBranchesPassTheirCheckOverTheRange) {
  const std::vector<double> special{-360, -180, -90, -1e-12, 0, 1e-300, 1e-12, 90, 180 - 1e-12, 180, 360};
  SplitMix64 rng{20};
  double worst = 0;
  int branches = 0, no_answer = 0, cases = 0;
  for (int k = 0; k < 3000; ++k) {
    S4RSectors tw;
    for (double& t : tw) {
      const double u = rng.uniform();
      t = to_radians(u < 0.15 ? special[rng.next() % special.size()] : -360 + 720 * rng.uniform());
    }
    std::vector<double> inputs{-kPi, kPi, 0.0, to_radians(1e-12), kPi * (2 * rng.uniform() - 1)};
    const S4RInputRange range = s4r_input_range(tw, 0);
    for (double lim : range.limits())
      for (double eps : {0.0, 1e-12, -1e-12}) inputs.push_back(std::clamp(lim + eps, -kPi, kPi));
    for (double in : inputs) {
      ++cases;
      try {
        const S4RBranches b = s4r_branches_checked(tw, in, 0);
        for (const auto& br : b.branches) {
          const double r = vertex_closure_residual(std::span<const double>(tw.data(), 4), std::span<const double>(br.data(), 4)).norm();
          EXPECT_LE(r, kS4RClosureTolerance);
          worst = std::max(worst, r);
          ++branches;
        }
      } catch (const NoAnswerError& e) {
        ++no_answer;
        EXPECT_GT(e.residual(), kS4RClosureTolerance);
      }
    }
  }
  std::cout << "[ s4r ] " << cases << " cases, " << branches << " branches, worst residual " << worst << ", "
            << no_answer << " without an answer within tolerance\n";
  EXPECT_EQ(no_answer, 0);
  EXPECT_GT(branches, cases / 2);
}

// Generic twists, inputs strictly inside the motion range: two branches, both closing.
TEST(ClosedFormRange, S4RInsideTheRangeAlwaysAnswers) {
  SplitMix64 rng{7};
  for (int k = 0; k < 500; ++k) {
    S4RSectors tw;
    for (double& t : tw) t = to_radians(10 + 160 * rng.uniform());
    const S4RInputRange range = s4r_input_range(tw, 0);
    if (!range.feasible || range.max_abs - range.min_abs < 1e-3) continue;
    const double in = range.min_abs + (range.max_abs - range.min_abs) * (0.01 + 0.98 * rng.uniform());
    const S4RBranches b = s4r_branches_checked(tw, in, 0);
    EXPECT_TRUE(b.feasible);
    EXPECT_EQ(b.branches.size(), 2u);
  }
}

}}  // namespace
}  // namespace rigidfold
