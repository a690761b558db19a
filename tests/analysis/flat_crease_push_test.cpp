// From a weakly folded state to a strict one (kernel/analysis/flat_crease_push.hpp):
//   - a degree-6 vertex folded with two creases flat (a degree-4 motion) is pushed to a state
//     that folds all six their lettered way, closed to 1e-12, near the weak one;
//   - where two straight lettered lines cross (degree 4, 90-degree sectors) no motion from flat
//     folds all four creases: one line folded alone is not pushed to a strict state;
//   - a strict state is left alone, and bad sizes are refused;
//   - the fold-size continuation with the letters' margin also leaves the flat creases.
#include "kernel/analysis/flat_crease_push.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <numbers>
#include <stdexcept>

#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/norm_continuation.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::vector<int> edge_signs(const CreasePattern& p) {
  std::vector<int> s(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) s[e] = assigned_fold_sign(p.assignments[e]);
  return s;
}

// Creases at 0, 50, 130, 170, 245, 300 degrees; with creases 0 and 3 flat the other four form
// a degree-4 vertex of sectors 80, 115, 55, 110 degrees (no sector above 180, no two creases
// in line: it folds). The weak state: creases 0 and 3 flat, crease 1 at 0.3 rad, the rest
// projected (the degree-4 vertex's motion; its sign pattern found by trying each). Letters:
// the weak state's signs, and the given ones for creases 0 and 3.
struct WeakDegreeSixVertex {
  CreasePattern p;
  std::optional<ClosureSystem> sys;
  Eigen::VectorXd weak;
  std::vector<int> sign;

  WeakDegreeSixVertex(Assignment letter0, Assignment letter3) {
    std::vector<double> directions;
    for (double d : {0.0, 50.0, 130.0, 170.0, 245.0, 300.0}) directions.push_back(d * std::numbers::pi / 180);
    p = testing::single_vertex_pattern(directions);
    sys.emplace(p, build_topology(p));
    const int u0 = sys->unknown_of_edge(0), u3 = sys->unknown_of_edge(3), u1 = sys->unknown_of_edge(1);
    auto folds_all_four = [&](const NewtonResult& r) {
      if (!r.converged) return false;
      for (int e : {1, 2, 4, 5})
        if (std::abs(r.x[sys->unknown_of_edge(e)]) <= 1e-3) return false;
      return true;
    };
    NewtonResult r;
    for (int signs = 0; signs < 8 && !folds_all_four(r); ++signs) {
      Eigen::VectorXd x0 = Eigen::VectorXd::Zero(6);
      int bit = 0;
      for (int e : {2, 4, 5}) x0[sys->unknown_of_edge(e)] = (signs >> bit++) & 1 ? 0.3 : -0.3;
      x0[u1] = 0.3;
      NewtonOptions nopt;
      nopt.held_unknowns = {u0, u3, u1};
      r = newton_project(*sys, x0, nopt);
    }
    if (!folds_all_four(r) || r.x[u0] != 0.0 || r.x[u3] != 0.0) return;  // weak stays empty
    weak = r.x;
    for (int e : {1, 2, 4, 5})
      p.assignments[e] = weak[sys->unknown_of_edge(e)] > 0 ? Assignment::Valley : Assignment::Mountain;
    p.assignments[0] = letter0;
    p.assignments[3] = letter3;
    sign = edge_signs(p);
  }
};

TEST(FlatCreasePush, DegreeSixVertexWithTwoFlatCreasesBecomesStrict) {
  for (Assignment a0 : {Assignment::Valley, Assignment::Mountain}) {
    for (Assignment a3 : {Assignment::Valley, Assignment::Mountain}) {
      const WeakDegreeSixVertex v(a0, a3);
      ASSERT_EQ(v.weak.size(), 6);
      const std::optional<Eigen::VectorXd> strict = push_off_flat_creases(*v.sys, v.weak, v.sign, 1e-12);
      const std::string letters = std::string(1, assignment_letter(a0)) + assignment_letter(a3);
      ASSERT_TRUE(strict.has_value()) << letters;
      EXPECT_LE(v.sys->residual(*strict).lpNorm<Eigen::Infinity>(), 1e-12) << letters;
      const double cut = 1e-6 * strict->cwiseAbs().maxCoeff();
      for (int i = 0; i < 6; ++i) EXPECT_GT(v.sign[v.sys->edge_of_unknown(i)] * (*strict)[i], cut) << letters << " " << i;
      EXPECT_LE((*strict - v.weak).lpNorm<Eigen::Infinity>(), 0.05) << letters;
      // Already strict: nothing to do.
      EXPECT_FALSE(push_off_flat_creases(*v.sys, *strict, v.sign, 1e-12).has_value()) << letters;
    }
  }
}

// The fold-size continuation with the letters' margin (norm_continuation.hpp), from the same
// weak state: the box lifts the two flat creases to their margin on their letter's side and
// the corrector closes the vertex around them, so every point keeps every letter by at least
// the margin, and at some point the margin is what holds a crease (the bound is active).
TEST(FlatCreasePush, FoldSizeContinuationWithTheLettersMarginLeavesTheFlatCreases) {
  const WeakDegreeSixVertex v(Assignment::Valley, Assignment::Mountain);
  ASSERT_EQ(v.weak.size(), 6);
  NormContinuationOptions opt;
  for (int i = 0; i < 6; ++i) opt.sign_floor.push_back(v.sign[v.sys->edge_of_unknown(i)]);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(6, -std::numbers::pi), hi = -lo;
  for (double target : {v.weak.norm() / 100, 3.0}) {
    opt.target_size = target;
    int points = 0;
    double least_ratio = 1e300;  // min over points and creases of s_i x_i / (margin ||x||)
    const NormContinuationResult res =
        continue_by_norm(*v.sys, v.weak, lo, hi, opt, [&](const Eigen::VectorXd& x) {
          ++points;
          EXPECT_LE(v.sys->residual(x).lpNorm<Eigen::Infinity>(), 1e-12);
          for (int i = 0; i < 6; ++i)
            least_ratio = std::min(least_ratio, opt.sign_floor[i] * x[i] / (opt.sign_margin * x.norm()));
          return x.cwiseAbs().maxCoeff() >= 2.5;
        });
    EXPECT_GE(points, 5) << target;
    EXPECT_GE(least_ratio, 1.0 - 1e-6) << target;
    EXPECT_LE(least_ratio, 10.0) << target;  // the margin held some crease
    std::cout << "[ push      ] degree-6 weak state continued to size " << target << ": " << points << " points, "
              << res.reason << ", least letter margin ratio " << least_ratio << "\n";
  }
}

TEST(FlatCreasePush, CrossingStraightLinesHaveNoStrictState) {
  const double q = std::numbers::pi / 2;
  CreasePattern p = testing::single_vertex_pattern({0.0, q, 2 * q, 3 * q});
  const ClosureSystem sys(p, build_topology(p));
  ASSERT_EQ(sys.num_unknowns(), 4);
  // Line 0-2 valley, line 1-3 mountain; the valley line folded alone closes exactly.
  Eigen::VectorXd x = Eigen::VectorXd::Zero(4);
  for (int i = 0; i < 4; ++i) {
    const int e = sys.edge_of_unknown(i);
    const bool valley_line = e == 0 || e == 2;
    p.assignments[e] = valley_line ? Assignment::Valley : Assignment::Mountain;
    if (valley_line) x[i] = 0.5;
  }
  ASSERT_LE(sys.residual(x).lpNorm<Eigen::Infinity>(), 1e-15);
  EXPECT_FALSE(push_off_flat_creases(sys, x, edge_signs(p), 1e-12).has_value());
}

TEST(FlatCreasePush, RefusesWrongSizes) {
  const CreasePattern p = testing::single_vertex_pattern({0.0, 1.5, 3.0, 4.5});
  const ClosureSystem sys(p, build_topology(p));
  EXPECT_THROW(push_off_flat_creases(sys, Eigen::VectorXd::Ones(3), edge_signs(p), 1e-12), std::invalid_argument);
  EXPECT_THROW(push_off_flat_creases(sys, Eigen::VectorXd::Ones(4), {1, -1}, 1e-12), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold
