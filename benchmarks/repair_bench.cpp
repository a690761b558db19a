// Repair to rigid foldability (design/repair/pattern_repair.hpp), time against size:
//   BM_RepairJitteredMiura/n   an n x n Miura-ori (alpha 60 deg, a = b = 1) whose interior
//                              vertices moved by up to 0.02 (uniform, seed 1), repaired back
//                              to foldable with its letters. Counters: the constraints met
//                              (largest Kawasaki defect and |log loop gain| after), the
//                              RMS move over the RMS jitter (<= 1: the exact Miura is one
//                              pattern meeting the constraints), SQP iterations, and the
//                              seconds spent in the two checks (before and after) of the total.
#include <benchmark/benchmark.h>

#include <cmath>

#include "data/generators/miura.hpp"
#include "design/repair/pattern_repair.hpp"
#include "kernel/pattern/topology.hpp"

namespace {

using namespace rigidfold;

void BM_RepairJitteredMiura(benchmark::State& state) {
  generators::MiuraParams params;
  params.rows = params.cols = static_cast<int>(state.range(0));
  params.perturbation = 0.02;
  const CreasePattern jittered = generators::miura_ori(params);
  params.perturbation = 0;
  const CreasePattern exact = generators::miura_ori(params);
  const Topology topology = build_topology(jittered);
  RepairSummary s;
  for (auto _ : state) s = repair_pattern(jittered, topology);
  double jitter = 0;
  for (int v = 0; v < exact.num_vertices(); ++v) jitter += (exact.vertices[v] - jittered.vertices[v]).squaredNorm();
  jitter = std::sqrt(jitter / exact.num_vertices());
  state.counters["repaired"] = s.termination == RepairTermination::kRepaired ? 1 : 0;
  state.counters["creases"] = static_cast<double>(jittered.num_edges());
  state.counters["kawasaki_after"] = s.kawasaki_after;
  state.counters["gain_after"] = s.gain_after;
  state.counters["move_over_jitter"] = s.rms_move / jitter;
  state.counters["iterations"] = s.iterations;
  state.counters["check_seconds"] = s.before.seconds + (s.after ? s.after->seconds : 0.0);
}

}  // namespace

BENCHMARK(BM_RepairJitteredMiura)->Arg(10)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
