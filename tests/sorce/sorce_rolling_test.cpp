// SORCE (seed 002) forward-rolling reconstruction: roll the generated profiles against each
// other by matched arc length (sorce_rolling.hpp: only the curves' geometry) and recover
// the fold angle gamma(t) and the right panel's translation R(gamma)(0, z_r) + d.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "design/sorce/sorce_rolling.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::vertex_a_linear;
using testing::vertex_b_sectors;
using testing::vertex_b_split;

std::vector<double> grid(int n) {
  std::vector<double> t;
  for (int k = 0; k <= n; ++k) t.push_back(static_cast<double>(k) / n);
  return t;
}

RollingRecovery recover(const FoldMotion& m, const PlanarCurve& right) { return rolling_recovery(m, right, grid(50)); }

TEST(SorceRolling, ForwardRollingRecoversTheMotion) {
  std::vector<std::pair<const char*, SorceVertex>> cases{
      {"vertex A linear", vertex_a_linear(1.0)},
      {"vertex B eq 60", vertex_b_split(1)},
      {"vertex B eq 61", vertex_b_split(2)},
      {"vertex B circular", circular_split_vertex(vertex_b_sectors(), VertexParameterization::kSymmetric, 0.1)}};
  for (const auto& [name, v] : cases) {
    for (int j = 0; j < 4; ++j) {
      const RollingRecovery e = recover(v.folds[j], right_profile_curve(v.folds[j]));
      EXPECT_LE(e.gamma, 1e-8) << name << " fold " << j + 1;
      EXPECT_LE(e.translation, 1e-8) << name << " fold " << j + 1;
      EXPECT_LE(e.parameter, 1e-6) << name << " fold " << j + 1;
    }
  }
  // The circle oracle.
  const ScalarFunction g = linear_fold(kPi);
  const FoldMotion circle{g, circular_offset(0.25, g), circular_offset(0.25, g), {}, 0.5, 0.5};
  const RollingRecovery e = recover(circle, right_profile_curve(circle));
  EXPECT_LE(e.gamma, 1e-8);
  EXPECT_LE(e.translation, 1e-8);
}

// The reconstruction can fail: a right profile from other offsets does not reproduce gamma.
TEST(SorceRolling, WrongProfileIsNotRecovered) {
  const SorceVertex v = vertex_a_linear(1.0);
  FoldMotion other = v.folds[1];
  other.z_right = power_function(0.6, 1);  // z2(1) = 0.6 instead of 0.5
  const RollingRecovery e = recover(v.folds[1], right_profile_curve(other));
  EXPECT_GT(e.gamma, 1e-3);
}

}}  // namespace
}  // namespace rigidfold::sorce
