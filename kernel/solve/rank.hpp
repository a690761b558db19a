#pragma once
// Rank, degrees of freedom and null space of a constraint Jacobian J (m x n) at a point
// (docs/DESIGN.md, "DOF and tangent").
//
//   DOF = n - rank(J)   (first-order mobility: the dimension of the tangent space when the
//                        point is regular; at a singular point, e.g. the flat state of a
//                        flat-foldable pattern, it over-counts and says nothing final).
//
// Tolerance: a singular value sigma_i counts toward the rank when
//     sigma_i > relative_tolerance * sigma_max.
// Methods (RankOptions::method; kAuto picks dense SVD up to dense_limit unknowns, the factor
// subspace above, so no O(n^3) dense step runs on a large system):
//   - Dense SVD (Eigen::BDCSVD) when n <= dense_limit: exact singular values; the two
//     singular values on either side of the cut are reported so the gap can be judged; the
//     null space is the trailing right singular vectors.
//   - Factor subspace (subspace_rank.hpp): block inverse iteration on the CHOLMOD factor of
//     J^T J + lambda I with Rayleigh-Ritz on J; about one factorisation; the DOF and the
//     Ritz values on both sides of the cut, an estimate resting on the block's convergence.
//   - SPQR (Eigen::SPQR, SuiteSparseQR), only when asked for (kSpqr): J P = Q [R11 R12; 0 ~0], a column
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

enum class RankMethod { kAuto, kDenseSvd, kSubspace, kSpqr };

struct RankOptions {
  double relative_tolerance = 1e-9;  // relative to sigma_max (dense, subspace) or max column norm (SPQR)
  RankMethod method = RankMethod::kAuto;
  int dense_limit = 200;             // kAuto: n <= dense_limit dense SVD, else the factor subspace
  bool compute_null_space = true;
  int max_null_space = 64;           // SPQR path: null vectors formed at most (they are dense)
  int dof_hint = 1;                  // subspace: expected DOF (the first block holds dof_hint + 4 vectors)
  int max_block = 512;               // subspace: the block doubles up to this; more DOF is not counted
  double lambda_relative = 1e-14;    // subspace: the regularisation of J^T J, as the corrector's
};

struct RankResult {
  int rows = 0, cols = 0;
  int rank = 0;
  int dof = 0;                       // cols - rank
  double threshold = 0.0;            // absolute cut applied
  double sigma_max = 0.0;            // largest singular value (dense) / largest |R_ii| (SPQR)
  double sigma_kept = 0.0;           // smallest value counted in the rank (0 if rank == 0)
  double sigma_dropped = 0.0;        // largest value below the cut (0 if none)
  std::vector<double> singular_values;  // dense path: all min(m, n), descending; empty otherwise
  std::vector<double> smallest_singular_values;  // subspace path: the final Ritz values, ascending
  bool converged = true;             // subspace path: the block settled (false: an estimate only)
  int iterations = 0;                // subspace path: block iterations
  Eigen::MatrixXd null_space;        // cols x dof, orthonormal columns (if computed)
  std::string method;                // "dense-svd", "cholmod-subspace" or "spqr"
};

// Inputs: J (any sparse matrix, e.g. ClosureSystem::evaluate's Jacobian), options.
// Output: as RankResult. Never throws for a rank-deficient or empty matrix.
RankResult jacobian_rank(const Eigen::SparseMatrix<double>& J, const RankOptions& options = {});

}  // namespace rigidfold
