// Flat-foldable degree-4 vertex: tan-half multipliers against the spherical 4R closed form,
// sign patterns (Maekawa), seed 003 (3-3) and seed 001 (5) through the adapter.
#include <gtest/gtest.h>

#include <stdexcept>

#include "kernel/vertex/flat_foldable_multipliers.hpp"
#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/vertex/vertex_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using test::angle_distance;
using test::as_span;
using test::uniform;

constexpr FlatFoldMode kModes[] = {FlatFoldMode::kEqual13, FlatFoldMode::kEqual02};

std::array<double, 4> flat_foldable(double a0, double a1) { return {a0, a1, kPi - a0, kPi - a1}; }

// Generic and Miura-like (a0 = a1) vertices, acute and obtuse.
std::vector<std::array<double, 4>> sample_vertices(std::mt19937_64& rng, int count) {
  std::vector<std::array<double, 4>> out;
  for (int i = 0; i < count; ++i) {
    const double a0 = uniform(rng, 0.05, kPi - 0.05);
    const double a1 = (i % 4 == 0) ? a0 : uniform(rng, 0.05, kPi - 0.05);
    out.push_back(flat_foldable(a0, a1));
  }
  return out;
}

double max_angle_distance(const std::array<double, 4>& x, const std::array<double, 4>& y) {
  double d = 0.0;
  for (int i = 0; i < 4; ++i) d = std::max(d, angle_distance(x[i], y[i]));
  return d;
}

// A driving crease that folds in this mode (crease 0 unless it stays flat).
int driver_for(const FlatFoldMultipliers& m) { return m.direction[0] != 0.0 ? 0 : 1; }

TEST(MultiplierFlatFoldable, MatchesSpherical4RClosedForm) {
  std::mt19937_64 rng(404);
  int checked = 0;
  for (const auto& a : sample_vertices(rng, 300)) {
    for (FlatFoldMode mode : kModes) {
      const FlatFoldMultipliers m = flat_fold_multipliers(a, mode);
      const int driver = driver_for(m);
      const double rho_in = uniform(rng, -kPi, kPi);
      const std::array<double, 4> rho = flat_fold_angles(a, mode, rho_in, driver);
      EXPECT_EQ(rho[driver], rho_in);
      EXPECT_LE(vertex_closure_residual(as_span(a), as_span(rho)).norm(), 1e-12);
      // The mode is one of the closed-form branches at the same input.
      const S4RBranches sol = s4r_branches(a, rho_in, driver);
      ASSERT_TRUE(sol.feasible);
      if (sol.degenerate) continue;  // e.g. a Miura line fold driven at rho = 0
      double best = 1e9;
      for (const auto& b : sol.branches) best = std::min(best, max_angle_distance(b, rho));
      EXPECT_LE(best, 1e-12) << "mode " << to_string(mode) << " a0 " << a[0] << " a1 " << a[1];
      ++checked;
    }
  }
  EXPECT_GT(checked, 550);
}

TEST(MultiplierFlatFoldable, TheTwoModesAreTheTwoBranches) {
  std::mt19937_64 rng(405);
  for (const auto& a : sample_vertices(rng, 100)) {
    if (a[0] == a[1] || std::abs(a[0] + a[1] - kPi) < 1e-9) continue;  // a mode keeps crease 0 flat
    const double rho0 = uniform(rng, -3.0, 3.0);
    const S4RBranches sol = s4r_branches(a, rho0);
    ASSERT_EQ(sol.branches.size(), 2u);
    for (FlatFoldMode mode : kModes) {
      const auto rho = flat_fold_angles(a, mode, rho0);
      EXPECT_LE(std::min(max_angle_distance(sol.branches[0], rho),
                         max_angle_distance(sol.branches[1], rho)),
                1e-12);
    }
  }
}

TEST(MultiplierFlatFoldable, MaekawaSignPatternAndModeRelations) {
  std::mt19937_64 rng(406);
  int generic = 0;
  for (const auto& a : sample_vertices(rng, 300)) {
    for (FlatFoldMode mode : kModes) {
      const FlatFoldMultipliers m = flat_fold_multipliers(a, mode);
      const int driver = driver_for(m);
      double rho_in = uniform(rng, 0.01, kPi - 0.01);
      if (rng() % 2) rho_in = -rho_in;
      const auto rho = flat_fold_angles(a, mode, rho_in, driver);
      if (mode == FlatFoldMode::kEqual13) {
        EXPECT_NEAR(rho[3], rho[1], 1e-14);
        EXPECT_NEAR(rho[2], -rho[0], 1e-14);
      } else {
        EXPECT_NEAR(rho[2], rho[0], 1e-14);
        EXPECT_NEAR(rho[3], -rho[1], 1e-14);
      }
      if (m.odd_crease < 0) {
        // Degenerate: one opposite pair stays flat, the other folds like a straight crease.
        int flat = 0;
        for (double x : rho) flat += x == 0.0;
        EXPECT_EQ(flat, 2);
        continue;
      }
      // Maekawa: three creases of one sign, the odd one of the other.
      int positive = 0;
      for (int i = 0; i < 4; ++i) {
        ASSERT_NE(rho[i], 0.0);
        positive += rho[i] > 0;
      }
      EXPECT_TRUE(positive == 1 || positive == 3);
      const bool odd_positive = positive == 1;
      for (int i = 0; i < 4; ++i) {
        EXPECT_EQ((rho[i] > 0) == odd_positive, i == m.odd_crease) << "crease " << i;
      }
      // The documented rule for the odd crease.
      if (mode == FlatFoldMode::kEqual13) {
        EXPECT_EQ(m.odd_crease, a[1] > a[0] ? 0 : 2);
      } else {
        EXPECT_EQ(m.odd_crease, a[0] + a[1] < kPi ? 1 : 3);
      }
      ++generic;
    }
  }
  EXPECT_GT(generic, 400);
}

TEST(MultiplierFlatFoldable, StepsAndProductsAreConsistent) {
  std::mt19937_64 rng(407);
  for (const auto& a : sample_vertices(rng, 100)) {
    if (a[0] == a[1]) continue;
    for (FlatFoldMode mode : kModes) {
      const FlatFoldMultipliers m = flat_fold_multipliers(a, mode);
      if (m.odd_crease < 0) continue;
      EXPECT_NEAR(m.step[0] * m.step[1] * m.step[2] * m.step[3], 1.0, 1e-9);
      EXPECT_EQ(m.from_first[0], 1.0);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(m.from_first[i + 1], m.from_first[i] * m.step[i],
                    1e-12 * std::max(1.0, std::abs(m.from_first[i + 1])));
      }
      const double rho0 = uniform(rng, -3.0, 3.0);
      const auto rho = flat_fold_angles(a, mode, rho0);
      for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(std::tan(rho[i] / 2), m.from_first[i] * std::tan(rho0 / 2),
                    1e-12 * std::max(1.0, std::abs(std::tan(rho[i] / 2))));
      }
    }
  }
}

// The unchecked pair of directions the multiplier model uses is each mode's own direction, bit
// for bit, including the degenerate vertices (d = 0, s = pi/2) where a pair stays flat.
TEST(MultiplierFlatFoldable, BothDirectionsAtOnceMatchEachMode) {
  std::mt19937_64 rng(409);
  std::vector<std::array<double, 4>> vertices = sample_vertices(rng, 100);
  vertices.push_back(flat_foldable(kPi / 3, kPi / 3));  // d = 0
  vertices.push_back(flat_foldable(kPi / 3, kPi / 6));  // s = pi/2
  for (const auto& a : vertices) {
    const auto both = flat_fold_directions(a);
    EXPECT_EQ(both[0], flat_fold_multipliers(a, FlatFoldMode::kEqual13, 1e-6).direction);
    EXPECT_EQ(both[1], flat_fold_multipliers(a, FlatFoldMode::kEqual02, 1e-6).direction);
  }
}

TEST(MultiplierFlatFoldable, MiuraVertex) {
  // Acute sectors 0 and 1 around crease 1; creases 1 and 3 collinear, 0 and 2 the zig-zag.
  const double a = 1.0;
  const auto sectors = flat_foldable(a, a);
  const FlatFoldMultipliers miura = flat_fold_multipliers(sectors, FlatFoldMode::kEqual02);
  EXPECT_EQ(miura.odd_crease, 1);
  const auto rho = flat_fold_angles(sectors, FlatFoldMode::kEqual02, -1.0);  // zig-zag mountain
  EXPECT_LT(rho[0], 0.0);
  EXPECT_GT(rho[1], 0.0);  // valley between the acute sectors
  EXPECT_LT(rho[2], 0.0);
  EXPECT_LT(rho[3], 0.0);
  EXPECT_NEAR(std::tan(rho[1] / 2), -std::cos(a) * std::tan(-0.5), 1e-15);

  // The other mode is the fold along the straight line 1-3 alone.
  const FlatFoldMultipliers line = flat_fold_multipliers(sectors, FlatFoldMode::kEqual13);
  EXPECT_EQ(line.odd_crease, -1);
  const auto straight = flat_fold_angles(sectors, FlatFoldMode::kEqual13, 0.7, 1);
  EXPECT_EQ(straight[0], 0.0);
  EXPECT_EQ(straight[2], 0.0);
  EXPECT_DOUBLE_EQ(straight[3], 0.7);
  EXPECT_THROW(flat_fold_angles(sectors, FlatFoldMode::kEqual13, 0.7, 0), std::invalid_argument);
}

TEST(MultiplierFlatFoldable, FoldsCompletelyFlatAtPi) {
  const auto a = flat_foldable(0.7, 1.9);
  for (FlatFoldMode mode : kModes) {
    for (double end : {kPi, -kPi}) {
      const auto rho = flat_fold_angles(a, mode, end);
      for (double x : rho) EXPECT_NEAR(std::abs(x), kPi, 1e-15);
      EXPECT_LE(vertex_closure_residual(as_span(a), as_span(rho)).norm(), 1e-14);
    }
  }
}

TEST(MultiplierFlatFoldable, RejectsVerticesThatAreNotFlatFoldable) {
  EXPECT_THROW(flat_fold_multipliers({1.0, 1.2, kPi - 1.0 + 1e-6, kPi - 1.2}, FlatFoldMode::kEqual02),
               std::invalid_argument);
  EXPECT_THROW(flat_fold_multipliers({1.0, 1.2, kPi - 1.0, kPi - 1.3}, FlatFoldMode::kEqual13),
               std::invalid_argument);
  EXPECT_THROW(flat_fold_multipliers({-0.5, 1.0, kPi + 0.5, kPi - 1.0}, FlatFoldMode::kEqual13),
               std::invalid_argument);
  EXPECT_THROW(flat_fold_angles(flat_foldable(1.0, 1.2), FlatFoldMode::kEqual13, 0.1, 4),
               std::invalid_argument);
  EXPECT_NO_THROW(flat_fold_multipliers({1.0, 1.2, kPi - 1.0 + 1e-12, kPi - 1.2}, FlatFoldMode::kEqual02));
}

// ---- Seeds, through the adapter theta = -rho (tan-half ratios do not see the sign). ----

TEST(MultiplierSeedMapping, Seed003Eq3_3) {
  // (3-3a), branch S: tan(t1/2)/tan(t2/2) = -sin d / sin s, tan(t2/2)/tan(t3/2) = sin s / sin d,
  // tan(t3/2)/tan(t4/2) = sin d / sin s, tan(t4/2)/tan(t1/2) = -sin s / sin d.
  // (3-3b), branch C: -cos d / cos s, -cos s / cos d, cos d / cos s, cos s / cos d.
  // d = (alpha23 - alpha12)/2, s = (alpha23 + alpha12)/2.
  std::mt19937_64 rng(33);
  for (int trial = 0; trial < 50; ++trial) {
    const double a12 = uniform(rng, 0.1, 3.0), a23 = uniform(rng, 0.1, 3.0);
    if (std::abs(a12 - a23) < 1e-3 || std::abs(a12 + a23 - kPi) < 1e-3) continue;
    const auto sectors = flat_foldable(a12, a23);
    const double d = (a23 - a12) / 2, s = (a23 + a12) / 2;
    const std::array<double, 4> ratio_S = {-std::sin(d) / std::sin(s), std::sin(s) / std::sin(d),
                                           std::sin(d) / std::sin(s), -std::sin(s) / std::sin(d)};
    const std::array<double, 4> ratio_C = {-std::cos(d) / std::cos(s), -std::cos(s) / std::cos(d),
                                           std::cos(d) / std::cos(s), std::cos(s) / std::cos(d)};
    const double theta1 = uniform(rng, -3.0, 3.0);
    for (FlatFoldMode mode : kModes) {
      const auto& expected = mode == FlatFoldMode::kEqual13 ? ratio_S : ratio_C;
      const auto theta =
          test::seed_theta_from_rho(flat_fold_angles(sectors, mode, test::rho_from_seed_theta(theta1)));
      for (int i = 0; i < 4; ++i) {
        const double got = std::tan(theta[i] / 2) / std::tan(theta[(i + 1) % 4] / 2);
        EXPECT_NEAR(got, expected[i], 1e-10 * std::max(1.0, std::abs(expected[i])));
        // The multiplier step is the inverse ratio.
        const double step = flat_fold_multipliers(sectors, mode).step[i];
        EXPECT_NEAR(1.0 / step, expected[i], 1e-12 * std::max(1.0, std::abs(expected[i])));
      }
    }
  }
}

TEST(MultiplierSeedMapping, Seed001SquareTwistEq5And7) {
  // Square-twist vertex (eq. 4): alpha12 = pi/2, alpha23 = a, alpha34 = pi/2, alpha41 = pi - a.
  for (double alpha : {0.3, 0.8, 1.3}) {
    const std::array<double, 4> sectors = {kPi / 2, alpha, kPi / 2, kPi - alpha};
    const double ca = std::cos(alpha), sa = std::sin(alpha);
    // (5a): theta_1, theta_3 opposite -> kEqual13; (5b) -> kEqual02.
    const std::array<double, 4> eq5a = {ca / (1 - sa), -ca / (1 + sa), -ca / (1 - sa), ca / (1 + sa)};
    const std::array<double, 4> eq5b = {-ca / (1 + sa), -ca / (1 - sa), ca / (1 + sa), ca / (1 - sa)};
    const auto m13 = flat_fold_multipliers(sectors, FlatFoldMode::kEqual13);
    const auto m02 = flat_fold_multipliers(sectors, FlatFoldMode::kEqual02);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(m13.step[i], eq5a[i], 1e-12 * std::abs(eq5a[i]));
      EXPECT_NEAR(m02.step[i], eq5b[i], 1e-12 * std::abs(eq5b[i]));
    }
    // (7): Type 1, four identical vertices chained theta_1 -> theta_2: the loop gain is
    // cos^4 a / (1 - sin a)^4 != 1, so the Type 1 square twist is not rigidly foldable.
    const double gain = std::pow(m13.step[0], 4);
    EXPECT_NEAR(gain, std::pow(ca, 4) / std::pow(1 - sa, 4), 1e-12 * gain);
    EXPECT_GT(std::abs(gain - 1.0), 1e-3);
  }
}

}}  // namespace
}  // namespace rigidfold
