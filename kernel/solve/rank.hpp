#pragma once
// Rank, degrees of freedom and null space of a constraint Jacobian J (m x n) at a point
// (DESIGN.md, "DOF and tangent").
//
//   DOF = n - rank(J)   (first-order mobility: the dimension of the tangent space when the
//                        point is regular; at a singular point, e.g. the flat state of a
//                        flat-foldable pattern, it over-counts and says nothing final).
//
// Tolerance: a singular value sigma_i counts toward the rank when
//     sigma_i > relative_tolerance * sigma_max.
// Methods:
//   - Dense SVD (Eigen::BDCSVD) when n <= dense_limit: exact singular values; the two
//     singular values on either side of the cut are reported so the gap can be judged; the
//     null space is the trailing right singular vectors.
//   - SPQR (Eigen::SPQR, SuiteSparseQR) on J otherwise: J P = Q [R11 R12; 0 ~0], a column
//     is dropped when its remaining norm is below relative_tolerance * (max column norm of
//     J); rank = number of live columns; null vectors P [-R11^{-1} R12; I], orthonormalised.
//     SPQR's rank detection (Heath's method) is a heuristic, reliable for a clear gap;
//     sigma_max/sigma_kept are then the largest/smallest |R_ii| kept, and sigma_dropped is
//     the largest |J v| over the computed null basis (0 if not computed).
//     (Factorising J^T instead was tried and rejected: on a 40x40 Miura SPQR kept a pivot
//     just above the threshold whatever the threshold, 1e-12..1e-9, and missed the DOF.)
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

namespace rigidfold {

struct RankOptions {
  double relative_tolerance = 1e-9;  // relative to sigma_max (dense) or max column norm (SPQR)
  int dense_limit = 2000;            // n <= dense_limit: dense SVD, else SPQR
  bool compute_null_space = true;
  int max_null_space = 64;           // SPQR path: null vectors formed at most (they are dense)
};

struct RankResult {
  int rows = 0, cols = 0;
  int rank = 0;
  int dof = 0;                       // cols - rank
  double threshold = 0.0;            // absolute cut applied
  double sigma_max = 0.0;            // largest singular value (dense) / largest |R_ii| (SPQR)
  double sigma_kept = 0.0;           // smallest value counted in the rank (0 if rank == 0)
  double sigma_dropped = 0.0;        // largest value below the cut (0 if none)
  std::vector<double> singular_values;  // dense path: all min(m, n), descending; empty for SPQR
  Eigen::MatrixXd null_space;        // cols x dof, orthonormal columns (if computed)
  std::string method;                // "dense-svd" or "spqr"
};

// Inputs: J (any sparse matrix, e.g. ClosureSystem::evaluate's Jacobian), options.
// Output: as RankResult. Never throws for a rank-deficient or empty matrix.
RankResult jacobian_rank(const Eigen::SparseMatrix<double>& J, const RankOptions& options = {});

}  // namespace rigidfold
