// Algebraic multigrid against CHOLMOD on the corrector's linear system: hypre
// BoomerAMG as an iterative path for large systems (one of two candidate routes).
//
// The system is the one every Newton step of the general corrector solves (newton_projection.hpp):
//       G dx = J_f^T r,   G = J_f^T J_f + lambda I,   lambda = 1e-14 max diag(G),
// J_f the Jacobian of a Miura n x n (miura_case.hpp) at its closed form plus 1e-4 rad of noise,
// with crease 0 held (its column dropped), so G is symmetric positive definite.
//   BM_CholmodStep/n:   MinimumNormSolver: symbolic analysis, factorisation and the solve
//                       (with its refinement), the corrector's direct step from scratch.
//   BM_AmgPcgStep/n/s:  G formed from J_f (Eigen), copied into hypre's IJ matrix, BoomerAMG set
//                       up and hypre's PCG preconditioned by one V-cycle per iteration, to a
//                       relative residual ||G dx - b||_2 <= 1e-10 ||b||_2 (about what the direct
//                       step reaches). s, the strength of connection (G is not an M-matrix: its
//                       off-diagonal entries have both signs):
//                         0: hypre's default (classical: strong only on negative entries, 0.25;
//                            run up to 100 x 100 only: it hardly coarsens, ~300 iterations there);
//                         1, 2, 3: on |g_ij| (HYPRE_BoomerAMGSetSabs), threshold 0.5, 0.8, 0.9.
//                       Everything else is hypre 2.26's default (HMIS coarsening, extended+i
//                       interpolation, hybrid symmetric Gauss-Seidel, one sweep).
// Counters: pcg_iterations, s_setup / s_solve (AMG setup, PCG solve; the rest of the time is
// forming and copying G), relative_residual (hypre's), step_difference (||dx - dx_cholmod||_inf
// / ||dx_cholmod||_inf: the AMG step against the direct one, a cross-check of both),
// linear_residual (||J_f dx - r||_inf, as BM_Factorize reports it), edges, peak_rss_mb (of the
// whole process so far: bench_report.sh runs amg_bench as one process).
// Built only where hypre and MPI are found (benchmarks/CMakeLists.txt); hypre needs MPI
// initialised even on one process, hence the main() below.
#include <HYPRE.h>
#include <HYPRE_krylov.h>
#include <HYPRE_parcsr_ls.h>
#include <benchmark/benchmark.h>
#include <mpi.h>

#include <Eigen/SparseCore>
#include <chrono>
#include <cstdlib>
#include <vector>

#include "benchmarks/miura_case.hpp"
#include "benchmarks/peak_memory.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {
namespace {

using bench::MiuraCase;
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The corrector's system at the perturbed start: J, r, and the direct step (held crease 0).
struct StepCase {
  MiuraCase miura;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  explicit StepCase(int n) : miura(n) { miura.system.evaluate(miura.start, r, J); }
  Eigen::VectorXd direct_step() const {
    MinimumNormSolver solver(J, {0});
    if (!solver.factorize(J, 1e-14)) return {};
    return solver.solve(J, r);
  }
};

void BM_CholmodStep(benchmark::State& state) {
  const StepCase c(static_cast<int>(state.range(0)));
  Eigen::VectorXd dx;
  for (auto _ : state) {
    dx = c.direct_step();
    benchmark::DoNotOptimize(dx.data());
  }
  if (dx.size() == 0) {
    state.SkipWithError("CHOLMOD factorisation failed");
    return;
  }
  state.counters["linear_residual"] = (c.J * dx - c.r).lpNorm<Eigen::Infinity>();
  state.counters["edges"] = c.miura.pattern.num_edges();
  state.counters["peak_rss_mb"] = bench::peak_rss_mb();
}

// hypre objects of one solve, destroyed on every path.
struct HypreSolve {
  HYPRE_IJMatrix A = nullptr;
  HYPRE_IJVector b = nullptr, x = nullptr;
  HYPRE_Solver pcg = nullptr, amg = nullptr;
  ~HypreSolve() {
    if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (x) HYPRE_IJVectorDestroy(x);
    if (b) HYPRE_IJVectorDestroy(b);
    if (A) HYPRE_IJMatrixDestroy(A);
  }
};

HYPRE_IJVector make_vector(int n, const std::vector<HYPRE_Int>& rows, const double* values) {
  HYPRE_IJVector v;
  HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &v);
  HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
  HYPRE_IJVectorInitialize(v);
  HYPRE_IJVectorSetValues(v, n, rows.data(), values);
  HYPRE_IJVectorAssemble(v);
  return v;
}

void BM_AmgPcgStep(benchmark::State& state) {
  const StepCase c(static_cast<int>(state.range(0)));
  const int strength = static_cast<int>(state.range(1));
  const int n = static_cast<int>(c.J.cols()) - 1;  // crease 0 held
  const Eigen::SparseMatrix<double> Jf = c.J.rightCols(n);
  Eigen::VectorXd dx_kept(n);
  int iterations = 0;
  double relative_residual = 0, s_setup = 0, s_solve = 0;
  for (auto _ : state) {
    Eigen::SparseMatrix<double, Eigen::RowMajor> G = Jf.transpose() * Jf;
    const double lambda = 1e-14 * G.diagonal().maxCoeff();
    for (int i = 0; i < n; ++i) G.coeffRef(i, i) += lambda;
    G.makeCompressed();
    const Eigen::VectorXd rhs = Jf.transpose() * c.r;
    std::vector<HYPRE_Int> rows(n), row_sizes(n);
    for (int i = 0; i < n; ++i) {
      rows[i] = i;
      row_sizes[i] = G.outerIndexPtr()[i + 1] - G.outerIndexPtr()[i];
    }
    HypreSolve h;
    HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, n - 1, 0, n - 1, &h.A);
    HYPRE_IJMatrixSetObjectType(h.A, HYPRE_PARCSR);
    HYPRE_IJMatrixSetRowSizes(h.A, row_sizes.data());
    HYPRE_IJMatrixInitialize(h.A);
    HYPRE_IJMatrixSetValues(h.A, n, row_sizes.data(), rows.data(), G.innerIndexPtr(), G.valuePtr());
    HYPRE_IJMatrixAssemble(h.A);
    const std::vector<double> zero(n, 0.0);
    h.b = make_vector(n, rows, rhs.data());
    h.x = make_vector(n, rows, zero.data());
    HYPRE_ParCSRMatrix A;
    HYPRE_ParVector b, x;
    HYPRE_IJMatrixGetObject(h.A, reinterpret_cast<void**>(&A));
    HYPRE_IJVectorGetObject(h.b, reinterpret_cast<void**>(&b));
    HYPRE_IJVectorGetObject(h.x, reinterpret_cast<void**>(&x));

    HYPRE_BoomerAMGCreate(&h.amg);
    HYPRE_BoomerAMGSetPrintLevel(h.amg, 0);
    HYPRE_BoomerAMGSetMaxIter(h.amg, 1);  // one V-cycle per preconditioner application
    HYPRE_BoomerAMGSetTol(h.amg, 0.0);
    if (strength > 0) {
      HYPRE_BoomerAMGSetSabs(h.amg, 1);
      HYPRE_BoomerAMGSetStrongThreshold(h.amg, strength == 1 ? 0.5 : strength == 2 ? 0.8 : 0.9);
    }
    HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &h.pcg);
    HYPRE_PCGSetTol(h.pcg, 1e-10);
    HYPRE_PCGSetTwoNorm(h.pcg, 1);
    HYPRE_PCGSetMaxIter(h.pcg, 2000);
    HYPRE_PCGSetPrecond(h.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), h.amg);
    auto t0 = Clock::now();
    HYPRE_ParCSRPCGSetup(h.pcg, A, b, x);
    s_setup = seconds_since(t0);
    t0 = Clock::now();
    HYPRE_ParCSRPCGSolve(h.pcg, A, b, x);
    s_solve = seconds_since(t0);
    HYPRE_Int its = 0;
    HYPRE_PCGGetNumIterations(h.pcg, &its);
    HYPRE_PCGGetFinalRelativeResidualNorm(h.pcg, &relative_residual);
    iterations = its;
    HYPRE_IJVectorGetValues(h.x, n, rows.data(), dx_kept.data());
  }
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(n + 1);
  dx.tail(n) = dx_kept;
  const Eigen::VectorXd direct = c.direct_step();
  state.counters["pcg_iterations"] = iterations;
  state.counters["relative_residual"] = relative_residual;
  state.counters["s_setup"] = s_setup;
  state.counters["s_solve"] = s_solve;
  state.counters["strength"] = strength;
  if (direct.size() == n + 1)
    state.counters["step_difference"] =
        (dx - direct).lpNorm<Eigen::Infinity>() / direct.lpNorm<Eigen::Infinity>();
  state.counters["linear_residual"] = (c.J * dx - c.r).lpNorm<Eigen::Infinity>();
  state.counters["edges"] = c.miura.pattern.num_edges();
  state.counters["peak_rss_mb"] = bench::peak_rss_mb();
  if (!(relative_residual <= 1e-10)) state.SkipWithError("hypre PCG did not reach 1e-10 in 2000 iterations");
}

// Sizes: 30, 100 and 200 cells (1.8k to 80k creases); RIGIDFOLD_BENCH_LARGE >= 1 adds 320.
void register_all() {
  const char* env = std::getenv("RIGIDFOLD_BENCH_LARGE");
  std::vector<int> sizes = {30, 100, 200};
  if (env && std::atoi(env) >= 1) sizes.push_back(320);
  for (int n : sizes) {
    benchmark::RegisterBenchmark("BM_CholmodStep", BM_CholmodStep)
        ->Arg(n)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
    for (int s : {0, 1, 2, 3}) {
      if (s == 0 && n > 100) continue;  // classical strength: ~300 iterations at 100 x 100 already
      benchmark::RegisterBenchmark("BM_AmgPcgStep", BM_AmgPcgStep)
          ->Args({n, s})->Iterations(1)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();
    }
  }
}

}  // namespace
}  // namespace rigidfold

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  rigidfold::register_all();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  MPI_Finalize();
  return 0;
}
