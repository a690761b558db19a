#include "kernel/solve/subspace_rank.hpp"

#include <Eigen/Dense>
#include <Spectra/SymEigsSolver.h>
#include <algorithm>
#include <vector>
#include <cmath>

#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/portable_random.hpp"

namespace rigidfold {

namespace {

constexpr int kMaxIterations = 30;
// The Ritz value just above the cut must change by less than this (relative) between two
// iterations: it is the upper side of the reported gap.
constexpr double kSettled = 1e-2;
constexpr double kClearGap = 1e3;

// y = J^T J x for Spectra's Lanczos (largest eigenvalue of J^T J = sigma_max^2).
class NormalProduct {
 public:
  using Scalar = double;
  explicit NormalProduct(const Eigen::SparseMatrix<double>& J) : J_(J) {}
  Eigen::Index rows() const { return J_.cols(); }
  Eigen::Index cols() const { return J_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Eigen::VectorXd> x(x_in, J_.cols());
    Eigen::Map<Eigen::VectorXd> y(y_out, J_.cols());
    const Eigen::VectorXd jx = J_ * x;
    y = J_.transpose() * jx;
  }

 private:
  const Eigen::SparseMatrix<double>& J_;
};

double largest_singular_value(const Eigen::SparseMatrix<double>& J) {
  const int n = static_cast<int>(J.cols());
  if (n <= 8) {  // Spectra needs a Krylov space larger than one vector: tiny systems directly
    Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(J)};
    return svd.singularValues().size() ? svd.singularValues()[0] : 0.0;
  }
  // sigma_max only scales the relative cut: Spectra's 1e-3 (on the Ritz residual of
  // sigma_max^2) is plenty, and a tighter one costs many restarts on meshes whose top
  // singular values cluster (1e-8 took 17% of a 100 x 100 Miura trace; 1e-6 kept BM_Rank at
  // 200 x 200 at 1.7 s, 1e-3 takes 0.62 s).
  NormalProduct op(J);
  Spectra::SymEigsSolver<NormalProduct> eigs(op, 1, std::min(n, 16));
  eigs.init();
  eigs.compute(Spectra::SortRule::LargestAlge, 100, 1e-3);
  if (eigs.info() == Spectra::CompInfo::Successful) return std::sqrt(std::max(eigs.eigenvalues()[0], 0.0));
  // Not converged (not seen): the Frobenius norm is an upper bound.
  return J.norm();
}

Eigen::MatrixXd random_block(int rows, int cols, SplitMix64& rng) {
  Eigen::MatrixXd V(rows, cols);
  for (int c = 0; c < cols; ++c)
    for (int r = 0; r < rows; ++r) V(r, c) = 2.0 * rng.uniform() - 1.0;
  return V;
}

// Orthonormal basis of V's columns (thin Householder Q).
Eigen::MatrixXd orthonormal(const Eigen::MatrixXd& V) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(V);
  return qr.householderQ() * Eigen::MatrixXd::Identity(V.rows(), V.cols());
}

}  // namespace

RankResult subspace_rank(const Eigen::SparseMatrix<double>& J_in, const RankOptions& options) {
  RankResult res;
  res.rows = static_cast<int>(J_in.rows());
  res.cols = static_cast<int>(J_in.cols());
  res.method = "cholmod-subspace";
  const int n = res.cols;
  if (res.rows == 0 || n == 0) {  // no constraint: every direction is free
    res.dof = n;
    if (options.compute_null_space) res.null_space = Eigen::MatrixXd::Identity(n, n);
    return res;
  }
  Eigen::SparseMatrix<double> J = J_in;
  J.makeCompressed();
  MinimumNormSolver solver(J);
  if (!solver.factorize(J, options.lambda_relative)) {
    res.converged = false;
    res.dof = -1;
    return res;
  }
  res.sigma_max = largest_singular_value(J);
  res.threshold = options.relative_tolerance * res.sigma_max;

  SplitMix64 rng{0x5eed5ULL};
  const int block_cap = std::min(n, std::max(1, options.max_block));
  // rank J <= its rows with a nonzero entry, so DOF >= n - those rows: a block that small
  // would only double its way up (a straight-line fold's midpoint on huffmanWaterbomb.svg:
  // 339 flat vertices with an all-zero normal row each, DOF 337, seven doublings).
  std::vector<char> live_row(J.rows(), 0);
  for (int k = 0; k < J.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(J, k); it; ++it)
      if (it.value() != 0.0) live_row[it.row()] = 1;
  const int live_rows = static_cast<int>(std::count(live_row.begin(), live_row.end(), 1));
  const int hint = std::max({1, options.dof_hint, n - live_rows});
  int b = std::min(block_cap, hint + 4);
  Eigen::MatrixXd Q = orthonormal(random_block(n, b, rng));
  Eigen::VectorXd ritz;  // ascending
  int dof = 0;
  double previous_gap = -1.0;
  int previous_dof = -1;
  for (int it = 1; it <= kMaxIterations; ++it) {
    res.iterations = it;
    Q = orthonormal(solver.inverse_times(Q));
    // Rayleigh-Ritz on J: the singular values of J Q are upper bounds of J's smallest ones.
    // With fewer rows than the block (m < b) J Q has b - m more zero singular values: the full
    // V holds their vectors after the m computed ones.
    const Eigen::MatrixXd JQ = J * Q;
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(JQ, Eigen::ComputeFullV);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(b);  // descending
    s.head(svd.singularValues().size()) = svd.singularValues();
    ritz = s.reverse();
    Q = Q * svd.matrixV().rowwise().reverse();
    dof = 0;
    while (dof < b && ritz[dof] <= res.threshold) ++dof;
    if (dof == b) {  // the whole block is below the cut: the DOF may be larger
      if (b == n) break;             // every direction is free
      if (b >= block_cap) {          // more DOF than the largest block: not counted here
        res.converged = false;
        res.dof = -1;
        return res;
      }
      const int grown = std::min(block_cap, 2 * b);
      Eigen::MatrixXd V(n, grown);
      V << Q, random_block(n, grown - b, rng);
      Q = orthonormal(V);
      b = grown;
      previous_gap = -1.0;
      continue;
    }
    const double gap = ritz[dof];
    if (it >= 2 && dof == previous_dof && std::fabs(gap - previous_gap) <= kSettled * gap) break;
    // A clear gap decides the DOF before the Ritz value above it has settled: each iteration
    // amplifies a direction below the cut against one at the block's edge by about
    // sigma_edge^2 / lambda (>= 1e8 once the gap is 1e3 x the cut), so after 3 iterations no
    // such direction can be missing from the block. sigma_kept is then an upper bound only
    // (a Ritz value; on the soft modes of a 200 x 200 Miura the settling took 30 iterations).
    if (it >= 3 && dof == previous_dof && gap >= kClearGap * res.threshold) break;
    previous_gap = gap;
    previous_dof = dof;
    if (it == kMaxIterations) res.converged = false;
  }
  res.dof = dof;
  res.rank = n - dof;
  res.sigma_dropped = dof > 0 ? ritz[dof - 1] : 0.0;
  res.sigma_kept = dof < ritz.size() ? ritz[dof] : 0.0;
  res.smallest_singular_values.assign(ritz.data(), ritz.data() + ritz.size());
  if (options.compute_null_space && dof > 0) {
    // One minimum-norm correction per vector removes what is left of J w, then the block is
    // orthonormalised again (the correction is tiny, so it stays the same subspace).
    Eigen::MatrixXd N = Q.leftCols(dof);
    for (int k = 0; k < dof; ++k) {
      const Eigen::VectorXd jw = J * N.col(k);
      N.col(k) -= solver.solve(J, jw);
    }
    res.null_space = orthonormal(N);
  }
  return res;
}

}  // namespace rigidfold
