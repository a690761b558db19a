// SORCE (seed 002) section 7: the printed optimised offset coefficients (eq 39) lost their
// minus signs in the OCR, and eq 37's third basis reads "4(1 - t) t^2". Scanning the 64 sign
// patterns on vertex A (eq 35 fold angles, eq 36 offsets, d = 1) settles both: with
// B3 = (1 - t) t^2 exactly two patterns make every profile convex toward its mate, the
// better one (FOM 55.3, eq 34) being
//   b_i = (+0.322657, +0.0885048, -0.814152),  b_o = (+0.876535, -0.32912, +0.184345);
// with B3 = 4 (1 - t) t^2 no pattern does (the seed says all four joints come out convex).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "design/sorce/sorce_fold_report.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct Design {
  double min_convexity = 0.0, max_convexity = 0.0, fom = 0.0;
  std::size_t cusps = 0;
};

Design evaluate(const std::vector<double>& bi, const std::vector<double>& bo, double b3_scale) {
  const VertexSectors a = testing::vertex_a_sectors();
  const auto gamma = vertex_fold_angles(a, VertexParameterization::kSymmetric);
  const ScalarFunction outer = basis_offset(-1.5, bo, seed_offset_bases(b3_scale));
  const ScalarFunction inner = basis_offset(0.5, bi, seed_offset_bases(b3_scale));
  const SorceVertex v = sorce_vertex(a, gamma, {outer, inner, inner, outer}, {1, 1, 1, 1});
  std::vector<FoldReport> r;
  Design d{1e300, -1e300, 0.0, 0};
  for (const FoldMotion& f : v.folds) {
    r.push_back(fold_report(f, {401}));
    d.min_convexity = std::min({d.min_convexity, r.back().min_convexity_left, r.back().min_convexity_right});
    d.max_convexity = std::max({d.max_convexity, r.back().max_convexity_left, r.back().max_convexity_right});
    d.cusps += r.back().cusps.size();
  }
  d.fom = figure_of_merit(r, 0.0);
  return d;
}

TEST(SorceSeedCoefficients, SignPatternOfEq39MakesEveryProfileConvex) {
  const double bi[3] = {0.322657, 0.0885048, 0.814152}, bo[3] = {0.876535, 0.32912, 0.184345};
  for (double scale : {1.0, 4.0}) {
    int convex = 0, best = -1;
    double best_fom = INFINITY, worst_fom = 0.0;
    for (int mask = 0; mask < 64; ++mask) {
      std::vector<double> vi(3), vo(3);
      for (int k = 0; k < 3; ++k) {
        vi[k] = (mask >> k & 1 ? -1 : 1) * bi[k];
        vo[k] = (mask >> (k + 3) & 1 ? -1 : 1) * bo[k];
      }
      const Design d = evaluate(vi, vo, scale);
      if (d.min_convexity > 0.0 && std::isfinite(d.max_convexity) && d.cusps == 0) {
        ++convex;
        worst_fom = std::max(worst_fom, d.fom);
        if (d.fom < best_fom) best_fom = d.fom, best = mask;
      }
    }
    if (scale == 1.0) {
      EXPECT_EQ(convex, 2);
      EXPECT_EQ(best, 0b010'100);  // b_i3 < 0 (bit 2) and b_o2 < 0 (bit 4), all others > 0
      EXPECT_LT(best_fom, worst_fom);  // measured 55.3 against 825
    } else {
      EXPECT_EQ(convex, 0) << "B3 = 4 (1 - t) t^2";
    }
  }
}

}}  // namespace
}  // namespace rigidfold::sorce
