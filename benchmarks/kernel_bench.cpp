// Foundation benchmarks: FOLD parsing, topology, single-vertex closure and Jacobian, and
// folding a Miura-ori by face placement. Each reports the error it reached next to its time
// (counter "rel_mismatch": closure mismatch of the folded Miura relative to its size).
#include <benchmark/benchmark.h>

#include <numbers>
#include <random>

#include "data/generators/miura.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {
namespace {

generators::MiuraParams miura_params(int n) {
  generators::MiuraParams m;
  m.rows = n;
  m.cols = n;
  m.alpha = std::numbers::pi / 3;
  return m;
}

void BM_ParseFold(benchmark::State& state) {
  const std::string text = write_fold_string(generators::miura_ori(miura_params(static_cast<int>(state.range(0)))));
  for (auto _ : state) benchmark::DoNotOptimize(parse_fold(text, "bench"));
  state.counters["edges"] = static_cast<double>(generators::miura_ori(miura_params(static_cast<int>(state.range(0)))).num_edges());
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_ParseFold)->Arg(10)->Arg(30)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_BuildTopology(benchmark::State& state) {
  const CreasePattern p = generators::miura_ori(miura_params(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(build_topology(p));
  state.counters["edges"] = p.num_edges();
}
BENCHMARK(BM_BuildTopology)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Unit(benchmark::kMillisecond);

void BM_VertexClosureJacobian(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.2, 1.2);
  std::vector<double> sectors(n), rho(n);
  for (int i = 0; i < n; ++i) {
    sectors[i] = u(rng);
    rho[i] = u(rng) - 0.7;
  }
  Eigen::Vector3d r;
  Eigen::Matrix3Xd J(3, n);
  for (auto _ : state) {
    vertex_closure_jacobian(sectors, rho, r, J);
    benchmark::DoNotOptimize(J.data());
  }
  state.counters["residual_norm"] = r.norm();
}
BENCHMARK(BM_VertexClosureJacobian)->Arg(4)->Arg(6)->Arg(8);

void BM_FoldMiuraByFacePlacement(benchmark::State& state) {
  const auto params = miura_params(static_cast<int>(state.range(0)));
  const CreasePattern p = generators::miura_ori(params);
  const Topology t = build_topology(p);
  const Eigen::VectorXd rho = fold_angle_vector(generators::miura_fold_angles(p, params, 2.0));
  const Eigen::VectorXd ref = Eigen::VectorXd::Zero(p.num_edges());
  double mismatch = 0;
  for (auto _ : state) {
    const FoldedGeometry g = place_faces(p, t, rho, ref);
    mismatch = g.relative_mismatch();
    benchmark::DoNotOptimize(g.vertices.data());
  }
  state.counters["edges"] = p.num_edges();
  state.counters["rel_mismatch"] = mismatch;
}
BENCHMARK(BM_FoldMiuraByFacePlacement)->Arg(10)->Arg(30)->Arg(100)->Arg(300)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rigidfold

BENCHMARK_MAIN();
