// Vertex loop closure: residual (SO(3) log) and its exact Jacobian.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <stdexcept>

#include "kernel/vertex/vertex_closure.hpp"
#include "tests/vertex/vertex_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using test::as_span;
using test::uniform;

// Central differences of the residual, column by column.
Eigen::Matrix3Xd finite_difference_jacobian(const std::vector<double>& sectors,
                                            std::vector<double> folds, double h) {
  Eigen::Matrix3Xd J(3, static_cast<Eigen::Index>(folds.size()));
  for (std::size_t i = 0; i < folds.size(); ++i) {
    const double f = folds[i];
    folds[i] = f + h;
    const Eigen::Vector3d rp = vertex_closure_residual(as_span(sectors), as_span(folds));
    folds[i] = f - h;
    const Eigen::Vector3d rm = vertex_closure_residual(as_span(sectors), as_span(folds));
    folds[i] = f;
    J.col(static_cast<Eigen::Index>(i)) = (rp - rm) / (2.0 * h);
  }
  return J;
}

// Max entry error relative to max(1, max |J|).
double relative_jacobian_error(const std::vector<double>& sectors,
                               const std::vector<double>& folds) {
  Eigen::Vector3d r;
  Eigen::Matrix3Xd J;
  vertex_closure_jacobian(as_span(sectors), as_span(folds), r, J);
  const Eigen::Matrix3Xd Jfd = finite_difference_jacobian(sectors, folds, 1e-5);
  return (J - Jfd).cwiseAbs().maxCoeff() / std::max(1.0, J.cwiseAbs().maxCoeff());
}

TEST(VertexClosure, JacobianMatchesCentralDifferencesOnRandomVertices) {
  std::mt19937_64 rng(20240611);
  int tested = 0, large = 0;
  double worst = 0.0;
  while (tested < 600) {
    const int n = 3 + static_cast<int>(rng() % 6);  // degree 3..8
    std::vector<double> sectors(n), folds(n);
    // Half the vertices have paper-like sectors in (0, pi), half arbitrary reals (twists
    // beyond pi, negative ones); none is developable by construction.
    const bool paper_like = tested % 2 == 0;
    for (int i = 0; i < n; ++i) {
      sectors[i] = paper_like ? uniform(rng, 0.05, kPi - 0.05) : uniform(rng, -7.0, 7.0);
      folds[i] = uniform(rng, -kPi, kPi);
    }
    const double angle = vertex_closure_residual(as_span(sectors), as_span(folds)).norm();
    if (angle > kPi - 0.05) continue;  // the log's branch cut: not differentiable there
    large += angle > 2.5;
    const double err = relative_jacobian_error(sectors, folds);
    worst = std::max(worst, err);
    EXPECT_LE(err, 1e-7) << "degree " << n << ", |r| = " << angle;
    ++tested;
  }
  EXPECT_GT(large, 20) << "large rotations must be part of the sample";
  RecordProperty("worst_relative_error", std::to_string(worst));
}

TEST(VertexClosure, JacobianMatchesCentralDifferencesNearIdentity) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + trial % 6;
    std::vector<double> sectors(n), folds(n);
    for (int i = 0; i < n; ++i) {
      sectors[i] = uniform(rng, -4.0, 4.0);
      folds[i] = uniform(rng, -kPi, kPi);
    }
    test::close_loop(sectors, folds);
    const double eps = std::pow(10.0, -3.0 - (trial % 6));  // 1e-3 .. 1e-8
    for (double& f : folds) f += uniform(rng, -eps, eps);
    const double angle = vertex_closure_residual(as_span(sectors), as_span(folds)).norm();
    EXPECT_LT(angle, 50 * eps);
    EXPECT_LE(relative_jacobian_error(sectors, folds), 1e-7) << "degree " << n;
  }
}

TEST(VertexClosure, JacobianAtClosureIsTheCreaseAxes) {
  // At r = 0, Jl^{-1} = I: column i is crease i's axis in the vertex frame, a unit vector,
  // and the sector after crease i rises toward +z for rho_i > 0 (valley).
  const std::vector<double> sectors = {1.0, 2.0, 1.5, 2 * kPi - 4.5};
  const std::vector<double> folds = {0.0, 0.0, 0.0, 0.0};
  Eigen::Vector3d r;
  Eigen::Matrix3Xd J, U;
  vertex_closure_jacobian(as_span(sectors), as_span(folds), r, J, &U);
  EXPECT_LE(r.norm(), 1e-15);
  EXPECT_LE((J - U).cwiseAbs().maxCoeff(), 1e-15);
  double angle = 0.0;
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(U(0, i), std::cos(angle), 1e-15);
    EXPECT_NEAR(U(1, i), std::sin(angle), 1e-15);
    EXPECT_NEAR(U(2, i), 0.0, 1e-15);
    angle += sectors[i];
  }
  // Valley fold of crease 0 lifts crease 1 (which bounds the sector after crease 0) to z > 0.
  const std::vector<double> valley = {0.3, 0.0, 0.0, 0.0};
  vertex_closure_jacobian(as_span(sectors), as_span(valley), r, J, &U);
  EXPECT_GT(U(2, 1), 0.0);
}

TEST(VertexClosure, ResidualVanishesOnKnownClosedConfigurations) {
  // Flat state of developable vertices.
  std::mt19937_64 rng(3);
  for (int n = 1; n <= 8; ++n) {
    std::vector<double> sectors(n), folds(n, 0.0);
    double sum = 0.0;
    for (int i = 0; i + 1 < n; ++i) {
      sectors[i] = uniform(rng, 0.1, 2 * kPi / n);
      sum += sectors[i];
    }
    sectors[n - 1] = 2 * kPi - sum;
    EXPECT_LE(vertex_closure_residual(as_span(sectors), as_span(folds)).norm(), 1e-14);
  }
  // Degree 2, a straight crease: any common fold angle closes.
  for (double t : {-kPi, -2.0, -1e-9, 0.5, 3.0, kPi}) {
    const std::array<double, 2> sectors = {kPi, kPi};
    const std::array<double, 2> folds = {t, t};
    EXPECT_LE(vertex_closure_residual(as_span(sectors), as_span(folds)).norm(), 1e-15);
    const std::array<double, 2> bent = {t, t + 1e-3};
    EXPECT_NEAR(vertex_closure_residual(as_span(sectors), as_span(bent)).norm(), 1e-3, 1e-12);
  }
  // Cube corner: three right-angled sectors, every crease folded by pi/2, either sign.
  for (double sign : {1.0, -1.0}) {
    const std::array<double, 3> sectors = {kPi / 2, kPi / 2, kPi / 2};
    const std::array<double, 3> folds = {sign * kPi / 2, sign * kPi / 2, sign * kPi / 2};
    EXPECT_LE(vertex_closure_residual(as_span(sectors), as_span(folds)).norm(), 1e-15);
  }
  // Degree 4 folded completely flat (Miura-like, rho = +-pi).
  {
    const double a = 1.1;
    const std::array<double, 4> sectors = {a, a, kPi - a, kPi - a};
    const std::array<double, 4> folds = {-kPi, kPi, -kPi, -kPi};
    EXPECT_LE(vertex_closure_residual(as_span(sectors), as_span(folds)).norm(), 1e-14);
  }
  // Random vertices closed by construction (x-z-x completion).
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 3 + trial % 6;
    std::vector<double> sectors(n), folds(n);
    for (int i = 0; i < n; ++i) {
      sectors[i] = uniform(rng, -4.0, 4.0);
      folds[i] = uniform(rng, -kPi, kPi);
    }
    test::close_loop(sectors, folds);
    EXPECT_LE(vertex_closure_residual(as_span(sectors), as_span(folds)).norm(), 1e-13);
  }
}

TEST(VertexClosure, RejectsMismatchedSizes) {
  const std::vector<double> sectors = {1.0, 2.0, 3.0};
  const std::vector<double> folds = {0.0, 0.0};
  EXPECT_THROW(vertex_loop_product(as_span(sectors), as_span(folds)), std::invalid_argument);
  EXPECT_THROW(vertex_closure_residual({}, {}), std::invalid_argument);
}

TEST(VertexSo3Log, RecoversRotationVectorAcrossAllAngles) {
  std::mt19937_64 rng(11);
  const std::vector<double> angles = {0.0,         1e-300,        1e-12,     1e-8,
                                      1e-3,        0.0999,        0.1001,    1.0,
                                      kPi / 2 - 1e-9, kPi / 2 + 1e-9, 2.0, 3.0,
                                      kPi - 1e-3,  kPi - 1e-6,    kPi - 1e-9};
  for (double t : angles) {
    for (int k = 0; k < 20; ++k) {
      const Eigen::Vector3d axis = Eigen::Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1),
                                                   uniform(rng, -1, 1)).normalized();
      const Eigen::Matrix3d R = Eigen::AngleAxisd(t, axis).toRotationMatrix();
      const Eigen::Vector3d phi = so3_log(R);
      EXPECT_LE((phi - t * axis).norm(), 1e-14 + 1e-15 * t) << "angle " << t;
    }
  }
  // At exactly pi the axis sign is free; either is a valid log.
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Vector3d phi = so3_log(Eigen::AngleAxisd(kPi, axis).toRotationMatrix());
  EXPECT_NEAR(phi.norm(), kPi, 1e-14);
  EXPECT_NEAR(std::abs(phi.normalized().dot(axis)), 1.0, 1e-14);
}

TEST(VertexSo3Log, LeftJacobianInverseIsAccurateAroundSeriesSwitch) {
  // Reference coefficient 1/t^2 - cot(t/2)/(2t) in long double (64-bit mantissa), which
  // survives the cancellation for t >= 0.01; the kernel switches to a series below t = 0.1.
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.4, 0.866).normalized();
  for (double t : {0.01, 0.05, 0.1 - 1e-12, 0.1 + 1e-12, 0.2, 1.0, 3.0}) {
    const long double tl = t;
    const long double coeff = 1.0L / (tl * tl) - std::cos(tl / 2) / (2 * tl * std::sin(tl / 2));
    const Eigen::Vector3d phi = t * axis;
    Eigen::Matrix3d K;
    K << 0, -phi.z(), phi.y(), phi.z(), 0, -phi.x(), -phi.y(), phi.x(), 0;
    const Eigen::Matrix3d expected =
        Eigen::Matrix3d::Identity() - 0.5 * K + static_cast<double>(coeff) * K * K;
    EXPECT_LE((so3_left_jacobian_inverse(phi) - expected).cwiseAbs().maxCoeff(), 1e-15) << t;
  }
  // Inverse of the left Jacobian Jl = I + (1-cos t)/t^2 K + (t - sin t)/t^3 K^2.
  for (double t : {1e-6, 0.05, 0.5, 2.0, 3.1}) {
    const Eigen::Vector3d phi = t * axis;
    Eigen::Matrix3d K;
    K << 0, -phi.z(), phi.y(), phi.z(), 0, -phi.x(), -phi.y(), phi.x(), 0;
    const Eigen::Matrix3d Jl = Eigen::Matrix3d::Identity() + (1 - std::cos(t)) / (t * t) * K +
                               (t - std::sin(t)) / (t * t * t) * K * K;
    const Eigen::Matrix3d prod = so3_left_jacobian_inverse(phi) * Jl;
    EXPECT_LE((prod - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-9) << t;
  }
}

}}  // namespace
}  // namespace rigidfold
