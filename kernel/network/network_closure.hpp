#pragma once
// Loop-closure equations of a LinkageNetwork (linkage_network.hpp), their exact sparse
// Jacobian, the Newton corrector onto r(q) = 0 and the mobility (DOF) at a configuration.
//
// Unknowns q: one angle per network joint (radians), in the network's joint order.
// Rows: 3 per linkage, rows 3k..3k+2 for linkage k: r_k = log(prod_i Rx(t_i) Rz(alpha_i))
//   with t_i = sign_i q_{j_i} + offset_i (vertex_closure_residual; radians). Column j of
//   linkage k's block is sign_i times d r_k / d t_i (vertex_closure_jacobian).
// Only the linkages' own loops are closed: the seed's network model (joint-angle equalities
// plus one closure per linkage). Loops through several linkages (the central panel of a
// Kokotsakis mesh) add no rows; the seed's flat-panel condition (2-32) is a separate check
// on the twists.
// The corrector and the rank are kernel/solve's: MinimumNormSolver (CHOLMOD on
// J^T J + lambda I, minimum-norm Gauss-Newton steps, held joints' columns dropped) and
// jacobian_rank (dense SVD for small networks).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "kernel/network/linkage_network.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {

class NetworkClosure {
 public:
  // Validates the network (validate_network; throws std::invalid_argument).
  explicit NetworkClosure(LinkageNetwork network);

  const LinkageNetwork& network() const { return network_; }
  int num_unknowns() const { return network_.num_joints(); }
  int num_rows() const { return 3 * network_.num_linkages(); }

  // r(q), size num_rows() (radians).
  Eigen::VectorXd residual(const Eigen::VectorXd& q) const;
  // r(q) and the exact Jacobian (num_rows() x num_unknowns(), compressed). The sparsity
  // pattern is the same for every q (zeros stored), so a factorisation's analysis is reused.
  void evaluate(const Eigen::VectorXd& q, Eigen::VectorXd& residual, Eigen::SparseMatrix<double>& jacobian) const;
  // Largest closure error ||r_k|| (radians) over the linkages, and which linkage has it.
  double max_linkage_residual(const Eigen::VectorXd& q, int* worst_linkage = nullptr) const;

 private:
  LinkageNetwork network_;
};

struct NetworkNewtonOptions {
  double tolerance = 1e-12;      // stop when ||r||_inf <= tolerance (radians)
  int max_iterations = 40;
  double lambda_relative = 1e-14;
  double max_step = 0.5;         // ||dq||_inf cap per step (radians)
  std::vector<int> held;         // joints kept at their starting value (e.g. the input joint)
};

struct NetworkNewtonResult {
  Eigen::VectorXd q;                      // last iterate (radians)
  std::vector<double> residual_history;   // ||r||_inf at each iterate (radians)
  bool converged = false;
  int iterations = 0;
};

// Minimum-norm Gauss-Newton from q0 onto r = 0 (quadratic at regular points). Never throws
// for non-convergence; throws std::invalid_argument for a wrong size or a held index.
NetworkNewtonResult network_project(const NetworkClosure& system, const Eigen::VectorXd& q0,
                                    const NetworkNewtonOptions& options = {});

// First-order mobility at q: DOF = joints - rank(J(q)) with the stated tolerance
// (a singular value counts toward the rank when sigma > relative_tolerance * sigma_max;
// RankResult reports sigma_kept / sigma_dropped on both sides of the cut). With `held`
// joints the DOF is that of the others with those held (the input fixed: 0 means the input
// determines the configuration locally). Meaningful at a closed, regular configuration.
RankResult network_mobility(const NetworkClosure& system, const Eigen::VectorXd& q,
                            const std::vector<int>& held = {}, double relative_tolerance = 1e-9);

}  // namespace rigidfold
