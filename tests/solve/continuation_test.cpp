// Pseudo-arclength continuation traces the Miura mode from a small fold to 170 degrees on the
// straight creases; every point agrees with the closed form.
#include "kernel/solve/continuation.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <numbers>

#include "data/generators/miura.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace {

using testing::miura_edge_angles;

TEST(SolverContinuation, MiuraTracedTo170DegreesMatchesClosedForm) {
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 5;
  m.alpha = 1.1;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  const auto kinds = generators::miura_crease_kinds(m);
  int driver = -1;  // a valley straight crease: its fold angle is the closed form's parameter
  for (int k = 0; k < sys.num_unknowns() && driver < 0; ++k) {
    const int e = sys.edge_of_unknown(k);
    if (kinds[e] == generators::MiuraCrease::Straight && p.assignments[e] == Assignment::Valley) driver = k;
  }
  ASSERT_GE(driver, 0);
  const double start = 0.05, target = 170.0 * std::numbers::pi / 180;
  const Eigen::VectorXd x0 = sys.unknowns_from_edges(miura_edge_angles(p, m, start));
  const Eigen::VectorXd dir = sys.unknowns_from_edges(miura_edge_angles(p, m, start + 1e-3)) - x0;
  ContinuationOptions opt;
  opt.max_step = 0.1;
  const auto t0 = std::chrono::steady_clock::now();
  const ContinuationResult res =
      continue_one_dof(sys, x0, dir, [&](const Eigen::VectorXd& x) { return x[driver] >= target; }, opt);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(res.stopped) << res.reason;
  double worst_residual = 0, worst_error = 0, min_step = 1e9, max_step = 0;
  int max_iter = 0;
  for (std::size_t i = 0; i < res.points.size(); ++i) {
    const ContinuationPoint& pt = res.points[i];
    const double s = pt.x[driver];
    const Eigen::VectorXd exact = sys.unknowns_from_edges(miura_edge_angles(p, m, s));
    worst_error = std::max(worst_error, (pt.x - exact).lpNorm<Eigen::Infinity>());
    worst_residual = std::max(worst_residual, pt.residual);
    EXPECT_LE(pt.residual, 1e-12) << i;
    if (i > 0) {
      EXPECT_GT(s, res.points[i - 1].x[driver]);  // monotone: no turning back
      min_step = std::min(min_step, pt.step);
      max_step = std::max(max_step, pt.step);
      max_iter = std::max(max_iter, pt.corrector_iterations);
    }
  }
  EXPECT_LE(worst_error, 1e-10);
  EXPECT_GE(res.points.back().x[driver], target);
  EXPECT_LT(res.points.front().x[driver], 0.1);
  std::cout << "[ contin.  ] miura 4x5: " << res.points.size() << " points, driver " << res.points.front().x[driver]
            << " -> " << res.points.back().x[driver] << " rad, steps [" << min_step << ", " << max_step
            << "], max corrector iterations " << max_iter << ", worst residual " << worst_residual
            << ", worst |x - closed form| " << worst_error << ", " << ms << " ms\n";
}

}  // namespace
}  // namespace rigidfold
