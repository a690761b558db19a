// Asymmetric Miura vertex closed form: time per evaluation, and the worst relative error of
// phi, psi and the fold angles against the 50-digit reference (reference/miura_reference.hpp)
// over the same inputs, printed as counters. BM_MiuraVertexRotation times the frame rotation.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "kernel/math/angle_units.hpp"
#include "kernel/math/so3.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "reference/miura_reference.hpp"

namespace rigidfold {
namespace {

struct Input {
  double a1, a2, th;
};

// Random alphas in [5, 85] deg; theta spread over the whole range, a quarter of them near
// flat (|theta| down to 1e-9) and a quarter near the limit.
const std::vector<Input>& inputs() {
  static const std::vector<Input> in = [] {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> alpha(to_radians(5), to_radians(85)), u(0.0, 1.0);
    std::vector<Input> v;
    for (int i = 0; i < 1024; ++i) {
      const double a1 = alpha(rng), a2 = alpha(rng), lim = miura_theta_limit(a1, a2);
      double th = u(rng) * lim;
      if (i % 4 == 1) th = std::pow(10.0, -9.0 + 6.0 * u(rng));
      if (i % 4 == 2) th = lim - std::pow(10.0, -9.0 + 6.0 * u(rng));
      v.push_back({a1, a2, (i % 2 ? -th : th)});
    }
    return v;
  }();
  return in;
}

struct Errors {
  double phi = 0, psi = 0, fold = 0;
};

// Worst relative errors over inputs(); psi skipped where the reference |a_x| < 1e-8 (its
// arctan(a_y / a_x) definition jumps there, see the header).
Errors reference_errors() {
  using test::Real50;
  Errors e;
  const auto rel = [](double x, const Real50& r) { return static_cast<double>(abs(Real50(x) - r) / abs(r)); };
  for (const Input& in : inputs()) {
    const MiuraVertexState st = miura_vertex(in.a1, in.a2, in.th);
    const auto ref = test::miura_reference<Real50>(in.a1, in.a2, in.th);
    e.phi = std::max(e.phi, rel(st.phi, ref.phi));
    if (in.a1 != in.a2 && abs(ref.a[0]) > Real50(1e-8)) e.psi = std::max(e.psi, rel(st.psi, ref.psi));
    for (int i = 0; i < 4; ++i) e.fold = std::max(e.fold, rel(st.fold_angles[i], ref.rho[i]));
  }
  return e;
}

void BM_MiuraVertex(benchmark::State& state) {
  const auto& in = inputs();
  std::size_t k = 0;
  for (auto _ : state) {
    const Input& x = in[k++ & 1023];
    const MiuraVertexState st = miura_vertex(x.a1, x.a2, x.th);
    benchmark::DoNotOptimize(st.phi);
    benchmark::DoNotOptimize(st.fold_angles.data());
  }
  const Errors e = reference_errors();
  state.counters["max_rel_err_phi"] = e.phi;
  state.counters["max_rel_err_psi"] = e.psi;
  state.counters["max_rel_err_fold"] = e.fold;
}
BENCHMARK(BM_MiuraVertex);

void BM_MiuraVertexRotation(benchmark::State& state) {
  const auto& in = inputs();
  std::size_t k = 0;
  double orth = 0.0;
  for (auto _ : state) {
    const Input& x = in[k++ & 1023];
    const Eigen::Matrix3d R = miura_vertex_rotation(x.a1, x.a2, x.th);
    benchmark::DoNotOptimize(R.data());
  }
  for (const Input& x : in) {
    const Eigen::Matrix3d R = miura_vertex_rotation(x.a1, x.a2, x.th);
    orth = std::max(orth, orthonormality_error(R));
  }
  state.counters["max_orthogonality_err"] = orth;
}
BENCHMARK(BM_MiuraVertexRotation);

}  // namespace
}  // namespace rigidfold

BENCHMARK_MAIN();
