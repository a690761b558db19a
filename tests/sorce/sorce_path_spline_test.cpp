// C^3 path splines (design/sorce/sorce_path_spline.hpp) against a closed form: the minor fold
// of the seed's vertex A (sectors 120, 80, 60, 100 deg) on eq 25, gamma_1 = 2 atan(tan(pi t/2)
// / mu), sampled like a trace (equal steps of the driving major fold gamma_2 = pi t).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "design/sorce/sorce_path_spline.hpp"
#include "design/sorce/sorce_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

const VertexSectors kVertexA = {to_radians(120.0), to_radians(80.0), to_radians(60.0), to_radians(100.0)};

// Largest error of value and derivatives 1-3 over a fine grid of t in [0, 1].
std::array<double, 4> spline_errors(int intervals) {
  const auto gamma = vertex_fold_angles(kVertexA, VertexParameterization::kMajorLinear);
  std::vector<double> values;
  for (int k = 0; k <= intervals; ++k) values.push_back(gamma[0](static_cast<double>(k) / intervals)[0]);
  const ScalarFunction spline = quintic_spline(values);
  std::array<double, 4> err{};
  for (int i = 0; i <= 2000; ++i) {
    const double t = i / 2000.0;
    const Jet s = spline(t), exact = gamma[0](t);
    for (int m = 0; m < 4; ++m) err[m] = std::max(err[m], std::abs(s[m] - exact[m]));
  }
  return err;
}

TEST(SorcePathSpline, InterpolatesAndReproducesQuintics) {
  std::vector<double> values;
  const int n = 10;
  auto p = [](double t) { return 0.3 * t - 1.2 * t * t + 0.7 * std::pow(t, 5); };
  for (int k = 0; k <= n; ++k) values.push_back(p(static_cast<double>(k) / n));
  const ScalarFunction s = quintic_spline(values);
  for (int k = 0; k <= n; ++k) EXPECT_NEAR(s(static_cast<double>(k) / n)[0], values[k], 1e-14);
  // A quintic is reproduced with its derivatives (the end conditions are exact for it).
  for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const Jet j = s(t);
    EXPECT_NEAR(j[0], p(t), 1e-13);
    EXPECT_NEAR(j[1], 0.3 - 2.4 * t + 3.5 * std::pow(t, 4), 1e-11);
    EXPECT_NEAR(j[2], -2.4 + 14.0 * std::pow(t, 3), 1e-9);
    EXPECT_NEAR(j[3], 42.0 * t * t, 1e-7);
  }
}

TEST(SorcePathSpline, ContinuousThirdDerivativeAcrossKnots) {
  std::vector<double> values;
  for (int k = 0; k <= 12; ++k) values.push_back(std::sin(3.0 * k / 12.0) + (k % 3) * 1e-3);
  const ScalarFunction s = quintic_spline(values);
  for (int k = 1; k < 12; ++k) {
    const double t = k / 12.0;
    const Jet a = s(t - 1e-12), b = s(t + 1e-12);
    for (int m = 0; m < 4; ++m) EXPECT_NEAR(a[m], b[m], 1e-6 * (1.0 + std::abs(a[m]))) << k << " " << m;
  }
}

// Measured (Release), max over t in [0, 1] of |spline - exact| for value and derivatives 1-3:
//   N = 20: 1.2e-04, 1.8e-02, 1.8e+00, 9.9e+01
//   N = 40: 9.9e-07, 3.3e-04, 7.1e-02, 8.8e+00
//   N = 80: 9.7e-09, 6.1e-06, 2.5e-03, 5.9e-01
// (the minor fold's derivatives are large near t = 1: its third derivative reaches ~ (mu pi)^3 ~ 7e2
// there, mu = 2.88), i.e. orders ~7, 5.7, 4.8, 3.9 per halving, the quintic spline's 6, 5, 4, 3 or better.
TEST(SorcePathSpline, ConvergesToTheVertexClosedForm) {
  const std::array<double, 4> e20 = spline_errors(20), e40 = spline_errors(40), e80 = spline_errors(80);
  const std::array<double, 4> bound40 = {2e-6, 7e-4, 0.15, 18.0};
  for (int m = 0; m < 4; ++m) {
    std::printf("derivative %d: N=20 %.2e  N=40 %.2e  N=80 %.2e\n", m, e20[m], e40[m], e80[m]);
    EXPECT_LE(e40[m], bound40[m]) << m;
    // Halving the step divides the error by at least 2^3 (the third derivative's order).
    EXPECT_LT(e40[m], e20[m] / 8.0) << m;
    EXPECT_LT(e80[m], e40[m] / 8.0) << m;
  }
}

TEST(SorcePathSpline, RejectsTooFewOrNonFiniteValues) {
  EXPECT_THROW(quintic_spline(std::vector<double>(7, 0.0)), InputError);
  std::vector<double> v(9, 0.0);
  v[4] = std::nan("");
  EXPECT_THROW(quintic_spline(v), InputError);
}

}}  // namespace
}  // namespace rigidfold::sorce
