// Spherical 4R closed form: against a Newton solve of the general closure, its motion
// limits, and the seeds' relations through the adapter theta = -rho.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>
#include <stdexcept>

#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/vertex/vertex_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using test::angle_distance;
using test::as_span;
using test::uniform;

double closure_error(const S4RSectors& a, const S4RFoldAngles& rho) {
  return vertex_closure_residual(as_span(a), as_span(rho)).norm();
}

double max_angle_distance(const S4RFoldAngles& x, const S4RFoldAngles& y) {
  double d = 0.0;
  for (int i = 0; i < 4; ++i) d = std::max(d, angle_distance(x[i], y[i]));
  return d;
}

// Random twists of three kinds: developable paper vertices (sum 2 pi), non-developable
// ones with sectors in (0, pi), and arbitrary twists in (-2 pi, 2 pi) (beyond pi/2,
// beyond pi, negative).
S4RSectors random_twists(std::mt19937_64& rng, int kind) {
  S4RSectors a{};
  if (kind == 0) {
    do {
      for (int i = 0; i < 3; ++i) a[i] = uniform(rng, 0.1, kPi - 0.1);
      a[3] = 2 * kPi - a[0] - a[1] - a[2];
    } while (a[3] < 0.1 || a[3] > kPi - 0.1);
  } else if (kind == 1) {
    for (double& x : a) x = uniform(rng, 0.1, kPi - 0.1);
  } else {
    for (double& x : a) x = uniform(rng, -2 * kPi, 2 * kPi);
  }
  return a;
}

// A feasible input at least `margin` inside the motion range, or NaN if there is none.
double random_feasible_input(std::mt19937_64& rng, const S4RInputRange& range, double margin) {
  if (!range.feasible || range.max_abs - range.min_abs < 3 * margin) return std::nan("");
  const double mag = uniform(rng, range.min_abs + margin, range.max_abs - margin);
  return (rng() % 2 == 0) ? mag : -mag;
}

TEST(S4RSolveCosSin, RootsLimitsAndInfeasibility) {
  // 2 cos x = 1: x = +-pi/3.
  CosSinRoots r = solve_cos_sin(2.0, 0.0, 1.0);
  ASSERT_EQ(r.count, 2);
  EXPECT_NEAR(r.x[0], kPi / 3, 1e-15);
  EXPECT_NEAR(r.x[1], -kPi / 3, 1e-15);
  // Roots wrap into [-pi, pi]: -cos x + 0 sin x = 0.5 -> x = +-2pi/3.
  r = solve_cos_sin(-1.0, 1e-300, 0.5);
  ASSERT_EQ(r.count, 2);
  for (double x : r.x) {
    EXPECT_LE(std::abs(x), kPi);
    EXPECT_NEAR(-std::cos(x), 0.5, 1e-15);
  }
  // Double root at |C| = hypot(A, B), and the tolerance band just beyond it.
  r = solve_cos_sin(3.0, 4.0, 5.0);
  ASSERT_EQ(r.count, 1);
  EXPECT_NEAR(r.x[0], std::atan2(4.0, 3.0), 1e-15);
  EXPECT_EQ(solve_cos_sin(3.0, 4.0, 5.0 * (1 + 1e-13)).count, 1);
  EXPECT_EQ(solve_cos_sin(3.0, 4.0, 5.0 * (1 + 1e-10)).count, 0);
  // Degenerate equations.
  EXPECT_TRUE(solve_cos_sin(0.0, 0.0, 0.0).any);
  r = solve_cos_sin(0.0, 0.0, 1.0);
  EXPECT_FALSE(r.any);
  EXPECT_EQ(r.count, 0);
}

TEST(S4RClosedForm, MatchesNewtonOnGeneralClosure) {
  std::mt19937_64 rng(42);
  int two_branch_cases = 0, newton_checks = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const S4RSectors a = random_twists(rng, trial % 3);
    const int input = trial % 4;
    const S4RInputRange range = s4r_input_range(a, input);
    const double rho_in = random_feasible_input(rng, range, 0.02);
    if (std::isnan(rho_in)) continue;
    const S4RBranches sol = s4r_branches(a, rho_in, input);
    ASSERT_TRUE(sol.feasible);
    ASSERT_FALSE(sol.degenerate);
    ASSERT_EQ(sol.branches.size(), 2u) << "strictly inside the range there are two branches";
    EXPECT_GT(max_angle_distance(sol.branches[0], sol.branches[1]), 1e-6);
    ++two_branch_cases;
    for (const S4RFoldAngles& rho : sol.branches) {
      EXPECT_DOUBLE_EQ(rho[input], rho_in);
      EXPECT_LE(closure_error(a, rho), 1e-12);
      for (int k = 0; k < 4; ++k) {
        EXPECT_LE(std::abs(s4r_pair_residual(a, k, rho[k], rho[(k + 1) % 4])), 1e-12);
      }
      // Independent Newton solve of the 3 closure equations from a perturbed start.
      Eigen::Vector3d r;
      Eigen::Matrix3Xd J;
      vertex_closure_jacobian(as_span(a), as_span(rho), r, J);
      Eigen::Matrix3d Jr;
      for (int j = 1, c = 0; j < 4; ++j) Jr.col(c++) = J.col((input + j) % 4);
      const Eigen::Vector3d sv = Jr.jacobiSvd().singularValues();
      if (sv(2) < 1e-3) continue;  // too close to a singular configuration for Newton
      S4RFoldAngles guess = rho;
      for (int j = 1; j < 4; ++j) guess[(input + j) % 4] += uniform(rng, -0.02, 0.02);
      ASSERT_GT(test::newton_degree4(a, guess, input), 0);
      EXPECT_LE(max_angle_distance(guess, rho), 1e-12);
      ++newton_checks;
    }
  }
  EXPECT_GT(two_branch_cases, 300);
  EXPECT_GT(newton_checks, 500);
}

TEST(S4RClosedForm, NewtonFromFlatStartLandsOnAClosedFormBranch) {
  // A start that knows nothing of the closed form: Newton from small folds; wherever it
  // lands, the closed form at that input has the same configuration.
  std::mt19937_64 rng(5);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const S4RSectors a = random_twists(rng, trial % 2);
    S4RFoldAngles rho = {uniform(rng, -2.5, 2.5), uniform(rng, -0.5, 0.5),
                         uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5)};
    if (test::newton_degree4(a, rho, 0) <= 0) continue;
    for (double& x : rho) x = test::wrap(x);
    const S4RBranches sol = s4r_branches(a, rho[0]);
    ASSERT_TRUE(sol.feasible);
    double best = 1e9;
    for (const S4RFoldAngles& b : sol.branches) best = std::min(best, max_angle_distance(b, rho));
    EXPECT_LE(best, 1e-11);
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(S4RClosedForm, AnyInputCreaseGivesTheSameConfigurations) {
  std::mt19937_64 rng(9);
  for (int trial = 0; trial < 200; ++trial) {
    const S4RSectors a = random_twists(rng, trial % 3);
    const double rho0 = random_feasible_input(rng, s4r_input_range(a, 0), 0.02);
    if (std::isnan(rho0)) continue;
    for (const S4RFoldAngles& rho : s4r_branches(a, rho0, 0).branches) {
      for (int k = 1; k < 4; ++k) {
        const S4RBranches other = s4r_branches(a, rho[k], k);
        double best = 1e9;
        for (const S4RFoldAngles& b : other.branches) {
          best = std::min(best, max_angle_distance(b, rho));
        }
        EXPECT_LE(best, 1e-9) << "input crease " << k;
      }
    }
  }
}

TEST(S4RMotionLimits, BranchesMeetAtTheLimitAndVanishBeyond) {
  std::mt19937_64 rng(77);
  int limits_checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const S4RSectors a = random_twists(rng, trial % 3);
    const S4RInputRange range = s4r_input_range(a, 0);
    if (!range.feasible) continue;
    for (double limit : range.limits()) {
      // Skip limits within 1e-3 of 0 or pi: there the input is stationary in cos(rho).
      if (std::abs(limit) < 1e-3 || std::abs(limit) > kPi - 1e-3) continue;
      const S4RBranches at = s4r_branches(a, limit);
      ASSERT_TRUE(at.feasible) << "limit " << limit;
      ASSERT_FALSE(at.degenerate);
      ASSERT_EQ(at.branches.size(), 1u) << "the two branches coincide at a motion limit";
      EXPECT_LE(closure_error(a, at.branches[0]), 1e-9);

      const double outward = std::abs(limit) == range.min_abs ? -1.0 : 1.0;
      const double dir = (limit > 0 ? 1.0 : -1.0) * outward;
      EXPECT_FALSE(s4r_branches(a, limit + dir * 1e-6).feasible) << "just beyond the limit";
      const S4RBranches inside = s4r_branches(a, limit - dir * 1e-6);
      ASSERT_EQ(inside.branches.size(), 2u) << "just inside the limit";
      EXPECT_LE(max_angle_distance(inside.branches[0], inside.branches[1]), 0.05);
      for (const auto& b : inside.branches) EXPECT_LE(closure_error(a, b), 1e-12);
      ++limits_checked;
    }
  }
  EXPECT_GT(limits_checked, 100);
}

TEST(S4RMotionLimits, RangeAgreesWithPointwiseFeasibility) {
  std::mt19937_64 rng(13);
  for (int trial = 0; trial < 60; ++trial) {
    const S4RSectors a = random_twists(rng, trial % 3);
    const int input = trial % 4;
    const S4RInputRange range = s4r_input_range(a, input);
    for (int k = 0; k <= 400; ++k) {
      const double rho = -kPi + 2 * kPi * k / 400.0;
      bool near_limit = false;
      for (double l : range.limits()) near_limit |= std::abs(rho - l) < 1e-7;
      if (near_limit) continue;
      EXPECT_EQ(s4r_branches(a, rho, input).feasible, range.contains(rho))
          << "trial " << trial << " rho " << rho;
    }
    // intervals() describes the same set.
    for (int k = 0; k < 50; ++k) {
      const double rho = uniform(rng, -kPi, kPi);
      bool in_interval = false;
      for (const auto& iv : range.intervals()) in_interval |= rho >= iv[0] && rho <= iv[1];
      EXPECT_EQ(in_interval, range.contains(rho));
    }
  }
}

TEST(S4RClosedForm, RejectsBadCreaseIndex) {
  const S4RSectors a = {1.0, 1.0, 1.0, 1.0};
  EXPECT_THROW(s4r_branches(a, 0.1, 4), std::invalid_argument);
  EXPECT_THROW(s4r_input_range(a, -1), std::invalid_argument);
  EXPECT_THROW(s4r_pair_residual(a, 7, 0.0, 0.0), std::invalid_argument);
}

// ---- Seeds, through the adapter theta = -rho (mountain positive), same twists. ----

// Seed 003 eq. (2-5), transcribed literally in the seed's variables: relation between
// theta_i and theta_{i+1} (1-based i), twists a[j] = alpha_{j(j+1)} (1-based, 0-based array).
double seed003_eq2_5(const S4RSectors& twist, int i, double th_i, double th_next) {
  auto alpha = [&](int j) { return twist[((j - 1) % 4 + 4) % 4]; };  // alpha_{j(j+1)}
  const double a_im1 = alpha(i - 1), a_i = alpha(i), a_ip1 = alpha(i + 1), a_ip2 = alpha(i + 2);
  return std::cos(a_ip1) * std::sin(a_im1) * std::sin(a_i) * std::cos(th_i) +
         std::cos(a_im1) * std::sin(a_i) * std::sin(a_ip1) * std::cos(th_next) +
         std::cos(a_i) * std::sin(a_ip1) * std::sin(a_im1) * std::cos(th_i) * std::cos(th_next) -
         std::sin(a_ip1) * std::sin(a_im1) * std::sin(th_i) * std::sin(th_next) +
         std::cos(a_ip2) - std::cos(a_i) * std::cos(a_ip1) * std::cos(a_im1);
}

// The seed's branches for input theta_1, through the adapter.
std::vector<S4RFoldAngles> seed_branches(const S4RSectors& twist, double theta1) {
  std::vector<S4RFoldAngles> out;
  for (const S4RFoldAngles& rho : s4r_branches(twist, test::rho_from_seed_theta(theta1)).branches) {
    out.push_back(test::seed_theta_from_rho(rho));
  }
  return out;
}

TEST(S4RSeedMapping, Seed003Eq2_5HoldsOnAdaptedBranches) {
  std::mt19937_64 rng(303);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const S4RSectors a = random_twists(rng, trial % 3);
    const double rho = random_feasible_input(rng, s4r_input_range(a, 0), 0.02);
    if (std::isnan(rho)) continue;
    for (const S4RFoldAngles& theta : seed_branches(a, -rho)) {
      for (int i = 1; i <= 4; ++i) {
        EXPECT_LE(std::abs(seed003_eq2_5(a, i, theta[i - 1], theta[i % 4])), 1e-12);
        // The kernel's pair relation is -(2-5) with theta -> rho.
        EXPECT_NEAR(s4r_pair_residual(a, i - 1, -theta[i - 1], -theta[i % 4]),
                    -seed003_eq2_5(a, i, -theta[i - 1], -theta[i % 4]), 1e-14);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

TEST(S4RSeedMapping, Seed003CentralSymmetryEq2_10) {
  // f(-theta_i) = -f(theta_i): the branch set at -theta_1 is the negated set at theta_1.
  std::mt19937_64 rng(210);
  for (int trial = 0; trial < 100; ++trial) {
    const S4RSectors a = random_twists(rng, trial % 3);
    const double rho = random_feasible_input(rng, s4r_input_range(a, 0), 0.02);
    if (std::isnan(rho)) continue;
    const auto plus = seed_branches(a, rho);
    const auto minus = seed_branches(a, -rho);
    ASSERT_EQ(plus.size(), minus.size());
    for (const S4RFoldAngles& p : plus) {
      const S4RFoldAngles neg = {-p[0], -p[1], -p[2], -p[3]};
      double best = 1e9;
      for (const S4RFoldAngles& m : minus) best = std::min(best, max_angle_distance(m, neg));
      EXPECT_LE(best, 1e-12);
    }
  }
}

TEST(S4RSeedMapping, Seed003VariantEq2_6GivesTransmission2_13b) {
  // Variant twists (2-6): alpha' = (alpha12, pi - alpha23, pi - alpha34, alpha41). With the
  // same input theta_1' = theta_1 the outputs are theta' = (theta_1, theta_2 - pi, -theta_3,
  // theta_4 - pi) (mod 2 pi), eq. (2-13b) and the corrected (2-9). The first linkage is
  // the one of the seed's Fig. 2-1 (its variant is the figure's dashed curve).
  std::vector<S4RSectors> bases = {{kPi / 9, 2 * kPi / 9, 4 * kPi / 9, 2 * kPi / 3}};
  std::mt19937_64 rng(206);
  for (int i = 0; i < 60; ++i) bases.push_back(random_twists(rng, i % 3));
  int checked = 0;
  for (const S4RSectors& a : bases) {
    const S4RSectors variant = {a[0], kPi - a[1], kPi - a[2], a[3]};
    const double rho = random_feasible_input(rng, s4r_input_range(a, 0), 0.02);
    if (std::isnan(rho)) continue;
    const double theta1 = -rho;
    const auto base = seed_branches(a, theta1);
    const auto var = seed_branches(variant, theta1);
    ASSERT_EQ(base.size(), var.size());
    for (const S4RFoldAngles& t : base) {
      const S4RFoldAngles expected = {t[0], t[1] - kPi, -t[2], t[3] - kPi};
      double best = 1e9;
      for (const S4RFoldAngles& v : var) best = std::min(best, max_angle_distance(v, expected));
      EXPECT_LE(best, 1e-12);
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
}

TEST(S4RSeedMapping, Seed001SquareTwistVertexEq5) {
  // Seed 001 eq. (4): alpha12 = pi/2, alpha23 = alpha, alpha34 = pi/2, alpha41 = pi - alpha.
  // Eq. (5a) (theta_1, theta_3 of opposite sign): tan(theta2/2) = cos a/(1 - sin a) tan(theta1/2);
  // eq. (5b): tan(theta2/2) = -cos a/(1 + sin a) tan(theta1/2). Both are the two branches of
  // the closed form at every input.
  for (double alpha : {0.2, 0.6, 1.0, 1.4}) {
    const S4RSectors a = {kPi / 2, alpha, kPi / 2, kPi - alpha};
    const double ka = std::cos(alpha) / (1 - std::sin(alpha));
    const double kb = -std::cos(alpha) / (1 + std::sin(alpha));
    for (double theta1 : {-3.0, -1.2, -0.01, 0.3, 1.7, 3.1}) {
      const auto branches = seed_branches(a, theta1);
      ASSERT_EQ(branches.size(), 2u);
      bool found_a = false, found_b = false;
      for (const S4RFoldAngles& t : branches) {
        const double ratio = std::tan(t[1] / 2) / std::tan(theta1 / 2);
        if (std::abs(ratio - ka) < 1e-10 * std::abs(ka)) {
          found_a = true;
          EXPECT_LT(t[0] * t[2], 0.0) << "(5a): theta1 and theta3 of opposite sign";
          EXPECT_GT(t[1] * t[3], 0.0) << "(5a): theta2 and theta4 of the same sign";
        } else if (std::abs(ratio - kb) < 1e-10 * std::abs(kb)) {
          found_b = true;
          EXPECT_GT(t[0] * t[2], 0.0) << "(5b): theta1 and theta3 of the same sign";
          EXPECT_LT(t[1] * t[3], 0.0) << "(5b): theta2 and theta4 of opposite sign";
        }
      }
      EXPECT_TRUE(found_a && found_b) << "alpha " << alpha << " theta1 " << theta1;
    }
  }
}

}}  // namespace
}  // namespace rigidfold
