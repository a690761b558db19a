// Design time against achieved error for Miura strings of 10, 100 and 1000 vertices, per
// method. Counters: err_* are the achieved errors (radians for angles; for curves the max
// point error divided by the mean segment length). Each case runs once (Iterations(1)):
// these are solves, not micro-kernels, and the whole program stays within about a minute.
#include <benchmark/benchmark.h>

#include <cmath>

#include "design/strings/miura_string.hpp"
#include "design/strings/string_fit_ceres.hpp"
#include "design/strings/string_fit_nlopt.hpp"
#include "design/strings/string_inverse.hpp"
#include "design/strings/string_kinematics.hpp"
#include "kernel/math/angle_units.hpp"

namespace {

using namespace rigidfold::design;
using rigidfold::to_radians;

MiuraString random_string(int n, std::uint64_t seed) { return random_miura_string(n, seed, to_radians(30), to_radians(65), 0.5); }

std::vector<Eigen::Vector3d> helix(int n) {
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < n + 2; ++k) p.emplace_back(0.15 * std::cos(to_radians(k * 172)), 0.15 * std::sin(to_radians(k * 172)), 1.0 * k);
  return p;
}

double mean_segment(const std::vector<Eigen::Vector3d>& p) {
  double t = 0;
  for (std::size_t k = 0; k + 1 < p.size(); ++k) t += (p[k + 1] - p[k]).norm();
  return t / (p.size() - 1);
}

void BM_ClosedFormDeflections(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const MiuraString s = random_string(n, 1);
  const StringState st = string_forward(s, 0.4);
  std::vector<double> phi, psi;
  for (const auto& v : st.vertices) {
    phi.push_back(v.phi);
    psi.push_back(v.psi);
  }
  const auto theta = transmitted_thetas(0.4, n);
  DeflectionDesign d;
  for (auto _ : state) benchmark::DoNotOptimize(d = design_from_deflections(phi, psi, theta));
  double err = 0, res = 0;
  for (int i = 0; i < n; ++i) {
    err = std::max({err, std::fabs(d.vertices[i].alpha1 - s.alpha1[i]), std::fabs(d.vertices[i].alpha2 - s.alpha2[i])});
    res = std::max({res, std::fabs(d.vertices[i].phi_error), std::fabs(d.vertices[i].psi_error)});
  }
  state.counters["err_alpha_rad"] = err;
  state.counters["err_phipsi_rad"] = res;
}

void BM_ClosedFormCurve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto target = helix(n);
  CurveDesignOptions o;
  o.theta_samples = 8;  // coarse grid: (theta0, roll) search costs samples x N
  o.roll_samples = 24;
  CurveDesign d;
  for (auto _ : state) benchmark::DoNotOptimize(d = design_from_curve(target, o));
  double m = 0, r = 0;
  if (d.feasible) curve_errors(d.string, d.theta0, d.pose, target, m, r);
  state.counters["feasible"] = d.feasible;
  state.counters["err_point_per_seg"] = d.feasible ? m / mean_segment(target) : INFINITY;
}

void BM_CeresTrajectories(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const MiuraString s = random_string(n, 2);
  TrajectoryTarget t;
  t.theta = {0.1, 0.2, 0.3, 0.4, 0.5};
  t.phi.assign(n, {});
  t.psi.assign(n, {});
  for (double th : t.theta) {
    const StringState st = string_forward(s, th);
    for (int i = 0; i < n; ++i) {
      t.phi[i].push_back(st.vertices[i].phi);
      t.psi[i].push_back(st.vertices[i].psi);
    }
  }
  TrajectoryFitResult r;
  for (auto _ : state) benchmark::DoNotOptimize(r = fit_string_trajectories(t, {}, 200, /*closed_form_start=*/false));
  double err = 0;
  for (int i = 0; i < n; ++i) err = std::max({err, std::fabs(r.alpha1[i] - s.alpha1[i]), std::fabs(r.alpha2[i] - s.alpha2[i])});
  state.counters["err_residual_rad"] = r.max_residual;
  state.counters["err_alpha_rad"] = err;
  state.counters["iterations"] = r.iterations;
}

// NLopt, two cases per algorithm:
//  Recover: a reachable target (a known string's spine) from a generic start (alpha = 45
//    deg, theta0 and roll off), so the optimiser has to do all the work; error -> 0 is
//    success.
//  Unreachable: a smooth helix (every turn the same way; the alternating theta cannot
//    follow) from the closed-form seed; the error is the best fit found (lower is better).
void nlopt_case(benchmark::State& state, const char* algorithm, bool global, bool recover) {
  const int n = static_cast<int>(state.range(0));
  std::vector<Eigen::Vector3d> target;
  NloptFitOptions o;
  if (recover) {
    target = string_forward(random_string(n, 3), 0.5, StringPose{}).spine;
    o.seed.theta0 = 0.4;
    o.seed.roll = 0.2;
    o.closed_form_seed = false;
  } else {
    for (int k = 0; k < n + 2; ++k) target.emplace_back(3 * std::cos(to_radians(k * 20)), 3 * std::sin(to_radians(k * 20)), 0.3 * k);
    o.seed.theta_samples = 8;
    o.seed.roll_samples = 24;
  }
  o.algorithm = algorithm;
  o.global = global;
  o.global_evaluations = 5000;
  o.max_time = n >= 1000 ? 8 : 3;
  o.max_evaluations = 5000;
  NloptFitResult r;
  for (auto _ : state) benchmark::DoNotOptimize(r = fit_string_to_curve(target, o));
  state.counters["err_point_per_seg"] = r.max_error / r.mean_segment;
  state.counters["err_rms_per_seg"] = r.rms_error / r.mean_segment;
  state.counters["evaluations"] = r.evaluations;
  std::string label = r.algorithm;
  label.append(1, ' ').append(r.status);
  state.SetLabel(label);
}

void BM_NloptRecover_SLSQP(benchmark::State& s) { nlopt_case(s, "LD_SLSQP", false, true); }
void BM_NloptRecover_CCSAQ(benchmark::State& s) { nlopt_case(s, "LD_CCSAQ", false, true); }
void BM_NloptRecover_MMA(benchmark::State& s) { nlopt_case(s, "LD_MMA", false, true); }
void BM_NloptRecover_COBYLA(benchmark::State& s) { nlopt_case(s, "LN_COBYLA", false, true); }
void BM_NloptRecover_ISRES_SLSQP(benchmark::State& s) { nlopt_case(s, "LD_SLSQP", true, true); }
void BM_NloptUnreachable_SLSQP(benchmark::State& s) { nlopt_case(s, "LD_SLSQP", false, false); }
void BM_NloptUnreachable_CCSAQ(benchmark::State& s) { nlopt_case(s, "LD_CCSAQ", false, false); }
void BM_NloptUnreachable_ISRES_SLSQP(benchmark::State& s) { nlopt_case(s, "LD_SLSQP", true, false); }

}  // namespace

BENCHMARK(BM_ClosedFormDeflections)->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ClosedFormCurve)->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CeresTrajectories)->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptRecover_SLSQP)->Arg(10)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptRecover_CCSAQ)->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptRecover_MMA)->Arg(10)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptRecover_COBYLA)->Arg(10)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptRecover_ISRES_SLSQP)->Arg(10)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptUnreachable_SLSQP)->Arg(10)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptUnreachable_CCSAQ)->Arg(10)->Arg(100)->Arg(1000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NloptUnreachable_ISRES_SLSQP)->Arg(10)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
