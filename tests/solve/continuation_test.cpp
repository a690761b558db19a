// Pseudo-arclength continuation traces the Miura mode from a small fold to 170 degrees on the
// straight creases; every point agrees with the closed form.
#include "kernel/math/angle_units.hpp"
#include "kernel/solve/continuation.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <limits>
#include <vector>

#include "data/generators/miura.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::miura_edge_angles;

// Unknown of the first valley straight crease of a Miura: its fold angle is the closed
// form's parameter (-1 if there is none).
int valley_straight_driver(const ClosureSystem& sys, const CreasePattern& p, const generators::MiuraParams& m) {
  const auto kinds = generators::miura_crease_kinds(m);
  for (int k = 0; k < sys.num_unknowns(); ++k) {
    const int e = sys.edge_of_unknown(k);
    if (kinds[e] == generators::MiuraCrease::Straight && p.assignments[e] == Assignment::Valley) return k;
  }
  return -1;
}

TEST(SolverContinuation, MiuraTracedTo170DegreesMatchesClosedForm) {
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 5;
  m.alpha = 1.1;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  const int driver = valley_straight_driver(sys, p, m);
  ASSERT_GE(driver, 0);
  const double start = 0.05, target = to_radians(170.0);
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

// Landing and the angle-step cap (the trace command's settings): on a 12 x 12 Miura the
// continuation, steps capped at 0.2 rad in any crease, lands exactly on every requested
// value of the driver (10, 20, .., 160 deg), each landed point within the tolerance and
// 1e-10 of the closed form; the points in between are few (the cap, not the arclength,
// sets the step: at most 3 points per 10 deg of the driver here).
// An n x n Miura (alpha = 1.1) traced from 5 deg with trace_motion's settings (steps of at
// most 0.2 rad in any crease, the curved predictor), landing on the driver's given values.
struct LandingTrace {
  generators::MiuraParams m;
  CreasePattern p;
  ClosureSystem sys;
  int driver;
  ContinuationOptions opt;
  ContinuationResult res;

  LandingTrace(int n, double target, std::vector<double> landing_values)
      : m(params(n)), p(generators::miura_ori(m)), sys(p, build_topology(p)), driver(valley_straight_driver(sys, p, m)) {
    EXPECT_GE(driver, 0);
    const double start = to_radians(5.0);
    const Eigen::VectorXd x0 = sys.unknowns_from_edges(miura_edge_angles(p, m, start));
    const Eigen::VectorXd dir = sys.unknowns_from_edges(miura_edge_angles(p, m, start + 1e-3)) - x0;
    opt.max_angle_step = 0.2;
    opt.initial_step = std::numeric_limits<double>::infinity();
    opt.curved_predictor = true;
    opt.landing_unknown = driver;
    opt.landing_values = std::move(landing_values);
    res = continue_one_dof(sys, x0, dir, [&](const Eigen::VectorXd& x) { return x[driver] >= target; }, opt);
  }
  static generators::MiuraParams params(int n) {
    generators::MiuraParams m;
    m.rows = m.cols = n;
    m.alpha = 1.1;
    return m;
  }
};

TEST(SolverContinuation, LandsOnEveryRequestedDrivingValue) {
  std::vector<double> values;
  for (int d = 10; d <= 160; d += 10) values.push_back(to_radians(d));
  const LandingTrace lt(12, to_radians(160.0), values);
  const auto& [m, p, sys, driver, opt, res] = lt;
  ASSERT_TRUE(res.stopped) << res.reason;
  std::vector<int> landed(opt.landing_values.size(), 0);
  double worst_error = 0;
  for (const ContinuationPoint& pt : res.points) {
    EXPECT_LE(pt.residual, 1e-12);
    worst_error = std::max(worst_error, (pt.x - sys.unknowns_from_edges(miura_edge_angles(p, m, pt.x[driver])))
                                            .lpNorm<Eigen::Infinity>());
    if (pt.landing < 0) continue;
    ASSERT_LT(pt.landing, static_cast<int>(landed.size()));
    ++landed[pt.landing];
    EXPECT_NEAR(pt.x[driver], opt.landing_values[pt.landing], 1e-15);
  }
  for (std::size_t i = 0; i < landed.size(); ++i) EXPECT_EQ(landed[i], 1) << "landing value " << i;
  EXPECT_LE(worst_error, 1e-10);
  EXPECT_LE(res.points.size(), 3u * landed.size() + 1);
  // The stats' total time is recorded on return (the benchmarks' s_per_step divides it) and
  // holds every part of the trace.
  EXPECT_GT(res.stats.seconds_total, 0.0);
  EXPECT_GE(res.stats.seconds_total, res.stats.seconds_start + res.stats.seconds_factorize);
  std::cout << "[ contin.  ] miura 12x12 landing: " << res.points.size() << " points for " << landed.size()
            << " landing values, " << res.stats.factorizations << " factorizations, worst |x - closed form| "
            << worst_error << "\n";
}

// Factorisation reuse (chord corrector): a trace from 5 deg to `target_deg` on an n x n Miura
// with the given reuse mode. Checks every point against the closed form and the tolerance,
// returns the stats.
struct TraceCheck {
  ContinuationResult result;
  double worst_error = 0, worst_residual = 0;
  double ms = 0;
};

// Steps of equal arclength: about `steps` of them from start to target.
TraceCheck trace_miura(int n, double target_deg, double steps, FactorizationReuse reuse,
                       LinearSolver linear_solver = LinearSolver::kAuto, int pcg_max_iterations = 8) {
  generators::MiuraParams m;
  m.rows = m.cols = n;
  m.alpha = 1.1;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  const int driver = valley_straight_driver(sys, p, m);
  EXPECT_GE(driver, 0);
  const double start = to_radians(5), target = to_radians(target_deg);
  const Eigen::VectorXd x0 = sys.unknowns_from_edges(miura_edge_angles(p, m, start));
  const Eigen::VectorXd dir = sys.unknowns_from_edges(miura_edge_angles(p, m, start + 1e-3)) - x0;
  ContinuationOptions opt;
  opt.initial_step = opt.max_step =
      (sys.unknowns_from_edges(miura_edge_angles(p, m, target)) - x0).norm() / steps;
  opt.reuse = reuse;
  opt.linear_solver = linear_solver;
  opt.pcg_max_iterations = pcg_max_iterations;
  TraceCheck tc;
  const auto t0 = std::chrono::steady_clock::now();
  tc.result = continue_one_dof(sys, x0, dir, [&](const Eigen::VectorXd& x) { return x[driver] >= target; }, opt);
  tc.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(tc.result.stopped) << tc.result.reason;
  for (std::size_t i = 0; i < tc.result.points.size(); ++i) {
    const ContinuationPoint& pt = tc.result.points[i];
    const Eigen::VectorXd exact = sys.unknowns_from_edges(miura_edge_angles(p, m, pt.x[driver]));
    tc.worst_error = std::max(tc.worst_error, (pt.x - exact).lpNorm<Eigen::Infinity>());
    tc.worst_residual = std::max(tc.worst_residual, pt.residual);
    EXPECT_LE(pt.residual, opt.tolerance) << i;
    if (i > 0) {
      EXPECT_GT(pt.x[driver], tc.result.points[i - 1].x[driver]) << i;  // monotone: no turning back
    }
  }
  if (!tc.result.points.empty()) {
    EXPECT_GE(tc.result.points.back().x[driver], target);
  }
  return tc;
}

void print(const char* name, const TraceCheck& tc) {
  const ContinuationStats& s = tc.result.stats;
  std::cout << "[ contin.  ] " << name << ": " << tc.result.points.size() << " points, reuse "
            << tc.result.reused_factorization << ", " << s.factorizations << " factorizations, " << s.solves
            << " solves, " << s.null_vectors << " null vectors, " << s.corrector_iterations << " corrector iterations, "
            << s.renewals << " renewals (" << s.stale_restarts << " stale restarts, " << s.tangent_renewals
            << " tangent), " << s.rejected_steps << " rejected, worst residual " << tc.worst_residual << ", worst |x - closed form| "
            << tc.worst_error << ", " << tc.ms << " ms, " << tc.result.linear_solver << " (" << s.pcg_solves
            << " PCG solves, " << s.pcg_iterations << " CG iterations, " << s.pcg_fallbacks << " fallbacks, "
            << s.pcg_predicted_renewals << " predicted renewals)\n";
}

// 40 x 40 cells (above the 2000-unknown rank-revealing limit, so kAuto picks reuse): the
// chord corrector traces the same closed-form path as Newton, to the same tolerance, with
// fewer factorisations (about 1.6 against 2.9 per step here).
TEST(SolverContinuation, ReuseOnLargeMiuraMatchesNewtonWithFewerFactorizations) {
  const TraceCheck on = trace_miura(40, 120, 40, FactorizationReuse::kAuto);
  const TraceCheck off = trace_miura(40, 120, 40, FactorizationReuse::kOff, LinearSolver::kDirect);
  print("miura 40x40 reuse (auto)", on);
  print("miura 40x40 newton", off);
  EXPECT_TRUE(on.result.reused_factorization);
  EXPECT_FALSE(off.result.reused_factorization);
  EXPECT_LE(on.worst_error, 1e-10);
  EXPECT_LE(off.worst_error, 1e-10);
  EXPECT_LT(on.result.stats.factorizations, off.result.stats.factorizations);
  EXPECT_LT(4 * on.result.stats.factorizations, 3 * off.result.stats.factorizations);
}

// Large fixed steps make the stale factor contract slowly: the refactorisation path runs and
// the tolerance still holds at every point.
TEST(SolverContinuation, ReuseRefactorizesWhenStepsAreLarge) {
  const TraceCheck big = trace_miura(40, 120, 8, FactorizationReuse::kOn);
  print("miura 40x40 reuse, 8 steps", big);
  EXPECT_LE(big.worst_error, 1e-10);
  EXPECT_GT(big.result.stats.renewals, 0);
}

// A small pattern (rank-revealing tangent) with reuse forced on: same path, fewer
// factorisations than the default (Newton) there.
TEST(SolverContinuation, ReuseForcedOnSmallMiuraMatchesNewton) {
  const TraceCheck on = trace_miura(4, 170, 60, FactorizationReuse::kOn);
  const TraceCheck off = trace_miura(4, 170, 60, FactorizationReuse::kAuto);
  print("miura 4x4 reuse (forced)", on);
  print("miura 4x4 newton (auto)", off);
  EXPECT_TRUE(on.result.reused_factorization);
  EXPECT_FALSE(off.result.reused_factorization);
  EXPECT_LE(on.worst_error, 1e-10);
  EXPECT_LE(off.worst_error, 1e-10);
  EXPECT_LT(on.result.stats.factorizations, off.result.stats.factorizations);
}

// The Newton corrector with the stale-factor PCG step (LinearSolver::kPcg) on a 40 x 40
// Miura: every point within the tolerance (trace_miura) and 1e-10 rad of the closed form, as
// the direct Newton corrector, with fewer factorisations (CG solves in their place).
TEST(SolverContinuation, PcgCorrectorOnLargeMiuraMatchesClosedForm) {
  const TraceCheck pcg = trace_miura(40, 120, 40, FactorizationReuse::kOff, LinearSolver::kPcg);
  const TraceCheck direct = trace_miura(40, 120, 40, FactorizationReuse::kOff, LinearSolver::kDirect);
  print("miura 40x40 newton, PCG", pcg);
  print("miura 40x40 newton, direct", direct);
  EXPECT_EQ(pcg.result.linear_solver, "PCG (stale CHOLMOD factor)");
  EXPECT_EQ(direct.result.linear_solver, "direct (CHOLMOD)");
  EXPECT_FALSE(pcg.result.reused_factorization);
  EXPECT_LE(pcg.worst_error, 1e-10);
  EXPECT_LE(direct.worst_error, 1e-10);
  EXPECT_EQ(pcg.result.points.size(), direct.result.points.size());
  EXPECT_GT(pcg.result.stats.pcg_solves, 0);
  EXPECT_GT(pcg.result.stats.pcg_iterations, pcg.result.stats.pcg_solves);
  EXPECT_EQ(direct.result.stats.pcg_solves, 0);
  EXPECT_LT(pcg.result.stats.factorizations, direct.result.stats.factorizations);
}

// A cap of one CG iteration: most PCG solves fail and fall back to a fresh factorisation
// (and the direct step); the trace is as accurate as ever.
TEST(SolverContinuation, PcgFallsBackToAFreshFactorization) {
  const TraceCheck tc = trace_miura(40, 60, 20, FactorizationReuse::kOff, LinearSolver::kPcg, 1);
  print("miura 40x40 newton, PCG capped at 1 iteration", tc);
  EXPECT_GT(tc.result.stats.pcg_fallbacks, 0);
  EXPECT_LE(tc.worst_error, 1e-10);
}

// kAuto above 2000 unknowns (40 x 40: 3,200) takes the PCG corrector and keeps it while the
// stale factors pay; with CG capped at one iteration they do not, and it drops to the direct
// one for the rest of the trace, saying so. Both traces as accurate as ever.
TEST(SolverContinuation, AutomaticLinearSolverPicksPcgOnLargeSystemsAndDropsItWhenItDoesNotPay) {
  const TraceCheck pays = trace_miura(40, 120, 40, FactorizationReuse::kOff, LinearSolver::kAuto);
  print("miura 40x40 newton, automatic", pays);
  EXPECT_EQ(pays.result.linear_solver, "PCG (stale CHOLMOD factor)");
  EXPECT_GT(pays.result.stats.pcg_solves, 0);
  EXPECT_LE(pays.worst_error, 1e-10);
  const TraceCheck drops = trace_miura(40, 60, 20, FactorizationReuse::kOff, LinearSolver::kAuto, 1);
  print("miura 40x40 newton, automatic, CG capped at 1 iteration", drops);
  EXPECT_EQ(drops.result.linear_solver.rfind("direct (CHOLMOD), after ", 0), 0u) << drops.result.linear_solver;
  // Dropped after its first window: far fewer PCG attempts than corrector iterations.
  EXPECT_LT(drops.result.stats.pcg_solves + drops.result.stats.pcg_predicted_renewals,
            drops.result.stats.corrector_iterations);
  EXPECT_LE(drops.worst_error, 1e-10);
}

// A landing value a rounding error (1e-13 rad) past the previous one makes a landing step
// ~1e-13 long. The curved predictor's term divides by the last step squared; used after such
// a step it threw the next predictor ~1e13 away, and the trace then failed step after step
// (14 rejected steps here, 21 on the trace command's 100 x 100 Miura). It now skips the term when
// the step is over 100x the last.
TEST(SolverContinuation, ALandingStepOfARoundingErrorDoesNotBreakTheCurvedPredictor) {
  const LandingTrace lt(6, to_radians(120.0), {to_radians(30.0), to_radians(30.0) + 1e-13, to_radians(90.0)});
  const auto& [m, p, sys, driver, opt, res] = lt;
  ASSERT_TRUE(res.stopped) << res.reason;
  int landings = 0;
  for (const ContinuationPoint& pt : res.points) {
    EXPECT_LE(pt.residual, 1e-12);
    EXPECT_LE((pt.x - sys.unknowns_from_edges(miura_edge_angles(p, m, pt.x[driver]))).lpNorm<Eigen::Infinity>(),
              1e-10);
    if (pt.landing >= 0) ++landings;
  }
  EXPECT_EQ(landings, 3);
  EXPECT_EQ(res.stats.rejected_steps, 0);
}

// The chord corrector reports itself whatever linear_solver says; kAuto stays direct on a
// small system.
TEST(SolverContinuation, ReportsTheLinearSolverInUse) {
  const TraceCheck chord = trace_miura(8, 30, 5, FactorizationReuse::kOn, LinearSolver::kPcg);
  EXPECT_EQ(chord.result.linear_solver, "chord (stale CHOLMOD factor)");
  EXPECT_EQ(chord.result.stats.pcg_solves, 0);
  const TraceCheck small = trace_miura(8, 30, 5, FactorizationReuse::kOff, LinearSolver::kAuto);
  EXPECT_EQ(small.result.linear_solver, "direct (CHOLMOD)");
}

}}  // namespace
}  // namespace rigidfold
