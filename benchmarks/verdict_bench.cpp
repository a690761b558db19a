// Verdict paths on the same Miura-ori patterns: the exact multiplier propagation (whole
// verdict with its certificate) against one general-solver corrector (CHOLMOD Newton
// projection to 1e-12 from the closed form perturbed by 1e-4, one crease held). Each run
// reports the error reached: "max_defect" (loop gain) / "mismatch" for the multiplier
// path; "residual" and "error_vs_closed_form" for the corrector.
//
// The general cases beside the Miura: `check`'s front door (check_foldability) on Resch
// triangle tessellations of 376 to ~4,000 creases and on every crease-pattern file of the corpus (tests/data/corpus, as for the tests), and the
// general verdict forced on a jittered Miura (interior vertices moved by up to 0.01 of the
// default panel size: not foldable, which `check` proves by the multiplier model's loop gain,
// 0.34 s at 100 x 100; the general solver's evidence search is what is timed here). Their
// counters: the verdict class (0 foldable, 1 within tolerance, 2 not foldable proof, 3 not
// foldable evidence, 4 undecided), the model and, for the general verdict, the least
// residual per amplitude.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "data/generators/miura.hpp"
#include "data/generators/resch_triangle.hpp"
#include "data/generators/waterbomb_tessellation.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/general_verdict.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/read_pattern.hpp"
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

// The corpus's .fold and .svg files, sorted (empty if there is no corpus).
std::vector<std::filesystem::path> corpus_files() {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  if (!std::filesystem::is_directory(RIGIDFOLD_CORPUS_DIR, ec)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(RIGIDFOLD_CORPUS_DIR, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".fold" || ext == ".svg")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// `check FILE` as the CLI runs it (default options: the input's own precision, letters kept).
void BM_CheckCorpusFile(benchmark::State& state, const std::filesystem::path& file) {
  const CreasePattern p = read_pattern(file.string());
  const Topology t = build_topology(p);
  FoldabilityReport r;
  for (auto _ : state) r = check_foldability(p, t);
  state.counters["edges"] = p.num_edges();
  state.counters["verdict_class"] = static_cast<int>(r.verdict);
  state.counters["general_model"] = r.model == FoldabilityModel::kGeneralLoopClosure;
  state.SetLabel(file.filename().string() + ": " + to_string(r.verdict));
}

// The general verdict forced on an n x n Miura with its interior vertices jittered.
void BM_GeneralVerdictJitteredMiura(benchmark::State& state) {
  auto params = miura(static_cast<int>(state.range(0)));
  params.perturbation = 0.01;
  params.seed = 3;
  const CreasePattern p = generators::miura_ori(params);
  const Topology t = build_topology(p);
  GeneralVerdict v;
  for (auto _ : state) v = general_verdict(p, t);
  state.counters["edges"] = p.num_edges();
  state.counters["not_foldable"] = v.verdict == Verdict::kNotRigidlyFoldable;
  state.counters["growth_exponent"] = v.growth_exponent;
  for (const AmplitudeEvidence& e : v.evidence)
    state.counters["least_residual_at_" + std::to_string(e.amplitude)] = e.least_residual;
  state.SetLabel(to_string(v.verdict));
}

// The multi-DOF case: the general verdict on an n x n waterbomb
// tessellation (2 (rows + cols) - 3 DOF), certified by the fold-size trace.
void BM_GeneralVerdictWaterbombTessellation(benchmark::State& state) {
  generators::WaterbombTessellationParams params;
  params.rows = params.cols = static_cast<int>(state.range(0));
  const CreasePattern p = generators::waterbomb_tessellation(params);
  const Topology t = build_topology(p);
  GeneralVerdict v;
  for (auto _ : state) v = general_verdict(p, t);
  state.counters["edges"] = p.num_edges();
  state.counters["foldable"] = v.verdict == Verdict::kRigidlyFoldable;
  state.counters["strict"] = v.strictness.strict;
  state.counters["dof"] = v.trace.dof_at_departure;
  state.counters["points"] = static_cast<double>(v.trace.path.size());
  state.counters["factorizations"] = v.trace.factorizations;
  state.counters["max_residual"] = v.trace.max_residual;
  state.SetLabel(std::string(to_string(v.verdict)) + (v.trace_method.empty() ? "" : ", " + v.trace_method));
}

// `check` (letters kept) on a Resch triangle tessellation of n x n grid rows and edges: a
// general-solver pattern with a high-DOF flat state (DOF ~ creases / 7), certified strictly
// foldable by the fold-size trace. Counters: creases, the verdict class, strict, DOF.
void BM_CheckReschTriangle(benchmark::State& state) {
  generators::ReschTriangleParams params;
  params.rows = params.cols = static_cast<int>(state.range(0));
  const CreasePattern p = generators::resch_triangle(params);
  const Topology t = build_topology(p);
  FoldabilityReport r;
  for (auto _ : state) r = check_foldability(p, t);
  state.counters["creases"] = static_cast<double>(std::count_if(p.assignments.begin(), p.assignments.end(), [](Assignment a) {
    return a == Assignment::Mountain || a == Assignment::Valley;
  }));
  state.counters["verdict_class"] = static_cast<int>(r.verdict);
  state.counters["strict"] = r.strictness && r.strictness->strict;
  state.counters["dof"] = r.dof;
  state.SetLabel(to_string(r.verdict));
}

void register_general_cases() {
  for (int n : {10, 16, 24, 32})
    benchmark::RegisterBenchmark("BM_CheckReschTriangle", BM_CheckReschTriangle)
        ->Arg(n)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();
  for (const std::filesystem::path& file : corpus_files())
    benchmark::RegisterBenchmark(
        ("BM_CheckCorpusFile/" + file.parent_path().filename().string() + "/" + file.stem().string()).c_str(),
        BM_CheckCorpusFile, file)
        ->Unit(benchmark::kMillisecond)->Iterations(1);
  for (int n : {30, 100, 200})
    benchmark::RegisterBenchmark("BM_GeneralVerdictJitteredMiura", BM_GeneralVerdictJitteredMiura)
        ->Arg(n)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();
  for (int n : {8, 16, 32})
    benchmark::RegisterBenchmark("BM_GeneralVerdictWaterbombTessellation", BM_GeneralVerdictWaterbombTessellation)
        ->Arg(n)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime()->UseRealTime();
}

}  // namespace
}  // namespace rigidfold

int main(int argc, char** argv) {
  rigidfold::register_general_cases();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
