// Seed systems' design-space tools, time against size with the result's own check as a
// counter:
//   BM_WaterbombBistability/n   every equilibrium of the n-fold waterbomb base (closed form
//                               on the symmetric path, each state re-checked on the general
//                               2n-crease problem); counters: states, worst stationarity residual
//   BM_WaterbombCurve/n         181 samples of energy and force-deflection, each a loaded
//                               equilibrium of the general model; counter: unchecked samples
//   BM_Assignments/kind/n       M-V assignment enumeration in symmetry classes (kind 0: Miura
//                               n x n panels, no verdicts; kind 1: units P, Q and the square
//                               twist with every class's verdict); counters: assignments, classes
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "data/generators/double_corrugated.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_curve.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"

namespace {

using namespace rigidfold;

void BM_WaterbombBistability(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  waterbomb::WaterbombBistability r;
  for (auto _ : state) r = waterbomb::waterbomb_bistability(n, to_radians(45.0), 2.0, 1.0);
  double worst = 0.0;
  for (const auto& e : r.equilibria)
    if (std::isfinite(e.stationarity_residual)) worst = std::max(worst, e.stationarity_residual);
  state.counters["states"] = static_cast<double>(r.equilibria.size());
  state.counters["stable"] = static_cast<double>(r.stable_states().size());
  state.counters["stationarity_residual"] = worst;
}

void BM_WaterbombCurve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  waterbomb::WaterbombCurve c;
  for (auto _ : state) c = waterbomb::waterbomb_curve(n, to_radians(45.0), 2.0, 1.0, 181);
  state.counters["samples"] = static_cast<double>(c.samples.size());
  state.counters["unchecked"] = c.unchecked;
}

void BM_Assignments(benchmark::State& state) {
  const int kind = static_cast<int>(state.range(0));
  const int n = static_cast<int>(state.range(1));
  CreasePattern p;
  if (kind == 0) {
    generators::MiuraParams m;
    m.rows = m.cols = n;
    p = generators::miura_ori(m);
  } else if (n == 0) {
    p = generators::corrugated_unit(generators::CorrugatedUnit::P, {}, generators::corrugated_rigid_assignment(generators::CorrugatedUnit::P));
  } else if (n == 1) {
    p = generators::corrugated_unit(generators::CorrugatedUnit::Q, {}, generators::corrugated_rigid_assignment(generators::CorrugatedUnit::Q));
  } else {
    p = generators::square_twist({}, generators::SquareTwistType::Type1);
  }
  const Topology t = build_topology(p);
  AssignmentEnumerationOptions o;
  o.max_verdicts = kind == 0 ? 0 : 100'000;
  AssignmentEnumeration r;
  for (auto _ : state) r = enumerate_assignments(p, t, o);
  state.counters["creases"] = static_cast<double>(r.creases.size());
  state.counters["assignments"] = static_cast<double>(r.assignments);
  state.counters["classes"] = static_cast<double>(r.class_count);
  state.counters["rigid_classes"] = static_cast<double>(r.foldable_classes);
}

void register_all() {
  auto add = [](const char* name, void (*fn)(benchmark::State&)) {
    return benchmark::RegisterBenchmark(name, fn)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
  };
  for (int n = 3; n <= 12; ++n) add("BM_WaterbombBistability", BM_WaterbombBistability)->Arg(n);
  for (int n : {3, 4, 6, 8, 12}) add("BM_WaterbombCurve", BM_WaterbombCurve)->Arg(n)->Iterations(1);
  for (int n : {3, 4, 5, 6}) add("BM_Assignments", BM_Assignments)->Args({0, n})->Iterations(1);
  for (int u : {0, 1, 2}) add("BM_Assignments", BM_Assignments)->Args({1, u});
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
