// SORCE (seed 002) folding paths and offset functions: the analytic degree-4 fold angles
// against the kernel's flat-foldable closed form and loop closure, and the exact jets
// against finite differences (interior) and analytic limits (ends).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "design/sorce/sorce_function.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::vertex_a_sectors;
using testing::vertex_b_sectors;

TEST(SorcePath, MultiplierIsEq23) {
  EXPECT_NEAR(fold_angle_multiplier(vertex_a_sectors()), std::sin(to_radians(100)) / std::sin(to_radians(20)), 1e-14);
  EXPECT_NEAR(fold_angle_multiplier(vertex_b_sectors()), std::sqrt(2.0), 1e-14);  // the OCR's "mu = 2"
  EXPECT_THROW(fold_angle_multiplier({1.0, 1.0, 1.0, 1.0}), InputError);           // not flat-foldable
}

// The seed's fold j is the kernel's crease j - 1: driving crease 1 (fold 2) with gamma_2(t),
// the kernel's closed form (mode kEqual13) must give all four gamma_j(t), and the four
// angles must close the vertex loop.
TEST(SorcePath, VertexFoldAnglesMatchKernelClosedFormAndClose) {
  for (const VertexSectors& s : {vertex_a_sectors(), vertex_b_sectors()}) {
    for (auto kind : {VertexParameterization::kMajorLinear, VertexParameterization::kSymmetric}) {
      for (double sign : {1.0, -1.0}) {
        const auto gamma = vertex_fold_angles(s, kind, sign);
        double worst = 0.0, worst_closure = 0.0;
        for (int k = 0; k <= 100; ++k) {
          const double t = k / 100.0;
          std::array<double, 4> g{};
          for (int j = 0; j < 4; ++j) g[j] = gamma[j](t)[0];
          const auto kernel = flat_fold_angles(s, FlatFoldMode::kEqual13, g[1], 1);
          for (int j = 0; j < 4; ++j) worst = std::max(worst, std::abs(kernel[j] - g[j]));
          worst_closure = std::max(worst_closure, vertex_closure_residual(s, g).norm());
        }
        EXPECT_LE(worst, 1e-12);
        EXPECT_LE(worst_closure, 1e-12);
        // Ends: flat at t = 0, flat-folded at t = 1 with folds 2, 4 of sign `sign`.
        EXPECT_EQ(gamma[1](0.0)[0], 0.0);
        EXPECT_NEAR(gamma[1](1.0)[0], sign * kPi, 1e-15);
        EXPECT_NEAR(std::abs(gamma[0](1.0)[0]), kPi, 1e-15);
      }
    }
  }
  // Vertex A: fold 3 is the odd (mountain) fold when folds 2, 4 are valleys (kernel odd crease 2).
  const auto g = vertex_fold_angles(vertex_a_sectors(), VertexParameterization::kMajorLinear);
  EXPECT_GT(g[0](0.5)[0], 0.0);
  EXPECT_LT(g[2](0.5)[0], 0.0);
  EXPECT_EQ(flat_fold_multipliers(vertex_a_sectors(), FlatFoldMode::kEqual13).odd_crease, 2);
}

// Central differences of the value and lower derivatives, at interior t only.
void expect_jet_matches_differences(const ScalarFunction& f, double tol) {
  const double h = 1e-5;
  for (double t : {0.05, 0.3, 0.5, 0.77, 0.95}) {
    const Jet a = f(t - h), b = f(t + h), c = f(t);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((b[k] - a[k]) / (2 * h), c[k + 1], tol * std::max(1.0, std::abs(c[k + 1]))) << "t " << t << " order " << k + 1;
  }
}

TEST(SorcePath, JetsMatchFiniteDifferencesInside) {
  expect_jet_matches_differences(tan_half_fold(1 / 2.879), 1e-8);
  expect_jet_matches_differences(tan_half_fold(-std::sqrt(std::sqrt(2.0))), 1e-8);
  expect_jet_matches_differences(circular_offset(0.1, tan_half_fold(1.7)), 1e-8);
  expect_jet_matches_differences(basis_offset(-1.5, {0.8, -0.3, 0.2}, seed_offset_bases()), 1e-8);
  const auto gamma = vertex_fold_angles(vertex_b_sectors(), VertexParameterization::kSymmetric);
  expect_jet_matches_differences(circular_split_offset(0.1, gamma[2], gamma[1]), 1e-8);
  const VectorFunction d = split_offset_along_half_angle(power_function(0.4, 2), gamma[2]);
  expect_jet_matches_differences([&](double t) { return d(t)[0]; }, 1e-8);
  expect_jet_matches_differences([&](double t) { return d(t)[1]; }, 1e-8);
}

// gamma = 2 atan(k tan(pi t/2)): gamma' = pi k / (cos^2 + k^2 sin^2) (of pi t / 2), so
// gamma'(0) = pi k and gamma'(1) = pi / k, and gamma''(0) = gamma''(1) = 0 (even about the
// ends); the jets must give these limits at the ends, where tan(pi/2) overflows.
TEST(SorcePath, TanHalfFoldEndsAreAnalyticLimits) {
  for (double k : {0.35, 1.0, 2.879, -1.4}) {
    const Jet a = tan_half_fold(k)(0.0), b = tan_half_fold(k)(1.0);
    EXPECT_EQ(a[0], 0.0);
    EXPECT_NEAR(a[1], kPi * k, 1e-13);
    EXPECT_NEAR(b[0], std::copysign(kPi, k), 1e-15);
    EXPECT_NEAR(b[1], kPi / k, 1e-12);
    EXPECT_NEAR(a[2], 0.0, 1e-12);
    EXPECT_NEAR(b[2], 0.0, 1e-11);
  }
}

TEST(SorcePath, BasisOffsetsKeepTheirEnds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 20; ++trial) {
    const double end = u(rng);
    const auto f = basis_offset(end, {u(rng), u(rng), u(rng)}, seed_offset_bases(trial % 2 ? 4.0 : 1.0));
    EXPECT_NEAR(f(0.0)[0], 0.0, 1e-15);
    EXPECT_NEAR(f(1.0)[0], end, 1e-14);
  }
  // With b = 0 it is the linear offset; a basis not vanishing at t = 1 is refused.
  const auto lin = basis_offset(0.5, {0.0, 0.0, 0.0}, seed_offset_bases());
  EXPECT_NEAR(lin(0.3)[0], 0.15, 1e-16);
  EXPECT_NEAR(lin(0.3)[1], 0.5, 1e-16);
  EXPECT_THROW(basis_offset(1.0, {1.0}, {Polynomial{{0.0, 1.0}}}), InputError);
  EXPECT_THROW(basis_offset(1.0, {1.0, 2.0}, {Polynomial{{0.0, 1.0, -1.0}}}), InputError);
}

// eq 69 is eq 67 simplified: d(t) u(gamma_3/2) = (R(gamma_3) - I)(0, -r (tan(g3/4) - tan(g2/4))).
TEST(SorcePath, CircularSplitOffsetIsEq67) {
  const auto gamma = vertex_fold_angles(vertex_b_sectors(), VertexParameterization::kSymmetric);
  const double r = 0.1;
  const VectorFunction d = split_offset_along_half_angle(circular_split_offset(r, gamma[2], gamma[1]), gamma[2]);
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0, g3 = gamma[2](t)[0], g2 = gamma[1](t)[0];
    const double a = -r * (std::tan(g3 / 4) - std::tan(g2 / 4));
    // (R - I)(0, a) = (-a sin g3, a (cos g3 - 1))
    EXPECT_NEAR(d(t)[0][0], -a * std::sin(g3), 1e-15);
    EXPECT_NEAR(d(t)[1][0], a * (std::cos(g3) - 1), 1e-15);
  }
  // d(1) = 4 r: the two halves stack two panel thicknesses apart (as eq 60's d(1) = 0.4).
  EXPECT_NEAR(circular_split_offset(r, gamma[2], gamma[1])(1.0)[0], 4 * r, 1e-15);
}

}}  // namespace
}  // namespace rigidfold::sorce
