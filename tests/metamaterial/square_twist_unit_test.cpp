// Square-twist unit (seed 003 §3.3.2, eqs. 3-30 ... 3-32), closed forms only: the constraint
// (3-31) and its tan-half form, the analytic derivatives against central differences, the
// printed Poisson's ratios (3-32a, 3-32b) against the derivative definitions (and the garbled
// definition printed in 3-32b shown to be a different quantity), the height maximum (TOMS 748)
// against Brent's maximiser, and the sign change of nu_HL there. The independent check against
// the traced tessellation is in square_twist_tessellation_test.cpp.
#include <gtest/gtest.h>

#include <boost/math/tools/minima.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "design/metamaterial/square_twist_unit.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

// alpha = pi - t for the twist angles t = 15, 30, 45, 60, 75 deg (and the seed's 5 pi / 6).
std::vector<double> alphas() {
  std::vector<double> out;
  for (double t_deg : {15.0, 30.0, 45.0, 60.0, 75.0}) out.push_back(kPi - t_deg * kPi / 180);
  return out;
}

SquareTwistUnitParams params(double alpha, double a = 1.0, double b = 1.0, double c = 1.0) {
  SquareTwistUnitParams p;
  p.alpha = alpha;
  p.a = a;
  p.b = b;
  p.c = c;
  return p;
}

double constraint_3_31(double alpha, double theta, double phi) {
  return -std::cos(alpha) * std::cos(theta) + std::cos(alpha) * std::cos(phi) -
         std::sin(alpha) * std::sin(theta) * std::sin(phi);
}

TEST(MetamaterialSquareTwistUnit, ConstraintHoldsAndTanHalfRatioIsMu) {
  for (double alpha : alphas()) {
    const double mu = square_twist_mu(alpha);
    EXPECT_GT(mu, 0.0);
    EXPECT_LT(mu, 1.0);
    for (int k = 1; k < 200; ++k) {
      const double theta = kPi * k / 200;
      const double phi = square_twist_phi(alpha, theta);
      EXPECT_GE(phi, theta);  // mu < 1: theta is the smaller fold
      EXPECT_LE(phi, kPi);
      EXPECT_LE(std::fabs(constraint_3_31(alpha, theta, phi)), 2e-15) << alpha << " " << theta;
      EXPECT_NEAR(std::tan(theta / 2) / std::tan(phi / 2), mu, 1e-13 * std::max(1.0, std::tan(phi / 2)));
      EXPECT_NEAR(square_twist_theta(alpha, phi), theta, 1e-14);
    }
    EXPECT_EQ(square_twist_phi(alpha, 0.0), 0.0);
    EXPECT_NEAR(square_twist_phi(alpha, kPi), kPi, 1e-15);
  }
}

// Analytic d/dtheta against central differences (h = 1e-6: truncation h^2/6 |f'''| with
// |f'''| up to ~1/mu^3 ~ 440 at twist 75 deg, about 1e-10, and round-off ~1e-16 |f| / h,
// about 1e-10: both below the bound 1e-8).
TEST(MetamaterialSquareTwistUnit, AnalyticDerivativesMatchCentralDifferences) {
  const double h = 1e-6;
  double worst = 0;
  for (double alpha : alphas())
    for (double b : {0.6, 1.0, 2.0}) {
      const auto p = params(alpha, 1.3, b, 1.0);
      for (int k = 1; k < 100; ++k) {
        const double theta = kPi * k / 100;
        const auto u = square_twist_unit(p, theta);
        const auto up = square_twist_unit(p, std::min(theta + h, kPi));
        const auto um = square_twist_unit(p, theta - h);
        const double span = std::min(theta + h, kPi) - (theta - h);
        const double fd_phi = (up.phi - um.phi) / span, fd_L = (up.L - um.L) / span;
        const double fd_S = (up.S - um.S) / span, fd_H = (up.H - um.H) / span;
        worst = std::max({worst, std::fabs(fd_phi - u.dphi_dtheta), std::fabs(fd_L - u.dL), std::fabs(fd_S - u.dS),
                          std::fabs(fd_H - u.dH)});
        // Implicit differentiation of (3-31) as printed gives the same dphi/dtheta.
        EXPECT_NEAR(square_twist_dphi_dtheta_implicit(alpha, u.theta, u.phi), u.dphi_dtheta,
                    1e-11 * std::max(1.0, std::fabs(u.dphi_dtheta)));
      }
    }
  EXPECT_LE(worst, 1e-8);
  {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", worst);
    RecordProperty("worst_fd_difference", text);
  }
}

// (3-32a) and the right side of (3-32b), as printed, equal -(S/L) dL/dS and -(L/H) dH/dL
// from the analytic derivatives. The definition printed in (3-32b), "-(dH/L)/(dL/H)", equals
// -(H/L) dH/dL: a different number (off by (L/H)^2), so it is not what the right side says.
TEST(MetamaterialSquareTwistUnit, PrintedPoissonRatiosMatchDefinitionsAndGarbledOneDoesNot) {
  for (double alpha : alphas())
    for (double c : {1.0, 1.5, 3.0}) {  // L > 0 all along: 2c > sin(alpha) - cos(alpha)
      const auto p = params(alpha, 1.0, 1.0, c);
      int garbled_differs = 0;
      for (int k = 1; k < 100; ++k) {
        const double theta = kPi * k / 100;
        const auto u = square_twist_unit(p, theta);
        const double sl = square_twist_nu_SL_printed(p, u.theta, u.phi);
        const double hl = square_twist_nu_HL_printed(p, u.theta, u.phi);
        EXPECT_NEAR(sl, u.nu_SL, 1e-11 * std::max(1.0, std::fabs(sl))) << alpha << " " << theta;
        EXPECT_NEAR(hl, u.nu_HL, 1e-11 * std::max(1.0, std::fabs(hl))) << alpha << " " << theta;
        // Definitions from the strains directly.
        EXPECT_NEAR(u.nu_SL, -(u.dL / u.L) / (u.dS / u.S), 1e-12 * std::max(1.0, std::fabs(u.nu_SL)));
        EXPECT_NEAR(u.nu_HL, -(u.dH / u.H) / (u.dL / u.L), 1e-12 * std::max(1.0, std::fabs(u.nu_HL)));
        const double garbled = -(u.dH / u.L) / (u.dL / u.H);
        if (std::fabs(garbled - hl) > 1e-3 * std::max(1.0, std::fabs(hl))) ++garbled_differs;
        // The in-plane ratio is negative everywhere (seed: "always negative").
        EXPECT_LT(u.nu_SL, 0.0);
      }
      EXPECT_GT(garbled_differs, 90);
    }
}

// Stationary points of H: the analytic scan + TOMS 748 finds exactly the sign changes of an
// independent finite-difference scan of H itself; nu_HL changes sign at every one (from + to
// - at a maximum); the global maximum is the highest H on a fine grid and Brent's maximiser
// (Boost.Math, precision ~sqrt(eps) in theta) lands on it. For twists up to 60 deg H has one
// stationary point; at 75 deg three (maximum, minimum, higher maximum).
TEST(MetamaterialSquareTwistUnit, HeightStationaryPointsMaximumAndNuHLSignChanges) {
  for (double alpha : alphas())
    for (double c : {1.0, 1.5, 3.0}) {
      const auto p = params(alpha, 1.0, 1.0, c);
      const auto points = square_twist_height_stationary_points(p);
      const auto m = square_twist_height_maximum(p);
      EXPECT_EQ(m.stationary_points, static_cast<int>(points.size()));
      // Independent scan: sign changes of the central difference of H (no derivative formula).
      std::vector<double> scan;
      const int n = 20000;
      const double h = kPi / n;
      double prev = square_twist_unit(p, 2 * h).H - square_twist_unit(p, 0.0).H;
      double grid_max = 0;
      for (int k = 2; k < n; ++k) {
        const double d = square_twist_unit(p, (k + 1) * h).H - square_twist_unit(p, (k - 1) * h).H;
        if ((d > 0) != (prev > 0)) scan.push_back((k - 0.5) * h);
        prev = d;
        grid_max = std::max(grid_max, square_twist_unit(p, k * h).H);
      }
      ASSERT_EQ(scan.size(), points.size()) << alpha;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const auto& s = points[i];
        EXPECT_NEAR(s.theta, scan[i], 2 * h) << alpha;
        const auto at = square_twist_unit(p, s.theta);
        EXPECT_LE(std::fabs(at.dH), 1e-13) << alpha;
        EXPECT_LE(std::fabs(at.nu_HL), 1e-12) << alpha;
        EXPECT_NEAR(at.H, s.height, 1e-15);
        EXPECT_EQ(s.maximum, i % 2 == 0);  // dH > 0 at 0+: maxima and minima alternate
        for (double d : {1e-6, 1e-3}) {
          const double before = square_twist_unit(p, s.theta - d).nu_HL, after = square_twist_unit(p, s.theta + d).nu_HL;
          if (s.maximum) {
            EXPECT_GT(before, 0.0) << alpha << " " << d;
            EXPECT_LT(after, 0.0) << alpha << " " << d;
          } else {
            EXPECT_LT(before, 0.0) << alpha << " " << d;
            EXPECT_GT(after, 0.0) << alpha << " " << d;
          }
        }
        // Each stationary point lies where phi > pi/2 > theta.
        EXPECT_GT(s.phi, kPi / 2);
        EXPECT_LT(s.theta, kPi / 2);
      }
      EXPECT_GE(m.height, grid_max);
      const auto brent = boost::math::tools::brent_find_minima(
          [&](double th) { return -square_twist_unit(p, th).H; }, std::max(0.0, m.theta - 0.1),
          std::min(kPi, m.theta + 0.1), 40);
      EXPECT_NEAR(brent.first, m.theta, 1e-6);
      EXPECT_NEAR(-brent.second, m.height, 1e-13);
      const double t_deg = (kPi - alpha) * 180 / kPi;
      EXPECT_EQ(points.size(), t_deg < 70 ? 1u : 3u) << t_deg;
    }
}

TEST(MetamaterialSquareTwistUnit, BadInputsThrow) {
  EXPECT_THROW(square_twist_mu(kPi / 2), std::invalid_argument);
  EXPECT_THROW(square_twist_mu(kPi), std::invalid_argument);
  EXPECT_THROW(square_twist_mu(1.0), std::invalid_argument);
  EXPECT_THROW(square_twist_phi(2.5, -0.1), std::invalid_argument);
  EXPECT_THROW(square_twist_phi(2.5, kPi + 1e-9), std::invalid_argument);
  EXPECT_THROW(square_twist_unit(params(2.5, 0.0), 1.0), std::invalid_argument);
  EXPECT_THROW(square_twist_unit(params(2.5, 1.0, std::nan("")), 1.0), std::invalid_argument);
  EXPECT_THROW(square_twist_height_maximum(params(1.2)), std::invalid_argument);
  EXPECT_TRUE(std::isnan(square_twist_unit(params(2.5), 0.0).nu_SL));
}

}}  // namespace
}  // namespace rigidfold::metamaterial
