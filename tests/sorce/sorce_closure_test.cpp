// SORCE (seed 002) thick-vertex 3D closure: T_1 Ry(a_1) .. T_4 Ry(a_4) = I along the whole
// path, and the 6x4 closure Jacobian of nullity 1 on (0, 1) with the joint rates in its
// null space.
#include <gtest/gtest.h>

#include <vector>

#include "design/sorce/sorce_closure.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::vertex_a_linear;
using testing::vertex_b_sectors;
using testing::vertex_b_split;

std::vector<std::pair<const char*, SorceVertex>> vertices() {
  const VertexSectors a = testing::vertex_a_sectors();
  const auto gamma = vertex_fold_angles(a, VertexParameterization::kSymmetric);
  const auto outer = basis_offset(-1.5, {0.3, -0.2, 0.5}, seed_offset_bases()), inner = basis_offset(0.5, {-0.4, 0.1, 0.2}, seed_offset_bases());
  return {{"vertex A linear", vertex_a_linear(1.0)},
          {"vertex A eq 35/36", sorce_vertex(a, gamma, {outer, inner, inner, outer}, {1, 1, 1, 1})},
          {"vertex B eq 60", vertex_b_split(1)},
          {"vertex B eq 61", vertex_b_split(2)},
          {"vertex B circular", circular_split_vertex(vertex_b_sectors(), VertexParameterization::kSymmetric, 0.1)}};
}

TEST(SorceClosure, ThickVertexClosesWithOneDegreeOfFreedom) {
  for (const auto& [name, v] : vertices()) {
    double error = 0.0, rate = 0.0, gap = 1e300;
    for (int k = 0; k <= 100; ++k) {
      const double t = k / 100.0;
      const VertexClosure c = vertex_closure(v, t);
      error = std::max(error, c.error);
      rate = std::max(rate, c.rate_residual);
      if (k > 0 && k < 100) {
        EXPECT_EQ(c.nullity, 1) << name << " t " << t;
        gap = std::min(gap, c.singular_values[2] / c.singular_values[0]);
      }
    }
    EXPECT_LE(error, 1e-12) << name;  // measured <= 5e-16
    EXPECT_LE(rate, 1e-12) << name;
    EXPECT_GT(gap, 1e-3) << name;  // the third singular value stays clear of the tolerance
  }
}

// The split directions matter: flipping d_3 (eq 59) opens the loop.
TEST(SorceClosure, WrongSplitDirectionOpensTheLoop) {
  SorceVertex v = vertex_b_split(1);
  const VectorFunction d = v.folds[2].d;
  v.folds[2].d = [d](double t) {
    VectorJet x = d(t);
    for (auto& c : x)
      for (double& y : c) y = -y;
    return x;
  };
  EXPECT_GT(vertex_closure(v, 0.5).error, 0.1);
}

}}  // namespace
}  // namespace rigidfold::sorce
