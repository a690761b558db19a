#pragma once
// Newton projection onto the constraint manifold r(x) = 0 of a ClosureSystem: minimum-norm
// Gauss-Newton steps on a redundant, rank-deficient system (docs/DESIGN.md, "Corrector").
//
// Each step takes the minimum-norm Gauss-Newton step of J_f dx = r (J_f: J with the held
// columns removed), computed from the column-side normal equations
//       G = J_f^T J_f + lambda I,   dx = G^{-1} J_f^T r
// (one extra refinement solve on the linear residual r - J_f dx removes most of the lambda
// bias), then x <- x - dx. By the identity (J^T J + lambda I)^{-1} J^T = J^T (J J^T + lambda I)^{-1}
// this is the same step as the row-side form J_f^T (J_f J_f^T + lambda I)^{-1} r; the column
// side is smaller for loop-closure systems (a quad mesh has 3 rows per vertex but about 2
// creases per vertex, and G couples only creases that share a vertex), so its Cholesky factor
// has about 4x fewer entries and 10x fewer flops on a Miura-ori.
// For lambda -> 0 dx is the minimum-norm solution of J_f dx = r, so the iteration moves
// x the least distance that closes the loops to first order, and it converges
// quadratically at regular points of the manifold.
// G is factorised by CHOLMOD, simplicial or supernodal by CHOLMOD's rule on the symbolic
// factor: supernodal iff flops / nnz(L) >= kSupernodalFlopsPerEntry (120; CHOLMOD's default
// is 40). Measured on this 2-core machine (Miura G, factorisation of equal values, the
// supernodal one on OpenBLAS with 2 threads, which scripts/bootstrap.sh installs):
//     cells      unknowns   flops/nnz(L)   simplicial   supernodal
//     100 x 100     19,800         54       0.009 s      0.013 s
//     200 x 200     79,600         88       0.070 s      0.062 s   (a solve: 0.005 / 0.009 s)
//     300 x 300    179,400        125       0.240 s      0.157 s
//     1000 x 1000 1,998,000        325       9.06 s       1.97 s    (on ATLAS: 4.7 s)
// Below the switch the supernodal factor's BLAS calls on small supernodes and its slower
// triangular solves (the continuation's PCG solves many times per factor) cost more than
// they save; above it the dense separators of these 2D meshes dominate and BLAS-3 wins.
// G's sparsity pattern does not change between steps, so the symbolic analysis (ordering and
// the simplicial/supernodal choice) is done once; each step assembles G's values into that
// fixed pattern (O(sum over rows of nnz(row)^2)) and only refactorises. From
// kStaleNewtonMinUnknowns kept unknowns up, the steps after the first do not even refactorise
// while CGLS preconditioned by the last factor converges fast (NewtonOptions, below).
// G is singular whenever the system has DOF (it always has, for a foldable pattern), hence
// lambda > 0: lambda = lambda_relative * max diag(G), multiplied by 100 and retried if the
// numeric factorisation still meets a non-positive pivot.
//
// Units: x and residuals in radians. Tolerance on ||r||_inf.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

// Fill-reducing ordering for CHOLMOD. kDefault is CHOLMOD's own choice (AMD, and METIS too
// when AMD's fill is large; the smaller factor wins). kNestedDissection is CHOLMOD's NESDIS
// (METIS-based nested dissection), asymptotically best for 2D meshes.
enum class FactorOrdering { kDefault, kAmd, kMetis, kNestedDissection };

// CHOLMOD's supernodal_switch: a factor with at least this many flops per entry of L is
// factorised supernodally (see the measurements above).
inline constexpr double kSupernodalFlopsPerEntry = 120.0;

// Newton steps after the first reuse the last factor (CGLS preconditioned by it, see
// MinimumNormSolver::solve_with_stale_factor) when the kept unknowns are at least this many.
// Measured on this 2-core machine, idle: a Miura from its closed form plus uniform noise of
// 1e-4 / 1e-3 rad, one crease held, to 1e-12 (fresh: every step refactorised):
//     cells      unknowns    fresh               stale-factor steps
//     30 x 30       1,740    0.0021 / 0.0020 s   0.0018 / 0.0017 s
//     50 x 50       4,900    0.0065 / 0.0088 s   0.0054 / 0.0058 s
//     70 x 70       9,660    0.0142 / 0.0141 s   0.0110 / 0.0113 s
//     100 x 100    19,800    0.0344 / 0.0471 s   0.0260 / 0.0300 s
//     160 x 160    50,880         - / 0.166 s         - / 0.101 s
//     1000 x 1000 1,998,000  7.11 s (1e-4)       5.91 s (BM_Corrector, 4 CGLS iterations)
// With no crease held (a singular G) the gains were alike, except none at 30 x 30 / 1e-3.
// The switch sits above the small patterns all the same: there a stale step saves under a
// millisecond, and the verdict's least-squares searches on them keep their fresh steps.
inline constexpr int kStaleNewtonMinUnknowns = 10000;

struct NewtonOptions {
  double tolerance = 1e-12;         // stop when ||r||_inf <= tolerance (radians)
  int max_iterations = 30;          // Newton steps at most
  double lambda_relative = 1e-14;   // regularisation, relative to max diag(J J^T)
  double max_step = 0.5;            // ||dx||_inf cap per step (radians); steps are scaled down to it
  std::vector<int> held_unknowns;   // indices of unknowns kept at their starting value
  // > 0: stop early (not converged) once ||r||_inf has fallen by less than stall_factor over
  // the last stall_window steps - a least-squares search on an inconsistent system sits on
  // its plateau long before max_iterations. Newton converging, even linearly at a singular
  // solution (ratio 1/2 per step), falls by far more than 0.9 over 5 steps. 0: off.
  int stall_window = 0;
  double stall_factor = 0.9;
  FactorOrdering ordering = FactorOrdering::kDefault;
  // Projected Gauss-Newton (empty: off). Per unknown, +1: kept >= 0, -1: kept <= 0, 0: free;
  // after each step an unknown on the wrong side is set to 0 (the nearest point of the
  // box). The sign-respecting least-squares search of the verdict (a valley stays >= 0, a
  // mountain <= 0). A held unknown is never moved. Size num_unknowns() when not empty.
  std::vector<int> sign_bounds;
  // Stale-factor steps: a step after the first may solve J_f dx = r by CGLS preconditioned
  // with the previous step's factor instead of refactorising, when the kept unknowns are at
  // least stale_factor_min_unknowns (0: always; INT_MAX: never). The linear solve stops at a
  // forcing term ~ ||r||_inf (Newton stays quadratic); a step whose solve did not converge in
  // stale_max_iterations, or whose new residual is not below the old one, is not taken and a
  // fresh factorisation follows; after a step that contracted the residual by less than 10x
  // the next step refactorises. Every step, stale or fresh, ends with its own residual check.
  int stale_factor_min_unknowns = kStaleNewtonMinUnknowns;
  int stale_max_iterations = 8;
};

struct NewtonResult {
  Eigen::VectorXd x;                     // last iterate (radians)
  std::vector<double> residual_history;  // ||r||_inf at x0, x1, ..., x (radians)
  bool converged = false;                // ||r(x)||_inf <= tolerance
  int iterations = 0;                    // Newton steps taken
  int factorizations = 0;                // numeric factorisations (>= iterations; retries count)
  int symbolic_analyses = 0;             // 1 unless the pattern changed (it does not for a ClosureSystem)
  double lambda = 0.0;                   // regularisation used in the last step
  bool supernodal = false;               // G's factor was CHOLMOD's supernodal one
  int stale_steps = 0;                   // steps solved on the previous factor (no refactorisation)
  int stale_iterations = 0;              // CGLS iterations of those solves (including rejected ones)
  int stale_rejections = 0;              // stale solves or steps not taken (a fresh factorisation followed)
};

// Outcome of MinimumNormSolver::solve_with_stale_factor.
struct StaleSolveResult {
  Eigen::VectorXd dx;             // size n, 0 at held unknowns (radians)
  int iterations = 0;             // CGLS iterations, one pair of triangular solves each
  bool converged = false;         // the relative tolerance was met
  double relative_residual = 0;   // sqrt(g . M g / g0 . M g0), g the normal-equation residual
};

// The linear algebra of the corrector, reusable across Newton steps and continuation
// steps on one ClosureSystem: G = J_f^T J_f + lambda I assembled into a fixed pattern and
// factorised by CHOLMOD, the symbolic analysis done once.
// Inputs: a Jacobian J (m x n, compressed) whose sparsity pattern stays the one given to
// the constructor (ClosureSystem::evaluate guarantees it); held: unknowns whose columns
// are dropped (their step is 0).
class MinimumNormSolver {
 public:
  // supernodal_flops_per_entry: CHOLMOD's supernodal_switch (0: always supernodal, infinity:
  // always simplicial; the default is measured above).
  MinimumNormSolver(const Eigen::SparseMatrix<double>& jacobian_pattern, const std::vector<int>& held = {},
                    FactorOrdering ordering = FactorOrdering::kDefault,
                    double supernodal_flops_per_entry = kSupernodalFlopsPerEntry);
  ~MinimumNormSolver();
  MinimumNormSolver(const MinimumNormSolver&) = delete;
  MinimumNormSolver& operator=(const MinimumNormSolver&) = delete;

  // Assembles and factorises G for J. Returns false if every lambda up to 1e24 times the
  // first one met a non-positive pivot.
  bool factorize(const Eigen::SparseMatrix<double>& J, double lambda_relative);
  // Minimum-norm dx (size n, 0 at held unknowns) with J_f dx = r, one refinement. Needs a
  // successful factorize(J).
  Eigen::VectorXd solve(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r) const;
  // Least-squares dx of J_f dx = r for a Jacobian J (same pattern) other than the one the
  // factor was computed from, by CGLS preconditioned with the factor's G_o^-1: stops when
  // sqrt(g . M g) <= relative_tolerance * sqrt(g0 . M g0) (g = J_f^T (r - J_f dx)), at most
  // max_iterations. For a regular G (J_f of full column rank) this is the unique least-squares
  // step, the same the direct solve gives; with a rank-deficient J_f it is a least-squares
  // step, not necessarily the minimum-norm one. Needs a successful factorize.
  StaleSolveResult solve_with_stale_factor(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r,
                                           double relative_tolerance, int max_iterations) const;
  // Unit null vector of J_f by inverse iteration on G from `guess` (which must not be
  // orthogonal to the null space), refined so that ||J_f w|| is at round-off. Its sign
  // follows guess. Needs a successful factorize(J).
  Eigen::VectorXd null_vector(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& guess) const;
  // G^-1 V for a block V (n x b, rows of held unknowns ignored; theirs are 0 in the result):
  // one pair of triangular solves per column. Needs a successful factorize.
  Eigen::MatrixXd inverse_times(const Eigen::MatrixXd& V) const;

  double lambda() const { return lambda_; }
  int unknowns() const;       // n, the Jacobian's columns
  int kept_unknowns() const;  // n minus the held unknowns
  bool supernodal() const;    // the factor is CHOLMOD's supernodal one (false before a factorize)
  int factorizations() const { return factorizations_; }
  int symbolic_analyses() const { return symbolic_analyses_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double lambda_ = 0.0;
  int factorizations_ = 0;
  int symbolic_analyses_ = 0;
};

// Projects x0 (size system.num_unknowns(), radians) onto r(x) = 0.
// Throws std::invalid_argument for a wrong size or a held index out of range.
// Never throws for non-convergence: check NewtonResult::converged and the history.
NewtonResult newton_project(const ClosureSystem& system, const Eigen::VectorXd& x0,
                            const NewtonOptions& options = {});

}  // namespace rigidfold
