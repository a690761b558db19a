// Verdict paths on the same Miura-ori patterns: the exact multiplier propagation (whole
// verdict with its certificate) against one general-solver corrector (CHOLMOD Newton
// projection to 1e-12 from the closed form perturbed by 1e-4, one crease held). Each run
// reports the error reached: "max_defect" (loop gain) / "mismatch" for the multiplier
// path; "residual" and "error_vs_closed_form" for the corrector.
#include <benchmark/benchmark.h>

#include <numbers>
#include <random>

#include "data/generators/miura.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {
namespace {

generators::MiuraParams miura(int n) {
  generators::MiuraParams m;
  m.rows = m.cols = n;
  m.alpha = std::numbers::pi / 3;
  return m;
}

void BM_MultiplierVerdict(benchmark::State& state) {
  const CreasePattern p = generators::miura_ori(miura(static_cast<int>(state.range(0))));
  const Topology t = build_topology(p);
  FoldabilityVerdict v;
  for (auto _ : state) v = verdict_with_assignment(p, t);
  state.counters["edges"] = p.num_edges();
  state.counters["max_defect"] = v.max_loop_defect;
  state.counters["mismatch"] = v.certificate_mismatch;
  state.counters["foldable"] = v.verdict == Verdict::kRigidlyFoldable;
}
BENCHMARK(BM_MultiplierVerdict)->Arg(10)->Arg(30)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

void BM_GeneralCorrector(benchmark::State& state) {
  const auto params = miura(static_cast<int>(state.range(0)));
  const CreasePattern p = generators::miura_ori(params);
  const Topology t = build_topology(p);
  const ClosureSystem system(p, t);
  const Eigen::VectorXd x_exact = system.unknowns_from_edges(fold_angle_vector(generators::miura_fold_angles(p, params, 1.2)));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> noise(-1e-4, 1e-4);
  Eigen::VectorXd x0 = x_exact;
  for (int k = 1; k < x0.size(); ++k) x0[k] += noise(rng);  // unknown 0 is held at its exact value
  NewtonOptions options;
  options.held_unknowns = {0};
  NewtonResult r;
  for (auto _ : state) r = newton_project(system, x0, options);
  state.counters["edges"] = p.num_edges();
  state.counters["iterations"] = r.iterations;
  state.counters["residual"] = r.residual_history.back();
  state.counters["error_vs_closed_form"] = (r.x - x_exact).cwiseAbs().maxCoeff();
}
BENCHMARK(BM_GeneralCorrector)->Arg(10)->Arg(30)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rigidfold

BENCHMARK_MAIN();
