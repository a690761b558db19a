// Local flat foldability of one vertex's letters (kernel/pattern/vertex_letter_rules.hpp),
// against two independent results: Hull's count 2 C(2n, n-1) for 2n equal sectors, and, for
// generic flat-foldable degree-4 vertices, the sign patterns of the two rigid modes
// (kernel/vertex/flat_foldable_multipliers.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

#include "kernel/pattern/vertex_letter_rules.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

long binomial(int n, int k) {
  long r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

TEST(VertexLetterRules, EqualSectorsGiveHullsCount) {
  for (int d : {2, 4, 6, 8, 10}) {
    const std::vector<double> sectors(d, 2 * std::numbers::pi / d);
    const auto masks = flat_folding_letter_masks(sectors);
    const long expected = d == 2 ? 2 : 2 * binomial(d, d / 2 - 1);
    EXPECT_EQ(static_cast<long>(masks.size()), expected) << "degree " << d;
  }
}

TEST(VertexLetterRules, GenericDegreeFourMatchesTheRigidModesSigns) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.05, std::numbers::pi - 0.05);
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const double a0 = u(rng), a1 = u(rng);
    const std::array<double, 4> s = {a0, a1, std::numbers::pi - a0, std::numbers::pi - a1};
    // Skip the degenerate vertices (a0 = a1 or a0 + a1 = pi keep one crease pair flat).
    if (std::fabs(a0 - a1) < 1e-3 || std::fabs(a0 + a1 - std::numbers::pi) < 1e-3) continue;
    std::vector<std::uint32_t> from_modes;
    for (FlatFoldMode mode : {FlatFoldMode::kEqual13, FlatFoldMode::kEqual02}) {
      const auto w = flat_fold_multipliers(s, mode).direction;
      for (int sign : {1, -1}) {
        std::uint32_t mask = 0;
        for (int i = 0; i < 4; ++i)
          if (sign * w[i] > 0) mask |= 1u << i;  // tan(rho/2) > 0: valley
        from_modes.push_back(mask);
      }
    }
    std::sort(from_modes.begin(), from_modes.end());
    EXPECT_EQ(flat_folding_letter_masks(s), from_modes) << a0 << " " << a1;
    ++compared;
  }
  EXPECT_GT(compared, 190);
}

TEST(VertexLetterRules, StrictMinimumNeedsOppositeLettersAndMaekawaHolds) {
  // Degree 6 with one strictly smallest sector (0.3, between creases 2 and 3); Kawasaki:
  // s0 + s2 + s4 = s1 + s3 + s5 = pi.
  const double pi = std::numbers::pi;
  const std::vector<double> sectors = {1.0, 1.2, 0.3, 0.9, pi - 1.3, pi - 2.1};
  const auto masks = flat_folding_letter_masks(sectors);
  ASSERT_FALSE(masks.empty());
  for (std::uint32_t m : masks) {
    const int valleys = __builtin_popcount(m);
    EXPECT_EQ(std::abs(2 * valleys - 6), 2);
    EXPECT_NE((m >> 2) & 1u, (m >> 3) & 1u) << m;  // the creases of the smallest sector differ
  }
  // Odd degree and a letter other than +-1 never fold flat.
  EXPECT_FALSE(letters_fold_flat(std::vector<double>{2.0, 2.0, 2 * pi - 4.0}, std::vector<int>{1, 1, -1}));
  EXPECT_FALSE(letters_fold_flat(std::vector<double>(4, pi / 2), std::vector<int>{1, 1, 1, 0}));
}

}}  // namespace
}  // namespace rigidfold
