// Double-corrugated metamaterial elements 1-3 (seed 003 §3.2.3, eqs. 3-24 ... 3-28): the
// seed's spherical-trigonometry chains against an independent vector construction of the
// same vertex (creases as 3D vectors, dihedral by rotation), element 2 as element 1 doubled,
// the automatic derivatives against central differences, the Poisson's ratios (3-28) from
// them, and the height maximum with the sign change of nu_out there.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "design/metamaterial/corrugated_elements.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;
using E = CorrugatedElement;

struct VectorDims {
  double W, L, H;
};

// Element 1 from vectors: A2 at the origin, crease A2B2 along x, A2A1 at the angle pi - beta
// from it in the xy plane, A2A3 at the angle alpha from it, turned out of the xy plane so
// that the dihedral at A2B2 (between the half-planes of A1 and A3) is phi. Base plane:
// through A2, A1, A3. W = |A1 A3|, H = distance of B2 from the base plane, L = 2 x the
// length of the projection of A2B2 on the bisector of A1 A2 A3.
VectorDims element1_by_vectors(double alpha, double beta, double l, double phi) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d b2 = l * x;
  const Eigen::Vector3d a1 = l * (-std::cos(beta) * x + std::sin(beta) * y);
  const Eigen::Vector3d a3 = l * (std::cos(alpha) * x + std::sin(alpha) * (std::cos(phi) * y + std::sin(phi) * z));
  const Eigen::Vector3d n = a1.cross(a3).normalized(), bisector = (a1 + a3).normalized();
  return {(a1 - a3).norm(), 2 * std::fabs(bisector.dot(b2)), std::fabs(n.dot(b2))};
}

// Element 3 from vectors: B5 at the origin, B5B4 along x, B5A5 at beta from it, B5C5 at
// alpha from it with dihedral theta at B4B5. L = |A5 C5|, H = 2 x the distance of B4 from the
// plane A5 B5 C5, W = 4 x the length of the projection of B5B4 on the bisector of A5 B5 C5.
VectorDims element3_by_vectors(double alpha, double beta, double l, double theta) {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d b4 = l * x;
  const Eigen::Vector3d a5 = l * (std::cos(beta) * x + std::sin(beta) * y);
  const Eigen::Vector3d c5 = l * (std::cos(alpha) * x + std::sin(alpha) * (std::cos(theta) * y + std::sin(theta) * z));
  const Eigen::Vector3d n = a5.cross(c5).normalized(), bisector = (a5 + c5).normalized();
  return {4 * std::fabs(bisector.dot(b4)), (a5 - c5).norm(), 2 * std::fabs(n.dot(b4))};
}

// Element 3 with alpha + beta = pi: (3-26) pins theta at 0 (cos((alpha + beta)/2) = 0), the
// element does not move and its dimensions are 0/0.
bool locked(const CorrugatedElementParams& p) { return std::fabs(std::cos((p.alpha + p.beta) / 2)) < 1e-12; }

std::vector<double> angles() { return {0.4, 0.8, 1.2, kPi / 2, 2.0, 2.6}; }

TEST(MetamaterialCorrugatedElements, SeedChainsMatchVectorConstruction) {
  double worst = 0;
  for (double alpha : angles())
    for (double beta : angles())
      for (double l : {1.0, 0.7}) {
        const CorrugatedElementParams p{alpha, beta, l};
        for (int k = 1; k < 60; ++k) {
          const double phi = kPi * k / 60;
          const auto e1 = corrugated_element(E::kElement1, p, phi);
          const auto v1 = element1_by_vectors(alpha, beta, l, phi);
          worst = std::max({worst, std::fabs(e1.W - v1.W), std::fabs(e1.L - v1.L), std::fabs(e1.H - v1.H)});
          const auto e2 = corrugated_element(E::kElement2, p, phi);
          EXPECT_EQ(e2.W, e1.W);
          EXPECT_EQ(e2.L, 2 * e1.L);
          EXPECT_EQ(e2.H, 2 * e1.H);
          ASSERT_TRUE(std::isfinite(e1.W) && std::isfinite(e1.L) && std::isfinite(e1.H));
          if (locked(p)) continue;
          const auto e3 = corrugated_element(E::kElement3, p, phi);
          ASSERT_TRUE(std::isfinite(e3.W) && std::isfinite(e3.L) && std::isfinite(e3.H));
          const auto v3 = element3_by_vectors(alpha, beta, l, e3.theta);
          worst = std::max({worst, std::fabs(e3.W - v3.W), std::fabs(e3.L - v3.L), std::fabs(e3.H - v3.H)});
          // (3-26) is a tan-half ratio between the two dihedrals.
          EXPECT_NEAR(std::tan(e3.theta / 2) / std::tan(phi / 2),
                      std::cos((beta + alpha) / 2) / std::cos((beta - alpha) / 2), 1e-12 * std::max(1.0, std::tan(e3.theta / 2)));
        }
        // Flat (phi = pi): element 1's base angle is the sum of its sectors, pi - beta + alpha.
        const auto flat = corrugated_element(E::kElement1, p, kPi);
        EXPECT_NEAR(flat.W, 2 * l * std::sin((kPi - beta + alpha) / 2), 1e-7);
      }
  EXPECT_LE(worst, 1e-12);
  {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_vector_difference", text);
  }
}

// Automatic derivatives against the 5-point central difference (h = 1e-4, truncation
// h^4/30 |f^(5)|, round-off ~1e-16 |f| / h ~ 1e-12; kept 0.2 rad from the ends, where the
// derivatives blow up, and skipping points where a dimension is near 0, where |.| has a
// kink). Measured worst relative difference 4e-10; bound 1e-8.
TEST(MetamaterialCorrugatedElements, DerivativesMatchCentralDifferencesAndPoissonRatiosFollow) {
  const double h = 1e-4;
  double worst = 0;
  for (double alpha : angles())
    for (double beta : angles())
      for (E e : {E::kElement1, E::kElement2, E::kElement3}) {
        const CorrugatedElementParams p{alpha, beta, 1.0};
        if (e == E::kElement3 && locked(p)) continue;
        for (int k = 0; k <= 50; ++k) {
          const double phi = 0.2 + (kPi - 0.4) * k / 50;
          const auto s = corrugated_element(e, p, phi);
          const auto sp = corrugated_element(e, p, phi + h), sm = corrugated_element(e, p, phi - h);
          const auto sp2 = corrugated_element(e, p, phi + 2 * h), sm2 = corrugated_element(e, p, phi - 2 * h);
          ASSERT_TRUE(std::isfinite(s.nu_in) && std::isfinite(s.nu_out)) << alpha << " " << beta << " " << phi;
          if (std::min({s.W, s.L, s.H, sp2.W, sp2.L, sp2.H, sm2.W, sm2.L, sm2.H}) < 1e-3) continue;
          if (std::min({sp.W, sp.L, sp.H, sm.W, sm.L, sm.H}) < 1e-3) continue;
          auto check = [&](double d, double fp, double fm, double fp2, double fm2) {
            const double fd = (8 * (fp - fm) - (fp2 - fm2)) / (12 * h);
            worst = std::max(worst, std::fabs(fd - d) / std::max(1.0, std::fabs(d)));
          };
          check(s.dW, sp.W, sm.W, sp2.W, sm2.W);
          check(s.dL, sp.L, sm.L, sp2.L, sm2.L);
          check(s.dH, sp.H, sm.H, sp2.H, sm2.H);
          EXPECT_NEAR(s.nu_in, -(s.dL / s.L) / (s.dW / s.W), 1e-12 * std::max(1.0, std::fabs(s.nu_in)));
          EXPECT_NEAR(s.nu_out, -(s.dH / s.H) / (s.dW / s.W), 1e-12 * std::max(1.0, std::fabs(s.nu_out)));
        }
      }
  EXPECT_LE(worst, 1e-8);
  {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_fd_relative", text);
  }
}

// Height maximum: H rises from the flat state (phi = pi) and falls again; the stationary
// point found by TOMS 748 is the grid maximum, elements 1 and 2 share it (seed: metamaterials
// (a) to (c) reach the maximum height at the same phi) with element 2 twice as high, and
// nu_out changes sign there (dW/dphi keeps its sign through it).
TEST(MetamaterialCorrugatedElements, HeightMaximumAndNuOutSignChange) {
  int found = 0;
  for (double alpha : angles())
    for (double beta : angles())
      for (E e : {E::kElement1, E::kElement3}) {
        const CorrugatedElementParams p{alpha, beta, 1.0};
        if (e == E::kElement3 && locked(p)) continue;
        // Scan for the sign change of dH/dphi from + (small phi) to - (large phi).
        int changes = 0;
        double lo = 0, hi = 0, grid_max = 0;
        double prev_phi = 0.02, prev = corrugated_element(e, p, prev_phi).dH;
        for (int k = 1; k <= 400; ++k) {
          const double phi = 0.02 + (kPi - 0.04) * k / 400;
          const auto s = corrugated_element(e, p, phi);
          grid_max = std::max(grid_max, s.H);
          if (prev > 0 && s.dH < 0) {
            ++changes;
            lo = prev_phi;
            hi = phi;
          }
          prev = s.dH;
          prev_phi = phi;
        }
        if (changes != 1) continue;
        ++found;
        const auto m = corrugated_height_maximum(e, p, lo, hi);
        const auto at = corrugated_element(e, p, m.phi);
        EXPECT_LE(std::fabs(at.dH), 1e-12);
        EXPECT_GE(m.height, grid_max - 1e-15);
        const auto before = corrugated_element(e, p, m.phi - 1e-4), after = corrugated_element(e, p, m.phi + 1e-4);
        if (before.dW * after.dW > 0) {
          EXPECT_LT(before.nu_out * after.nu_out, 0.0);
        }
        if (e == E::kElement1) {
          const auto m2 = corrugated_height_maximum(E::kElement2, p, lo, hi);
          EXPECT_NEAR(m2.phi, m.phi, 1e-12);
          EXPECT_NEAR(m2.height, 2 * m.height, 1e-14);
        }
      }
  EXPECT_GT(found, 20);
}

TEST(MetamaterialCorrugatedElements, BadInputsThrow) {
  EXPECT_THROW(corrugated_element(E::kElement1, {0.0, 1.0, 1.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(corrugated_element(E::kElement1, {1.0, kPi, 1.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(corrugated_element(E::kElement1, {1.0, 1.0, 0.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(corrugated_element(E::kElement3, {1.0, 1.0, 1.0}, -0.1), std::invalid_argument);
  EXPECT_THROW(corrugated_height_maximum(E::kElement1, {1.0, 1.0, 1.0}, 2.0, 1.0), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold::metamaterial
