// Seed systems' design-space tools, time against size with the result's own check as a
// counter:
//   BM_WaterbombBistability/n   every equilibrium of the n-fold waterbomb base (closed form
//                               on the symmetric path, each state re-checked on the general
//                               2n-crease problem); counters: states, worst stationarity residual
//   BM_WaterbombCurve/n         181 samples of energy and force-deflection, each a loaded
//                               equilibrium of the general model; counter: unchecked samples
//   BM_StableStateSearch/n      the general multistart search (kernel/energy/stable_state_search,
//                               rest at theta0 = 45 deg, k_m = 2 k_v, 24 random starts) on the
//                               n-fold base; counters: states keeping the letters, the largest
//                               fold-angle gap of the two symmetric ones to the closed form
//   BM_TessellationStableStates/n  the same search (4 random starts) on an n x n waterbomb
//                               tessellation with equal springs resting at a closed state near
//                               flat; counters: free creases, states, worst closure residual
//   BM_Assignments/kind/n       M-V assignment enumeration in symmetry classes (kind 0: Miura
//                               n x n panels, no verdicts; kind 1: units P, Q and the square
//                               twist with every class's verdict); counters: assignments, classes
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "data/generators/double_corrugated.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "data/generators/waterbomb.hpp"
#include "data/generators/waterbomb_tessellation.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "design/waterbomb/waterbomb_curve.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/stable_state_search.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/portable_random.hpp"
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

void BM_StableStateSearch(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  generators::WaterbombParams wp;
  wp.n = n;
  const CreasePattern p = generators::waterbomb_base(wp);
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t);
  const double theta0 = to_radians(45.0);
  const Eigen::VectorXd rest = waterbomb::waterbomb_edge_angles(p, waterbomb::waterbomb_fold_angles(n, theta0));
  const CreaseSprings springs = make_crease_springs(p, stiffness_by_assignment(p, {2.0, 1.0, 1.0}), rest);
  StableStateSearch s;
  for (auto _ : state) s = search_stable_states(p, t, sys, springs, rest);
  const auto closed = waterbomb::waterbomb_bistability(n, theta0, 2.0, 1.0).stable_states();
  double gap = 0.0;
  int physical = 0;
  for (const auto& f : s.states)
    if (f.physical()) ++physical;
  for (const auto& c : closed) {
    double best = 1e300;
    for (const auto& f : s.states) best = std::min(best, (f.state.edge_angles - waterbomb::waterbomb_edge_angles(p, c.path.angles)).lpNorm<Eigen::Infinity>());
    gap = std::max(gap, best);
  }
  state.counters["states_keeping_letters"] = physical;
  state.counters["closed_form_states"] = static_cast<double>(closed.size());
  state.counters["error_vs_closed_form"] = gap;
}

void BM_TessellationStableStates(benchmark::State& state) {
  generators::WaterbombTessellationParams wp;
  wp.rows = wp.cols = static_cast<int>(state.range(0));
  const CreasePattern p = generators::waterbomb_tessellation(wp);
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t);
  SplitMix64 rng{5};
  Eigen::VectorXd x0(sys.num_unknowns());
  for (int k = 0; k < x0.size(); ++k) x0[k] = 0.4 * (rng.uniform() - 0.5);
  const NewtonResult rest_state = newton_project(sys, x0);
  const Eigen::VectorXd rest = sys.edges_from_unknowns(rest_state.x);
  const CreaseSprings springs = make_crease_springs(p, stiffness_by_assignment(p, {1.0, 1.0, 1.0}), rest);
  StableStateSearchOptions o;
  o.random_starts = 4;
  StableStateSearch s;
  for (auto _ : state) s = search_stable_states(p, t, sys, springs, rest, o);
  double worst = 0.0;
  for (const auto& f : s.states) worst = std::max(worst, f.state.closure_residual);
  state.counters["free_creases"] = sys.num_unknowns();
  state.counters["rest_residual"] = rest_state.residual_history.back();
  state.counters["states"] = static_cast<double>(s.states.size());
  state.counters["closure_residual"] = worst;
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
  for (int n = 3; n <= 12; ++n) add("BM_StableStateSearch", BM_StableStateSearch)->Arg(n)->Iterations(1);
  for (int n : {4, 10}) add("BM_TessellationStableStates", BM_TessellationStableStates)->Arg(n)->Iterations(1);
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
