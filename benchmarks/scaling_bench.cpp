// Large-tessellation scaling benchmarks. Every run reports the error it reached
// next to its time, plus the pattern size and the process's peak resident memory:
//   edges               creases of the pattern (all edges, boundary included)
//   residual            ||r||_inf reached (radians)
//   error_vs_closed_form max |rho - rho_closed_form| over the unknowns (radians)
//   peak_rss_mb         getrusage peak RSS of the process so far (run one benchmark per
//                       process for a per-benchmark figure: scripts/bench_report.sh does)
// Sizes: Miura-ori n x n cells, about 2 n^2 creases; see register_all() at the end.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "benchmarks/miura_case.hpp"
#include "benchmarks/peak_memory.hpp"
#include "data/generators/graded_miura.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/square_twist_tessellation.hpp"
#include "data/generators/waterbomb_tessellation.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace {

using bench::MiuraCase;
using bench::peak_rss_mb;

void finish(benchmark::State& state, const CreasePattern& p) {
  state.counters["edges"] = p.num_edges();
  state.counters["peak_rss_mb"] = peak_rss_mb();
}

void BM_Residual(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  Eigen::VectorXd r;
  for (auto _ : state) {
    r = c.system.residual(c.exact);
    benchmark::DoNotOptimize(r.data());
  }
  state.counters["residual"] = r.lpNorm<Eigen::Infinity>();
  finish(state, c.pattern);
}

void BM_Jacobian(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  for (auto _ : state) c.system.evaluate(c.exact, r, J);
  state.counters["residual"] = r.lpNorm<Eigen::Infinity>();
  state.counters["nnz"] = static_cast<double>(J.nonZeros());
  finish(state, c.pattern);
}

// Numeric factorisation of G = J^T J + lambda I (symbolic analysis outside the loop);
// range(1) = FactorOrdering. Error: ||J_f dx - r||_inf of the minimum-norm step.
void BM_Factorize(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  const auto ordering = static_cast<FactorOrdering>(state.range(1));
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  c.system.evaluate(c.start, r, J);
  MinimumNormSolver solver(J, {0}, ordering);
  solver.factorize(J, 1e-14);
  for (auto _ : state) solver.factorize(J, 1e-14);
  const Eigen::VectorXd dx = solver.solve(J, r);
  state.counters["linear_residual"] = (J * dx - r).lpNorm<Eigen::Infinity>();
  state.counters["ordering"] = static_cast<double>(state.range(1));
  state.counters["supernodal"] = solver.supernodal();
  finish(state, c.pattern);
}

// One corrector (Newton projection) from the closed form + 1e-4 noise, one crease held, to
// tolerance 10^-range(2); range(1) = FactorOrdering.
void BM_Corrector(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  NewtonOptions o;
  o.held_unknowns = {0};
  o.ordering = static_cast<FactorOrdering>(state.range(1));
  o.tolerance = std::pow(10.0, -static_cast<double>(state.range(2)));
  // range(3): 0 = the default, 1 = every step on a fresh factorisation (no stale-factor steps).
  if (state.range(3) == 1) o.stale_factor_min_unknowns = std::numeric_limits<int>::max();
  NewtonResult res;
  for (auto _ : state) res = newton_project(c.system, c.start, o);
  state.counters["newton_iterations"] = res.iterations;
  state.counters["factorizations"] = res.factorizations;
  state.counters["stale_steps"] = res.stale_steps;
  state.counters["stale_its"] = res.stale_iterations;
  state.counters["residual"] = res.residual_history.back();
  state.counters["error_vs_closed_form"] = (res.x - c.exact).cwiseAbs().maxCoeff();
  state.counters["ordering"] = static_cast<double>(state.range(1));
  state.counters["tolerance"] = o.tolerance;
  state.counters["supernodal"] = res.supernodal;
  state.counters["fresh_only"] = static_cast<double>(state.range(3));
  finish(state, c.pattern);
}

// Work counters of a continue_one_dof call (ContinuationStats), per run.
void stats_counters(benchmark::State& state, const ContinuationStats& st, double steps) {
  state.counters["factorizations"] = st.factorizations;
  state.counters["fact_per_step"] = st.factorizations / steps;
  state.counters["solves"] = st.solves;
  state.counters["null_vectors"] = st.null_vectors;
  state.counters["renewals"] = st.renewals;
  state.counters["stale_restarts"] = st.stale_restarts;
  state.counters["tangent_renewals"] = st.tangent_renewals;
  state.counters["corrector_its"] = st.corrector_iterations;
  state.counters["rejected"] = st.rejected_steps;
  state.counters["s_per_step"] = st.seconds_total / steps;
  state.counters["s_factorize"] = st.seconds_factorize;
  state.counters["s_solve"] = st.seconds_solve;
  state.counters["s_null_vector"] = st.seconds_null_vector;
  state.counters["s_evaluate"] = st.seconds_evaluate;
  state.counters["pcg_solves"] = st.pcg_solves;
  state.counters["pcg_its"] = st.pcg_iterations;
  state.counters["pcg_fallbacks"] = st.pcg_fallbacks;
  state.counters["pcg_predicted"] = st.pcg_predicted_renewals;
  state.counters["s_pcg"] = st.seconds_pcg;
}

void continuation_counters(benchmark::State& state, const ContinuationResult& res) {
  const double steps = std::max<double>(1.0, static_cast<double>(res.points.size()) - 1);
  state.counters["reuse"] = res.reused_factorization;
  stats_counters(state, res.stats, steps);
  state.SetLabel(res.linear_solver);
}

// range(1) of the continuation benchmarks: 1 = factorisation reuse (chord corrector), 0 =
// Newton with a fresh factorisation per iteration (LinearSolver::kDirect), 2 = Newton with the
// stale-factor PCG step (LinearSolver::kPcg), 3 = the automatic choice (LinearSolver::kAuto:
// PCG above 2000 unknowns while it pays).
void set_corrector(ContinuationOptions& o, int64_t mode) {
  o.reuse = mode == 1 ? FactorizationReuse::kOn : FactorizationReuse::kOff;
  o.linear_solver = mode == 2 ? LinearSolver::kPcg : mode == 3 ? LinearSolver::kAuto : LinearSolver::kDirect;
}

// One continuation step (predictor + corrector + tangent) from the closed form; range(1) as
// for set_corrector.
void BM_ContinuationStep(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  ContinuationOptions o;
  o.max_points = 2;
  o.initial_step = 0.02 * std::sqrt(static_cast<double>(c.system.num_unknowns()));
  o.max_step = o.initial_step;
  set_corrector(o, state.range(1));
  ContinuationResult res;
  const Eigen::VectorXd dir = c.closed_form(1.3) - c.exact;
  for (auto _ : state) res = continue_one_dof(c.system, c.exact, dir, [](const Eigen::VectorXd&) { return false; }, o);
  const ContinuationPoint& last = res.points.back();
  const double rho_s = std::fabs(last.x[c.driver()]);
  state.counters["points"] = static_cast<double>(res.points.size());
  state.counters["residual"] = last.residual;
  state.counters["error_vs_closed_form"] = (last.x - c.closed_form(rho_s)).cwiseAbs().maxCoeff();
  continuation_counters(state, res);
  finish(state, c.pattern);
}

// A full trace: from rho_s = 5 deg (the flat state itself is a singular point) to 170 deg in
// about 100 equal arclength steps; range(1) as for set_corrector. Error:
// the worst distance of any traced point from the closed form at its own rho_s.
void BM_Trace(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  const double start_fold = to_radians(5), end_fold = to_radians(170);
  const Eigen::VectorXd x0 = c.closed_form(start_fold);
  ContinuationOptions o;
  o.initial_step = o.max_step = (c.closed_form(end_fold) - x0).norm() / 100;
  set_corrector(o, state.range(1));
  const int driver = c.driver();
  ContinuationResult res;
  for (auto _ : state)
    res = continue_one_dof(c.system, x0, c.closed_form(2 * start_fold) - x0,
                           [&](const Eigen::VectorXd& x) { return std::fabs(x[driver]) >= end_fold; }, o);
  double worst_residual = 0, worst_error = 0;
  for (const ContinuationPoint& pt : res.points) {
    worst_residual = std::max(worst_residual, pt.residual);
    worst_error = std::max(worst_error, (pt.x - c.closed_form(std::fabs(pt.x[driver]))).cwiseAbs().maxCoeff());
  }
  state.counters["points"] = static_cast<double>(res.points.size());
  state.counters["reached_deg"] = to_degrees(std::fabs(res.points.back().x[driver]));
  state.counters["residual"] = worst_residual;
  state.counters["error_vs_closed_form"] = worst_error;
  continuation_counters(state, res);
  finish(state, c.pattern);
}

// DOF / rank of the Jacobian at a folded state; range(1) = RankMethod (0 auto: dense SVD up
// to 200 unknowns, the CHOLMOD factor subspace above; 3 SPQR).
void BM_Rank(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  c.system.evaluate(c.exact, r, J);
  RankOptions ro;
  ro.method = static_cast<RankMethod>(state.range(1));
  RankResult rk;
  for (auto _ : state) rk = jacobian_rank(J, ro);
  state.counters["dof"] = rk.dof;
  state.counters["sigma_dropped"] = rk.sigma_dropped;
  state.counters["sigma_kept"] = rk.sigma_kept;
  state.counters["residual"] = r.lpNorm<Eigen::Infinity>();
  state.SetLabel(rk.method);
  finish(state, c.pattern);
}

// Multiplier propagation (exact verdict with certificate) against the general corrector on
// the same graded (non-Miura) quad mesh: n x n panels.
generators::GradedMiuraParams graded(int n) {
  generators::GradedMiuraParams g;
  g.rows = g.cols = n;
  g.theta_min = 0.9;
  g.theta_max = 1.1;
  return g;
}

// The multiplier verdict of a pattern, timed, with its loop defect and certificate mismatch.
void time_multiplier_verdict(benchmark::State& state, const CreasePattern& p) {
  const Topology t = build_topology(p);
  FoldabilityVerdict v;
  for (auto _ : state) v = verdict_with_assignment(p, t);
  state.counters["dof"] = v.dof;
  state.counters["max_defect"] = v.max_loop_defect;
  state.counters["mismatch"] = v.certificate_mismatch;
  finish(state, p);
}

// The general corrector from a known folded state (unknowns `exact`) perturbed by 1e-4 rad,
// one crease held, and its distance back to that state.
void time_corrector_back_to(benchmark::State& state, const CreasePattern& p, const ClosureSystem& sys,
                            const Eigen::VectorXd& exact) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> noise(-1e-4, 1e-4);
  Eigen::VectorXd x0 = exact;
  for (int k = 1; k < x0.size(); ++k) x0[k] += noise(rng);
  NewtonOptions o;
  o.held_unknowns = {0};
  NewtonResult res;
  for (auto _ : state) res = newton_project(sys, x0, o);
  state.counters["residual"] = res.residual_history.back();
  state.counters["error_vs_closed_form"] = (res.x - exact).cwiseAbs().maxCoeff();
  finish(state, p);
}

void BM_GradedMultiplier(benchmark::State& state) {
  time_multiplier_verdict(state, generators::graded_miura(graded(static_cast<int>(state.range(0)))));
}

void BM_GradedCorrector(benchmark::State& state) {
  const auto gp = graded(static_cast<int>(state.range(0)));
  const CreasePattern p = generators::graded_miura(gp);
  const ClosureSystem sys(p, build_topology(p));
  time_corrector_back_to(state, p, sys,
                         sys.unknowns_from_edges(fold_angle_vector(generators::graded_miura_fold_angles(gp, 1.2))));
}

// The same comparison on a square-twist tessellation of the rigid Type4 layout (n x n
// twists, about 8 n^2 creases; 1 DOF): the multiplier verdict against the general corrector
// started from the multiplier family's state perturbed by 1e-4 rad (one crease held).
generators::SquareTwistTessellationParams twist_tessellation(int n) {
  generators::SquareTwistTessellationParams p;
  p.rows = p.cols = n;
  return p;
}

void BM_TwistMultiplier(benchmark::State& state) {
  time_multiplier_verdict(state,
                          generators::square_twist_tessellation(twist_tessellation(static_cast<int>(state.range(0)))));
}

void BM_TwistCorrector(benchmark::State& state) {
  const CreasePattern p = generators::square_twist_tessellation(twist_tessellation(static_cast<int>(state.range(0))));
  const Topology t = build_topology(p);
  const FoldabilityVerdict v = verdict_with_assignment(p, t);
  if (v.verdict != Verdict::kRigidlyFoldable || !v.family) {
    state.SkipWithError("the Type4 tessellation should be rigidly foldable");
    return;
  }
  const ClosureSystem sys(p, t);
  time_corrector_back_to(state, p, sys, sys.unknowns_from_edges(v.family->angles(0.4)));  // tan(rho/2) = m * 0.4
}

// Multi-DOF: the waterbomb tessellation, a random small fold projected onto the manifold.
void BM_WaterbombCorrector(benchmark::State& state) {
  generators::WaterbombTessellationParams wp;
  wp.rows = wp.cols = static_cast<int>(state.range(0));
  const CreasePattern p = generators::waterbomb_tessellation(wp);
  const ClosureSystem sys(p, build_topology(p));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  Eigen::VectorXd x0(sys.num_unknowns());
  for (int k = 0; k < x0.size(); ++k) x0[k] = u(rng);
  NewtonResult res;
  for (auto _ : state) res = newton_project(sys, x0);
  state.counters["residual"] = res.residual_history.back();
  state.counters["newton_iterations"] = res.iterations;
  finish(state, p);
}

// Not foldable: perturbed Miura; the corrector from the Miura's folded state. It either
// fails or lands on a nearly flat state; "residual" and "max_fold" show which.
void BM_PerturbedCorrector(benchmark::State& state) {
  generators::MiuraParams mp = MiuraCase::make_params(static_cast<int>(state.range(0)));
  generators::MiuraParams exact = mp;
  mp.perturbation = 0.05;
  const CreasePattern p = generators::miura_ori(mp);
  const ClosureSystem sys(p, build_topology(p));
  const Eigen::VectorXd x0 =
      sys.unknowns_from_edges(fold_angle_vector(generators::miura_fold_angles(generators::miura_ori(exact), exact, 0.5)));
  NewtonResult res;
  for (auto _ : state) res = newton_project(sys, x0);
  state.counters["residual"] = res.residual_history.back();
  state.counters["max_fold"] = res.x.cwiseAbs().maxCoeff();
  state.counters["converged"] = res.converged;
  finish(state, p);
}

// The side-by-side table with the Python/Numba peer (osbo/rigid-origami), measured the
// same way: the general solver forced (trace_motion with force_general, as `trace
// --general`), 30 equally spaced steps of the driving straight crease from flat to 150 deg in
// its letter's direction. Error: every step against the Miura closed form at its own drive.
// Peer figures (measured elsewhere and quoted here): 9.5 s at 50 x 50, 56 s at 100 x 100.
void BM_PeerTrace(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  TraceRequest rq;
  rq.force_general = true;
  rq.steps = 30;
  const int drive = c.params.cols + 0;  // edge of the driver() unknown: a straight crease
  rq.drive = drive;
  const double sign = assigned_fold_sign(c.pattern.assignments[drive]) != 0 ? assigned_fold_sign(c.pattern.assignments[drive]) : 1.0;
  rq.to = sign * to_radians(150.0);
  MotionTrace tr;
  for (auto _ : state) tr = trace_motion(c.pattern, c.topology, rq);
  const MotionBranch& b = tr.branches.at(0);
  double worst = 0.0;
  for (const MotionStep& s : b.steps)
    worst = std::max(worst, (c.system.unknowns_from_edges(s.rho) - c.closed_form(std::fabs(s.drive))).cwiseAbs().maxCoeff());
  state.counters["steps"] = static_cast<double>(b.steps.size());
  state.counters["reached_deg"] = to_degrees(std::fabs(b.reached));
  state.counters["residual"] = b.max_residual;
  state.counters["error_vs_closed_form"] = worst;
  stats_counters(state, b.continuation, std::max<std::size_t>(1, b.continuation_points));
  state.SetLabel(b.linear_solver);
  finish(state, c.pattern);
}

// The peer table's corrector: one Newton projection from the closed form at rho_s = 1.2 plus
// uniform noise of 1e-3 rad (the quoted peer setting; BM_Corrector uses 1e-4), one crease held.
// Peer figures: 0.86 s at 100 x 100, 5.9 s at 200 x 200.
void BM_PeerCorrector(benchmark::State& state) {
  const MiuraCase c(static_cast<int>(state.range(0)));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  Eigen::VectorXd x0 = c.exact;
  for (int k = 1; k < x0.size(); ++k) x0[k] += noise(rng);
  NewtonOptions o;
  o.held_unknowns = {0};
  NewtonResult res;
  for (auto _ : state) res = newton_project(c.system, x0, o);
  state.counters["newton_iterations"] = res.iterations;
  state.counters["residual"] = res.residual_history.back();
  state.counters["error_vs_closed_form"] = (res.x - c.exact).cwiseAbs().maxCoeff();
  finish(state, c.pattern);
}

// Sizes (n x n Miura cells, about 2 n^2 creases): quick set up to 200 (80k creases);
// RIGIDFOLD_BENCH_LARGE=1 adds 160 and 320 (205k creases); RIGIDFOLD_BENCH_LARGE=2 also adds
// 1000 (2M creases) for the residual, Jacobian, factorisation and corrector.
void register_all() {
  const char* env = std::getenv("RIGIDFOLD_BENCH_LARGE");
  const int large = env ? std::atoi(env) : 0;
  std::vector<int> sizes = {10, 30, 100, 200};
  if (large >= 1) sizes.insert(sizes.end(), {160, 320});
  auto add = [](const char* name, void (*fn)(benchmark::State&)) {
    return benchmark::RegisterBenchmark(name, fn)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
  };
  for (int n : sizes) {
    add("BM_Residual", BM_Residual)->Arg(n);
    add("BM_Jacobian", BM_Jacobian)->Arg(n);
    add("BM_Factorize", BM_Factorize)->Args({n, 0});
    add("BM_Corrector", BM_Corrector)->Args({n, 0, 12, 0});
    add("BM_Corrector", BM_Corrector)->Args({n, 0, 12, 1});  // every step refactorised
    for (int mode : {1, 0, 2}) add("BM_ContinuationStep", BM_ContinuationStep)->Args({n, mode});
    add("BM_GradedMultiplier", BM_GradedMultiplier)->Arg(n);
    add("BM_GradedCorrector", BM_GradedCorrector)->Arg(n);
  }
  if (large >= 2) {
    add("BM_Residual", BM_Residual)->Arg(1000)->Iterations(1);
    add("BM_Jacobian", BM_Jacobian)->Arg(1000)->Iterations(1);
    add("BM_Factorize", BM_Factorize)->Args({1000, 0})->Iterations(1);
    add("BM_Corrector", BM_Corrector)->Args({1000, 0, 12, 0})->Iterations(1);
    add("BM_Corrector", BM_Corrector)->Args({1000, 0, 12, 1})->Iterations(1);
    // Orderings at 2M unknowns (AMD, METIS, NESDIS): the fill, hence the factorisation's cost, differs most here.
    for (int ord = 1; ord <= 3; ++ord) {
      add("BM_Factorize", BM_Factorize)->Args({1000, ord})->Iterations(1);
      add("BM_Corrector", BM_Corrector)->Args({1000, ord, 12, 0})->Iterations(1);
    }
    for (int reuse : {1, 0}) add("BM_ContinuationStep", BM_ContinuationStep)->Args({1000, reuse})->Iterations(1);
  }
  // Solver settings (time against error) on one mid size: orderings and tolerances.
  const int mid = large >= 1 ? 320 : 100;
  for (int ord = 1; ord <= 3; ++ord) {
    add("BM_Factorize", BM_Factorize)->Args({mid, ord});
    add("BM_Corrector", BM_Corrector)->Args({mid, ord, 12, 0});
  }
  for (int tol : {6, 8, 10}) add("BM_Corrector", BM_Corrector)->Args({mid, 0, tol, 0});
  // Traces, range(1): 1 = factorisation reuse, 0 = Newton (direct), 2 = Newton (PCG), 3 = the
  // automatic choice (2 and 3 from 40 x 40 up only). Up to 2000 unknowns the continuation checks DOF = 1 at every point (dense
  // SVD up to 200 unknowns, the factor subspace above: n = 30 took minutes with the dense SVD
  // it used before).
  for (int n : {10, 30, 40, 100, 200})
    for (int mode : {1, 0, 2, 3})
      if (mode < 2 || n >= 40) add("BM_Trace", BM_Trace)->Args({n, mode})->Iterations(1);
  if (large >= 1)
    for (int n : {160, 320})
      for (int mode : {1, 0, 2, 3}) add("BM_Trace", BM_Trace)->Args({n, mode})->Iterations(1);
  for (int n : {10, 20, 40, 100, 200}) add("BM_Rank", BM_Rank)->Args({n, 0});
  for (int n : {20, 40}) add("BM_Rank", BM_Rank)->Args({n, 3});
  if (large >= 1) add("BM_Rank", BM_Rank)->Args({320, 0});
  for (int n : {5, 10, 20}) add("BM_WaterbombCorrector", BM_WaterbombCorrector)->Arg(n);
  std::vector<int> twists = {5, 20, 50};
  if (large >= 1) twists.push_back(160);
  for (int n : twists) {
    add("BM_TwistMultiplier", BM_TwistMultiplier)->Arg(n);
    add("BM_TwistCorrector", BM_TwistCorrector)->Arg(n);
  }
  for (int n : {10, 30, 100}) add("BM_PerturbedCorrector", BM_PerturbedCorrector)->Arg(n);
  for (int n : {50, 100}) add("BM_PeerTrace", BM_PeerTrace)->Arg(n)->Iterations(1);
  for (int n : {100, 200}) add("BM_PeerCorrector", BM_PeerCorrector)->Arg(n);
}

}  // namespace
}  // namespace rigidfold

int main(int argc, char** argv) {
  rigidfold::register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
