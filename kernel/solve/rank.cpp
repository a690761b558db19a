#include "kernel/solve/rank.hpp"

#include "kernel/solve/subspace_rank.hpp"

#include <vector>

#include <Eigen/Dense>
#include <Eigen/SPQRSupport>
#include <algorithm>
#include <cmath>

namespace rigidfold {

namespace {

RankResult dense_rank(const Eigen::SparseMatrix<double>& J, const RankOptions& options) {
  RankResult res;
  res.rows = static_cast<int>(J.rows());
  res.cols = static_cast<int>(J.cols());
  res.method = "dense-svd";
  const int n = res.cols;
  if (res.rows == 0 || n == 0) {  // no constraint (or no unknown): Eigen's SVD does not take empty matrices
    res.dof = n;
    if (options.compute_null_space) res.null_space = Eigen::MatrixXd::Identity(n, n);
    return res;
  }
  const Eigen::MatrixXd Jd(J);
  // Full V is needed for the null space (the trailing right singular vectors).
  const unsigned flags = options.compute_null_space ? static_cast<unsigned>(Eigen::ComputeFullV) : 0u;
  Eigen::BDCSVD<Eigen::MatrixXd> svd(Jd, flags);
  const Eigen::VectorXd& s = svd.singularValues();
  res.singular_values.assign(s.data(), s.data() + s.size());
  res.sigma_max = s.size() > 0 ? s[0] : 0.0;
  res.threshold = options.relative_tolerance * res.sigma_max;
  int rank = 0;
  while (rank < s.size() && s[rank] > res.threshold) ++rank;
  res.rank = rank;
  res.dof = n - rank;
  res.sigma_kept = rank > 0 ? s[rank - 1] : 0.0;
  res.sigma_dropped = rank < s.size() ? s[rank] : 0.0;
  if (options.compute_null_space) res.null_space = svd.matrixV().rightCols(res.dof);
  return res;
}

RankResult sparse_rank(const Eigen::SparseMatrix<double>& J, const RankOptions& options) {
  using LongSparse = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
  RankResult res;
  res.rows = static_cast<int>(J.rows());
  res.cols = static_cast<int>(J.cols());
  res.method = "spqr";
  const LongSparse Jl(J);
  double max_col = 0.0;
  for (Eigen::Index c = 0; c < Jl.outerSize(); ++c) max_col = std::max(max_col, Jl.col(c).norm());
  res.threshold = options.relative_tolerance * std::max(max_col, 1e-300);
  // J P = Q [R11 R12; 0 ~0]: SPQR moves the columns it drops (norm below the threshold when
  // met) behind the rank live ones; R11 (rank x rank) is upper triangular.
  Eigen::SPQR<LongSparse> qr;
  qr.setPivotThreshold(res.threshold);
  qr.compute(Jl);
  const int rank = static_cast<int>(qr.rank());
  res.rank = rank;
  res.dof = res.cols - rank;
  const LongSparse R = qr.matrixR();
  double kept = 0.0, biggest = 0.0;
  for (int i = 0; i < rank; ++i) {
    const double d = std::fabs(R.coeff(i, i));
    biggest = std::max(biggest, d);
    kept = i == 0 ? d : std::min(kept, d);
  }
  res.sigma_max = biggest;
  res.sigma_kept = kept;
  if (options.compute_null_space && res.dof > 0 && res.dof <= options.max_null_space) {
    // Null vectors in the permuted order: z = [-R11^{-1} R12 e_k; e_k], then x = P z.
    const Eigen::MatrixXd R12 = Eigen::MatrixXd(R.topRightCorner(rank, res.dof));
    Eigen::MatrixXd top = R.topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solve(R12);
    // colsPermutation() returns a temporary view: copy its indices before using them
    // (binding a reference to them dangles; ASan reports stack-use-after-scope).
    const auto cols_permutation = qr.colsPermutation();
    const std::vector<Eigen::Index> perm(cols_permutation.indices().data(), cols_permutation.indices().data() + res.cols);
    Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(res.cols, res.dof);
    for (int i = 0; i < rank; ++i) Z.row(perm[i]) = -top.row(i);
    for (int k = 0; k < res.dof; ++k) Z(perm[rank + k], k) = 1.0;
    Eigen::HouseholderQR<Eigen::MatrixXd> orth(Z);
    res.null_space = orth.householderQ() * Eigen::MatrixXd::Identity(res.cols, res.dof);
    // What the cut dropped, measured: the largest |J v| over the orthonormal null basis.
    for (int k = 0; k < res.dof; ++k) res.sigma_dropped = std::max(res.sigma_dropped, (J * res.null_space.col(k)).norm());
  }
  return res;
}

}  // namespace

RankResult jacobian_rank(const Eigen::SparseMatrix<double>& J, const RankOptions& options) {
  switch (options.method) {
    case RankMethod::kDenseSvd: return dense_rank(J, options);
    case RankMethod::kSpqr: return sparse_rank(J, options);
    case RankMethod::kSubspace: break;
    case RankMethod::kAuto:
      if (J.cols() <= options.dense_limit || J.rows() == 0) return dense_rank(J, options);
      break;
  }
  RankResult res = subspace_rank(J, options);
  // G not factorisable, or more DOF than the largest block holds: the rank-revealing QR.
  if (res.dof < 0) return sparse_rank(J, options);
  return res;
}

}  // namespace rigidfold
