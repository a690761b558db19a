// design/metamaterial/metamaterial_table: the sampled, checked table of a metamaterial unit.
// Cross-checks: the sign changes the table finds (refined between its own samples) against the
// closed forms' independent stationary-point scans (4096 intervals), the dimensions against
// (3-30) written out here, and the Poisson's ratios against finite differences of the table's
// own dimension columns (no analytic derivative involved).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "design/metamaterial/metamaterial_table.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

MetamaterialParams twist(double alpha_deg, int samples = 181) {
  MetamaterialParams p;
  p.unit = MetamaterialUnit::kSquareTwist;
  p.square_twist.alpha = to_radians(alpha_deg);
  p.samples = samples;
  return p;
}

// nu_HL changes sign (from + to -) exactly at the height maximum of square_twist_height_maximum,
// and at every other stationary point of H (alpha = 105 deg has three).
TEST(MetamaterialTable, SquareTwistNuHLSignChangeIsTheHeightMaximum) {
  double worst = 0;
  for (double alpha_deg : {95.0, 105.0, 120.0, 135.0, 150.0, 165.0, 175.0}) {
    const MetamaterialParams p = twist(alpha_deg);
    const MetamaterialTable t = metamaterial_table(p);
    const SquareTwistHeightMaximum m = square_twist_height_maximum(p.square_twist);
    ASSERT_TRUE(t.has_height_maximum) << alpha_deg;
    const auto stationary = square_twist_height_stationary_points(p.square_twist);
    // One maximum: the same fold. Two mirror-image maxima (95, 105 deg): the same height.
    if (stationary.size() == 1) {
      EXPECT_NEAR(t.height_maximum_fold, m.theta, 1e-9) << alpha_deg;
    }
    EXPECT_NEAR(t.height_maximum, m.height, 1e-12 * m.height) << alpha_deg;
    EXPECT_NEAR(square_twist_unit(p.square_twist, t.height_maximum_fold).H, m.height, 1e-12 * m.height) << alpha_deg;
    EXPECT_EQ(t.height_stationary_points, static_cast<int>(stationary.size())) << alpha_deg;
    int hl_changes = 0;
    for (const auto& c : t.sign_changes) {
      if (c.ratio == "nu_in") ADD_FAILURE() << "nu_SL changed sign at alpha " << alpha_deg;
      if (c.ratio != "nu_out") continue;
      ++hl_changes;
      EXPECT_EQ(c.kind, "zero");
      // The nearest stationary point of the independent scan.
      double best = INFINITY;
      bool maximum = false;
      for (const auto& s : stationary)
        if (std::fabs(s.theta - c.fold) < best) {
          best = std::fabs(s.theta - c.fold);
          maximum = s.maximum;
        }
      worst = std::max(worst, best);
      EXPECT_LE(best, 1e-9) << alpha_deg;
      EXPECT_EQ(c.negative_after, maximum) << alpha_deg;  // + -> - at a maximum
    }
    EXPECT_EQ(hl_changes, static_cast<int>(stationary.size())) << alpha_deg;
    EXPECT_LE(t.max_constraint_residual, kConstraintTolerance);
    EXPECT_LE(t.max_derivative_error, kDerivativeTolerance);
  }
  RecordProperty("worst_sign_change_vs_stationary_point_rad", std::to_string(worst));
}

// Rows against (3-30) written out, and the ratios against central differences of the table's
// own columns (spacing pi/20002: truncation ~h^2 f''' ~ 1e-8 relative).
TEST(MetamaterialTable, SquareTwistRowsMatchFormulasAndFiniteDifferencesOfColumns) {
  const MetamaterialParams p = twist(150.0, 20001);
  const MetamaterialTable t = metamaterial_table(p);
  ASSERT_EQ(t.rows.size(), 20001u);
  const double a = p.square_twist.a, b = p.square_twist.b, c = p.square_twist.c, al = p.square_twist.alpha;
  double worst_nu = 0;
  for (std::size_t k = 1; k + 1 < t.rows.size(); ++k) {
    const auto& r = t.rows[k];
    EXPECT_NEAR(r.x, 2 * c + a * (std::cos(al) + std::sin(al) * std::cos(r.fold)), 1e-14);
    EXPECT_NEAR(r.y, 2 * b + a * (std::cos(al) + std::sin(al) * std::cos(r.second_angle)), 1e-14);
    EXPECT_NEAR(r.H, a * std::sin(al) * (std::sin(r.fold) + std::sin(r.second_angle)), 1e-14);
    if (k % 50 || k < 200 || k + 200 > t.rows.size()) continue;  // away from the ends (steep)
    const auto &m = t.rows[k - 1], &q = t.rows[k + 1];
    const double dL = q.x - m.x, dS = q.y - m.y, dH = q.H - m.H;
    const double nu_sl = -(dL / r.x) / (dS / r.y), nu_hl = -(dH / r.H) / (dL / r.x);
    if (std::fabs(dH) > 1e-6 * std::fabs(dL))  // skip the zero of dH, where the relative error blows up
      worst_nu = std::max(worst_nu, std::fabs(nu_hl - r.nu_out) / std::max(1.0, std::fabs(r.nu_out)));
    worst_nu = std::max(worst_nu, std::fabs(nu_sl - r.nu_in) / std::max(1.0, std::fabs(r.nu_in)));
    EXPECT_LT(r.nu_in, 0.0);
  }
  EXPECT_LE(worst_nu, 1e-6);
  RecordProperty("worst_ratio_vs_column_differences", std::to_string(worst_nu));
}

// Elements: nu_out changes sign where corrugated_height_maximum finds the maximum (in phi),
// and elements 1 and 2 peak at the same fold (seed: "reach maximum height at the same folding
// angle"), element 2 twice as high.
TEST(MetamaterialTable, ElementsNuOutSignChangeIsTheHeightMaximum) {
  for (auto [al, be] : {std::pair{60.0, 70.0}, std::pair{45.0, 100.0}, std::pair{80.0, 50.0}}) {
    MetamaterialParams p;
    p.element = {to_radians(al), to_radians(be), 1.0};
    double fold1 = 0, h1 = 0;
    for (auto u : {MetamaterialUnit::kElement1, MetamaterialUnit::kElement2, MetamaterialUnit::kElement3}) {
      p.unit = u;
      const MetamaterialTable t = metamaterial_table(p);
      ASSERT_TRUE(t.has_height_maximum) << unit_name(u) << " " << al << " " << be;
      // Independent bracket for the closed form's own maximum: around the table's fold, in phi.
      const CorrugatedElement e = u == MetamaterialUnit::kElement1   ? CorrugatedElement::kElement1
                                  : u == MetamaterialUnit::kElement2 ? CorrugatedElement::kElement2
                                                                     : CorrugatedElement::kElement3;
      const double phi = kPi - t.height_maximum_fold;
      const CorrugatedHeightMaximum m = corrugated_height_maximum(e, p.element, phi - 0.05, phi + 0.05);
      EXPECT_NEAR(t.height_maximum_fold, kPi - m.phi, 1e-9);
      bool found = false;
      for (const auto& c : t.sign_changes)
        if (c.ratio == "nu_out" && std::fabs(c.fold - t.height_maximum_fold) <= 1e-9) found = true;
      EXPECT_TRUE(found) << unit_name(u);
      if (u == MetamaterialUnit::kElement1) fold1 = t.height_maximum_fold, h1 = t.height_maximum;
      if (u == MetamaterialUnit::kElement2) {
        EXPECT_NEAR(t.height_maximum_fold, fold1, 1e-9);
        EXPECT_NEAR(t.height_maximum, 2 * h1, 1e-12);
      }
    }
  }
}

// Scale-free: a unit of size 1e-300 or 1e300 gets the table it gets at size 1, scaled (the
// ratios, folds and sign changes identical).
TEST(MetamaterialTable, TinyAndHugeUnitsScale) {
  for (double scale : {1e-300, 1e300}) {
    MetamaterialParams p = twist(150.0), q = p;
    q.square_twist.a = q.square_twist.b = q.square_twist.c = scale;
    MetamaterialParams e, f;
    e.unit = f.unit = MetamaterialUnit::kElement3;
    f.element.l = scale;
    for (auto [u, v] : {std::pair{p, q}, std::pair{e, f}}) {
      const MetamaterialTable a = metamaterial_table(u), b = metamaterial_table(v);
      ASSERT_EQ(a.rows.size(), b.rows.size());
      for (std::size_t k = 0; k < a.rows.size(); ++k) {
        EXPECT_EQ(a.rows[k].nu_in, b.rows[k].nu_in);
        EXPECT_EQ(a.rows[k].nu_out, b.rows[k].nu_out);
        EXPECT_NEAR(b.rows[k].H / scale, a.rows[k].H, 1e-15 * a.rows[k].H);
        EXPECT_NEAR(b.rows[k].dx / scale, a.rows[k].dx, 1e-15 * std::fabs(a.rows[k].dx));
      }
      EXPECT_EQ(a.height_maximum_fold, b.height_maximum_fold);
      EXPECT_NEAR(b.height_maximum / scale, a.height_maximum, 1e-15 * a.height_maximum);
      ASSERT_EQ(a.sign_changes.size(), b.sign_changes.size());
    }
  }
}

// Element 1 with alpha = beta has L = 0 throughout (round-off): nu_in is undefined, not a
// run of sign changes of round-off noise; nu_out (H over W) keeps its height-maximum change.
TEST(MetamaterialTable, RatioOnAZeroDimensionIsUndefined) {
  MetamaterialParams p;
  p.unit = MetamaterialUnit::kElement1;
  p.element = {to_radians(50.0), to_radians(50.0), 1.0};
  const MetamaterialTable t = metamaterial_table(p);
  EXPECT_FALSE(t.nu_in_defined);
  EXPECT_TRUE(t.nu_out_defined);
  for (const auto& r : t.rows) EXPECT_TRUE(std::isnan(r.nu_in));
  for (const auto& c : t.sign_changes) EXPECT_EQ(c.ratio, "nu_out");
  p.element.beta = to_radians(70.0);
  EXPECT_TRUE(metamaterial_table(p).nu_in_defined);
}

TEST(MetamaterialTable, RefusesBadParameters) {
  MetamaterialParams p = twist(150.0, 2);
  EXPECT_THROW(metamaterial_table(p), std::invalid_argument);
  p = twist(80.0);
  EXPECT_THROW(metamaterial_table(p), std::invalid_argument);
  p.unit = MetamaterialUnit::kElement3;
  p.element = {to_radians(60.0), to_radians(120.0), 1.0};
  EXPECT_THROW(metamaterial_table(p), std::invalid_argument);
}

TEST(MetamaterialTable, CsvHasOneLinePerRowAndRoundTrips) {
  const MetamaterialTable t = metamaterial_table(twist(150.0, 11));
  const std::string csv = metamaterial_csv(t);
  EXPECT_EQ(csv.rfind("fold_deg,second_angle_deg,L,S,H,dL_per_rad,dS_per_rad,dH_per_rad,nu_SL,nu_HL,", 0), 0u);
  std::size_t lines = 0;
  for (char ch : csv) lines += ch == '\n';
  EXPECT_EQ(lines, 12u);
  // Third row, column H (index 4) reads back as the row's double.
  std::size_t pos = 0;
  for (int i = 0; i < 3; ++i) pos = csv.find('\n', pos) + 1;
  for (int i = 0; i < 4; ++i) pos = csv.find(',', pos) + 1;
  EXPECT_EQ(std::strtod(csv.c_str() + pos, nullptr), t.rows[2].H);
  const std::string svg = metamaterial_ratios_svg(t);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_NE(svg.find("nu_HL"), std::string::npos);
}

}}  // namespace
}  // namespace rigidfold::metamaterial
