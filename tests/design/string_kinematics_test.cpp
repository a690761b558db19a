// Miura string: closed-form vertex against geometry and the general loop-closure solver,
// transmission of the driven crease, pattern layout and folded spine.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "design/strings/miura_string.hpp"
#include "design/strings/string_kinematics.hpp"
#include "design/strings/string_verify.hpp"
#include "design/strings/string_vertex.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold::design {
namespace { namespace RIGIDFOLD_UNITY_ID {


MiuraString random_string(int n, std::uint64_t seed) { return random_miura_string(n, seed, to_radians(35), to_radians(75), 0.9); }

double min_limit(const MiuraString& s) {
  double m = 10;
  for (int i = 0; i < s.size(); ++i) m = std::min(m, string_theta_limit(s.alpha1[i], s.alpha2[i]));
  return m;
}

TEST(StringVertex, ClosesTheLoopAndMatchesTheSeedFormulas) {
  // Paper's example alpha1 = 30, alpha2 = 60 deg, and other vertices over their range.
  for (const auto& [a1d, a2d] : {std::pair{30.0, 60.0}, {60.0, 30.0}, {45.0, 45.0}, {20.0, 70.0}, {80.0, 50.0}}) {
    const double a1 = to_radians(a1d), a2 = to_radians(a2d);
    const double lim = string_theta_limit(a1, a2);
    for (double frac : {-0.99, -0.5, -1e-6, 1e-9, 0.1, 0.5, 0.9, 0.999}) {
      const double th = frac * lim;
      const StringVertexState v = string_vertex_state(a1, a2, th);
      // Loop closure in the kernel's convention, creases CCW from a: a, b, c, d with
      // sectors alpha1, pi - alpha1, pi - alpha2, alpha2. Edge orientation: a and b point
      // away from the vertex (as in the kernel's fan), c points toward it (its FOLD sign
      // is the same either way: reversing an edge swaps left/right and the axis).
      const std::vector<double> sectors{a1, std::numbers::pi - a1, std::numbers::pi - a2, a2};
      const std::vector<double> rho{v.rho_a, v.rho_b, v.rho_c, v.rho_d};
      EXPECT_LT(vertex_closure_residual(sectors, rho).norm(), 1e-13) << a1d << " " << a2d << " " << th;
      // Transmission: theta_out = -theta exactly (to rounding).
      EXPECT_NEAR(v.theta_out, -th, 1e-14);
      EXPECT_NEAR(v.rho_a, -2 * th, 1e-14);
      // phi, psi from the seed's eq. (38)-(39) with the docs/DESIGN.md corrections.
      const double K1 = (1 / std::tan(a1) + 1 / std::tan(a2)) / 2, K2 = (1 / std::tan(a1) - 1 / std::tan(a2)) / 2;
      if (std::fabs(th) > 1e-3) {
        const double K3 = std::pow(K2 / std::cos(th), 2) + std::pow(K1 / std::sin(th), 2);
        EXPECT_NEAR(v.phi, std::atan2(2 * K1 / std::sin(th), K3 - 1), 1e-12);
        EXPECT_NEAR(v.psi, std::atan(2 * K2 / std::cos(th) / (K3 - 1)), 1e-12);
      }
      // The outgoing direction keeps the sector angles: a.b = cos a1, a.d = cos a2.
      const Eigen::Vector3d a = v.rotation.col(0);
      EXPECT_NEAR(a.dot(Eigen::Vector3d(std::cos(a1), std::sin(a1) * std::cos(th), std::sin(a1) * std::sin(th))), std::cos(a1), 1e-14);
      EXPECT_NEAR(a.dot(Eigen::Vector3d(std::cos(a2), -std::sin(a2) * std::cos(th), std::sin(a2) * std::sin(th))), std::cos(a2), 1e-14);
      EXPECT_LT((v.rotation.transpose() * v.rotation - Eigen::Matrix3d::Identity()).norm(), 1e-14);
      EXPECT_NEAR(v.rotation.determinant(), 1.0, 1e-14);
    }
  }
}

TEST(StringVertex, TemplatedFrameAgreesWithTheKernelClosedForm) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> alpha(to_radians(2), to_radians(88)), frac(-0.999, 0.999);
  for (int k = 0; k < 1000; ++k) {
    const double a1 = alpha(rng), a2 = alpha(rng), th = frac(rng) * miura_theta_limit(a1, a2);
    double R[9], phi, psi;
    string_vertex_frame(a1, a2, th, R, &phi, &psi);
    const Eigen::Matrix3d K = miura_vertex_rotation(a1, a2, th);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(R[3 * r + c], K(r, c), 1e-12) << a1 << " " << a2 << " " << th;
    const MiuraVertexState m = miura_vertex(a1, a2, th);
    if (std::fabs(m.spinal_out.x()) > 1e-3) {  // psi jumps where a_x changes sign
      EXPECT_NEAR(phi, m.phi, 1e-12);
      EXPECT_NEAR(psi, m.psi, 1e-12);
    }
  }
}

TEST(StringVertex, ThetaLimitIsWhereAPeripheralCreaseFoldsFlat) {
  const double a1 = to_radians(30), a2 = to_radians(60);
  const double lim = string_theta_limit(a1, a2);
  EXPECT_NEAR(to_degrees(lim), 54.735610317245346, 1e-9);  // 90 - acos(1/3)/2
  const StringVertexState near = string_vertex_state(a1, a2, lim * (1 - 1e-9));
  EXPECT_NEAR(std::fabs(near.rho_b), std::numbers::pi, 1e-3);
  EXPECT_LT(std::fabs(string_vertex_state(a1, a2, 0.9 * lim).rho_b), std::numbers::pi - 0.1);
}

TEST(StringVertex, InverseRecoversTheAlphasForGivenTheta) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> alpha(to_radians(5), to_radians(85)), frac(-0.98, 0.98);
  for (int k = 0; k < 2000; ++k) {
    const double a1 = alpha(rng), a2 = alpha(rng), th = frac(rng) * string_theta_limit(a1, a2);
    if (std::fabs(th) < 1e-3) continue;
    const StringVertexState v = string_vertex_state(a1, a2, th);
    double b1, b2;
    ASSERT_TRUE(string_vertex_inverse(v.phi, v.psi, th, b1, b2));
    EXPECT_NEAR(b1, a1, 1e-10);
    EXPECT_NEAR(b2, a2, 1e-10);
  }
  // Outside the cone |angle from +-z| < |theta| there is no alpha in (0, 90).
  double b1, b2;
  EXPECT_FALSE(string_vertex_inverse_direction(Eigen::Vector3d(1, 0.3, -0.1), 0.4, b1, b2));
  EXPECT_TRUE(std::isnan(b1));
}

TEST(StringPattern, LayoutNumberingAndWidthLimit) {
  const MiuraString s = random_string(5, 3);
  const CreasePattern p = build_string_pattern(s);
  EXPECT_EQ(p.num_vertices(), 3 * 5 + 6);
  EXPECT_EQ(p.num_edges(), 3 * 5 + 1 + 2 * 5 + 6);
  EXPECT_EQ(p.num_faces(), 2 * 5 + 2);
  MiuraString wide = s;
  wide.width = 1.01 * max_string_width(s);
  EXPECT_THROW(build_string_pattern(wide), std::invalid_argument);
  MiuraString bad = s;
  bad.alpha2[2] = std::numbers::pi / 2;
  EXPECT_THROW(build_string_pattern(bad), std::invalid_argument);
  const std::string svg = string_pattern_svg(p);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("class=\"B\""), std::string::npos);
}

void expect_general_solver_agrees(int n, std::uint64_t seed, double frac) {
  const MiuraString s = random_string(n, seed);
  const double theta0 = frac * min_limit(s);
  const StringState st = string_forward(s, theta0);
  const CreasePattern p = build_string_pattern(s, st.edge_fold_angles);
  // Newton from a start 1e-3 rad away: the solver finds the closed form on its own.
  const StringVerification v = verify_string_with_general_solver(s, p, st, 1e-3);
  ASSERT_TRUE(v.converged) << "n=" << n;
  EXPECT_LE(v.closure_residual, 1e-12);
  EXPECT_LE(v.max_angle_error, 1e-10) << "n=" << n;
  // Spine points of the folded FOLD vs the closed-form chain (length ~1 per segment).
  EXPECT_LE(v.max_spine_error, 1e-10 * n) << "n=" << n;
  EXPECT_LE(v.placement_mismatch, 1e-10 * n);
}

TEST(StringKinematics, GeneralSolverAgreesWithClosedFormSingleVertex) {
  for (double frac : {-0.9, -0.3, 0.05, 0.5, 0.95}) expect_general_solver_agrees(1, 11, frac);
}

TEST(StringKinematics, GeneralSolverAgreesWithClosedForm100Vertices) {
  expect_general_solver_agrees(100, 5, 0.6);
  expect_general_solver_agrees(100, 6, -0.3);
}

TEST(StringKinematics, DrivenCreaseTransmitsWithAlternatingSign) {
  const MiuraString s = random_string(7, 9);
  const StringState st = string_forward(s, 0.3);
  for (int i = 0; i < 7; ++i) EXPECT_DOUBLE_EQ(st.theta[i], i % 2 ? -0.3 : 0.3);
  EXPECT_LE(st.shared_crease_mismatch, 1e-14);
  // Independent mode with equal thetas is not a motion of the connected sheet.
  const StringState ind = string_forward_independent(s, std::vector<double>(7, 0.3));
  EXPECT_NEAR(ind.shared_crease_mismatch, 1.2, 1e-12);
  EXPECT_THROW(string_forward(s, 1.5), std::invalid_argument);
}

TEST(StringKinematics, SpineSegmentsKeepTheirLengths) {
  const MiuraString s = random_string(20, 4);
  const StringState st = string_forward(s, 0.4);
  ASSERT_EQ(st.spine.size(), 22u);
  for (int k = 0; k <= 20; ++k) EXPECT_NEAR((st.spine[k + 1] - st.spine[k]).norm(), s.lengths[k], 1e-13);
}

}}  // namespace
}  // namespace rigidfold::design
