// Rank / DOF of the closure Jacobian: Miura 1 DOF at folded points (dense SVD and SPQR),
// single generic vertices n - 3 DOF, a perturbed (non flat-foldable) 3x3 quad mesh rigid,
// and the flat state of a Miura singular (first-order count > 1, inconclusive there).
#include "kernel/solve/rank.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <iostream>
#include <random>

#include <Eigen/Dense>

#include "data/generators/miura.hpp"
#include "data/generators/waterbomb_tessellation.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::miura_edge_angles;
using testing::random_vector;

Eigen::MatrixXd random_matrix(int rows, int cols, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd A(rows, cols);
  for (int c = 0; c < cols; ++c)
    for (int r = 0; r < rows; ++r) A(r, c) = g(rng);
  return A;
}

Eigen::SparseMatrix<double> jacobian_at(const ClosureSystem& sys, const Eigen::VectorXd& x) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(x, r, J);
  return J;
}

void print_rank(const char* name, const RankResult& r) {
  std::cout << "[ rank     ] " << name << ": " << r.method << " " << r.rows << "x" << r.cols << " rank " << r.rank
            << " dof " << r.dof << "  sigma_max " << r.sigma_max << " kept " << r.sigma_kept << " dropped "
            << r.sigma_dropped << "\n";
}

TEST(SolverRank, MiuraAtFoldedPointHasOneDof) {
  for (auto [rows, cols] : {std::pair{2, 2}, {3, 3}, {4, 5}, {8, 8}}) {
    generators::MiuraParams m;
    m.rows = rows;
    m.cols = cols;
    m.alpha = 1.0;
    const CreasePattern p = generators::miura_ori(m);
    const ClosureSystem sys(p, build_topology(p));
    for (double s : {0.2, 1.3, 2.8}) {
      const Eigen::VectorXd x = sys.unknowns_from_edges(miura_edge_angles(p, m, s));
      const Eigen::SparseMatrix<double> J = jacobian_at(sys, x);
      const RankResult dense = jacobian_rank(J);
      print_rank("miura folded", dense);
      EXPECT_EQ(dense.dof, 1) << rows << "x" << cols << " s " << s;
      EXPECT_GT(dense.sigma_kept, 1e-4);    // a clear gap on both sides of the 1e-9 cut
      EXPECT_LT(dense.sigma_dropped, 1e-13);
      ASSERT_EQ(dense.null_space.cols(), 1);
      EXPECT_LE((J * dense.null_space).norm(), 1e-13);
      // The tangent is the derivative of the closed form.
      const double h = 1e-6;
      Eigen::VectorXd t = (sys.unknowns_from_edges(miura_edge_angles(p, m, s + h)) -
                           sys.unknowns_from_edges(miura_edge_angles(p, m, s - h))) / (2 * h);
      t.normalize();
      EXPECT_NEAR(std::fabs(t.dot(dense.null_space.col(0))), 1.0, 1e-8);

      RankOptions sparse_opt;
      sparse_opt.method = RankMethod::kSpqr;
      const RankResult sparse = jacobian_rank(J, sparse_opt);
      EXPECT_EQ(sparse.method, "spqr");
      EXPECT_EQ(sparse.dof, 1) << rows << "x" << cols << " s " << s;
      ASSERT_EQ(sparse.null_space.cols(), 1);
      EXPECT_NEAR(std::fabs(sparse.null_space.col(0).dot(dense.null_space.col(0))), 1.0, 1e-10);

      RankOptions subspace_opt;
      subspace_opt.method = RankMethod::kSubspace;
      const RankResult sub = jacobian_rank(J, subspace_opt);
      EXPECT_EQ(sub.method, "cholmod-subspace");
      EXPECT_TRUE(sub.converged);
      EXPECT_EQ(sub.dof, 1) << rows << "x" << cols << " s " << s;
      EXPECT_NEAR(sub.sigma_max, dense.sigma_max, 1e-6 * dense.sigma_max);  // Lanczos: well separated top here
      // The gap's upper side is a Ritz value: an upper bound of the dense sigma, settled to 1e-2.
      EXPECT_GE(sub.sigma_kept, dense.sigma_kept * (1 - 1e-12));
      EXPECT_LE(sub.sigma_kept, dense.sigma_kept * 1.02);
      EXPECT_LT(sub.sigma_dropped, 1e-13);
      ASSERT_EQ(sub.null_space.cols(), 1);
      EXPECT_LE((J * sub.null_space).norm(), 1e-13);
      EXPECT_NEAR(std::fabs(sub.null_space.col(0).dot(dense.null_space.col(0))), 1.0, 1e-12);
    }
  }
}

TEST(SolverRank, LargeMiuraUsesTheFactorSubspaceAndAgreesWithSpqr) {
  generators::MiuraParams m;
  m.rows = m.cols = 40;  // 3120 unknowns: above the dense limit
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  const Eigen::SparseMatrix<double> J = jacobian_at(sys, sys.unknowns_from_edges(miura_edge_angles(p, m, 1.0)));
  const auto t0 = std::chrono::steady_clock::now();
  const RankResult r = jacobian_rank(J);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  print_rank("miura 40x40", r);
  std::cout << "[ rank     ] miura 40x40 subspace time " << ms << " ms, " << r.iterations << " block iterations\n";
  EXPECT_EQ(r.method, "cholmod-subspace");
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.dof, 1);
  EXPECT_GT(r.sigma_kept, 1e3 * r.threshold);
  ASSERT_EQ(r.null_space.cols(), 1);
  EXPECT_LE((J * r.null_space).norm(), 1e-12);
  RankOptions qr;
  qr.method = RankMethod::kSpqr;
  const RankResult q = jacobian_rank(J, qr);
  EXPECT_EQ(q.method, "spqr");
  EXPECT_EQ(q.dof, 1);
  ASSERT_EQ(q.null_space.cols(), 1);
  EXPECT_NEAR(std::fabs(q.null_space.col(0).dot(r.null_space.col(0))), 1.0, 1e-10);
}

// A matrix with known singular values (J = U diag(s) V^T, U and V random orthogonal): three
// below the 1e-9 cut, one at 1e-7 just above it - below what J^T J can resolve (its
// eigenvalue 1e-14 sits at the round-off of J^T J), so this checks that the Ritz step works
// on J itself. The subspace method must count 3 and place the gap's upper side at 1e-7.
TEST(SolverRank, SubspaceResolvesASingularValueBelowTheNormalEquationsFloor) {
  const int m = 320, n = 260;
  std::mt19937_64 rng(11);
  const Eigen::MatrixXd U = Eigen::HouseholderQR<Eigen::MatrixXd>(random_matrix(m, m, rng)).householderQ();
  const Eigen::MatrixXd V = Eigen::HouseholderQR<Eigen::MatrixXd>(random_matrix(n, n, rng)).householderQ();
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i) s[i] = 1.0 + 9.0 * i / (n - 1);  // 1 .. 10
  s[n - 1] = 3e-13;
  s[n - 2] = 1e-15;
  s[n - 3] = 0.0;
  s[n - 4] = 1e-7;
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(m, n);
  S.diagonal() = s;
  const Eigen::MatrixXd Jd = U * S * V.transpose();
  const Eigen::SparseMatrix<double> J = Jd.sparseView();
  RankOptions o;
  o.method = RankMethod::kSubspace;
  const RankResult r = jacobian_rank(J, o);
  print_rank("known spectrum", r);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.dof, 3);
  // A Lanczos Ritz value: never above sigma_max; this spectrum's top is a tight cluster
  // (spacing 0.035), where it may stop inside it (subspace_rank.hpp).
  EXPECT_LE(r.sigma_max, 10.0 * (1 + 1e-12));
  EXPECT_GE(r.sigma_max, 9.8);
  EXPECT_NEAR(r.sigma_kept, 1e-7, 1e-9);
  EXPECT_LT(r.sigma_dropped, 1e-11);
  ASSERT_EQ(r.null_space.cols(), 3);
  // The null space found is the span of V's last three columns.
  const Eigen::MatrixXd overlap = V.rightCols(3).transpose() * r.null_space;
  EXPECT_NEAR(overlap.jacobiSvd().singularValues().minCoeff(), 1.0, 1e-9);
  const RankResult dense = jacobian_rank(J);  // 260 unknowns: above the dense limit, so force it
  RankOptions d;
  d.method = RankMethod::kDenseSvd;
  EXPECT_EQ(jacobian_rank(J, d).dof, 3);
  EXPECT_EQ(dense.method, "cholmod-subspace");
}

// A waterbomb tessellation at a generic folded state has 2 (rows + cols) - 3 DOF: the block
// has to grow past its first size (dof_hint + 4) to count them.
TEST(SolverRank, SubspaceCountsManyDofAsTheDenseSvd) {
  generators::WaterbombTessellationParams wp;
  wp.rows = 4;
  wp.cols = 5;
  const CreasePattern p = generators::waterbomb_tessellation(wp);
  const ClosureSystem sys(p, build_topology(p));
  std::mt19937_64 rng(5);
  NewtonOptions no;
  no.max_iterations = 60;
  const NewtonResult nr = newton_project(sys, random_vector(sys.num_unknowns(), rng, 0.4), no);
  ASSERT_TRUE(nr.converged);
  const Eigen::SparseMatrix<double> J = jacobian_at(sys, nr.x);
  RankOptions d, o;
  d.method = RankMethod::kDenseSvd;
  o.method = RankMethod::kSubspace;
  const RankResult dense = jacobian_rank(J, d), sub = jacobian_rank(J, o);
  print_rank("waterbomb dense", dense);
  print_rank("waterbomb subspace", sub);
  EXPECT_EQ(dense.dof, 2 * (wp.rows + wp.cols) - 3);
  EXPECT_EQ(sub.dof, dense.dof);
  EXPECT_TRUE(sub.converged);
  EXPECT_GE(sub.sigma_kept, dense.sigma_kept * (1 - 1e-12));
  EXPECT_LE(sub.sigma_kept, dense.sigma_kept * 1.02);
  ASSERT_EQ(sub.null_space.cols(), dense.dof);
  // Same subspace: the principal angles between the two null spaces vanish.
  const Eigen::MatrixXd overlap = dense.null_space.transpose() * sub.null_space;
  EXPECT_NEAR(overlap.jacobiSvd().singularValues().minCoeff(), 1.0, 1e-9);
  EXPECT_LE((J * sub.null_space).norm(), 1e-12);
}

// A generic single vertex of degree n (random sectors, not flat-foldable), brought to a
// closed, non-flat point by Newton projection from a random start: n - 3 DOF.
TEST(SolverRank, GenericSingleVertexHasDegreeMinusThreeDof) {
  std::mt19937_64 rng(2024);
  for (int n : {5, 6, 7}) {
    int tested = 0;
    for (int trial = 0; trial < 20 && tested < 3; ++trial) {
      const CreasePattern p = testing::single_vertex_pattern(testing::random_directions(n, rng));
      const ClosureSystem sys(p, build_topology(p));
      ASSERT_EQ(sys.num_unknowns(), n);
      NewtonOptions opt;
      opt.max_iterations = 60;
      const NewtonResult res = newton_project(sys, random_vector(n, rng, 1.0), opt);
      if (!res.converged || res.x.lpNorm<Eigen::Infinity>() < 0.2) continue;  // want a folded point
      const RankResult r = jacobian_rank(jacobian_at(sys, res.x));
      print_rank("single vertex", r);
      EXPECT_EQ(r.dof, n - 3) << "degree " << n;
      EXPECT_GT(r.sigma_kept, 1e-6);
      RankOptions o;
      o.method = RankMethod::kSubspace;
      const RankResult sub = jacobian_rank(jacobian_at(sys, res.x), o);
      EXPECT_EQ(sub.dof, n - 3) << "degree " << n << " (subspace)";
      ++tested;
    }
    EXPECT_GE(tested, 2) << "degree " << n;
  }
}

// A 3x3 Miura with perturbed interior vertices: 4 generic (non flat-foldable) degree-4
// vertices, 12 unknowns and 12 equations. What is asserted:
//   (a) J has full rank 12 (DOF 0) at random nonzero fold angles, so a folded solution, if
//       any, would be an isolated point, not a motion;
//   (b) with one crease held at a fold of 0.1 rad and the others started near a small fold,
//       Newton projection does not reach the manifold (its residual stays above 1e-6):
//       the 11 remaining unknowns cannot satisfy 12 equations;
//   (c) the same procedure on the unperturbed Miura converges (the control).
TEST(SolverRank, PerturbedMiuraIsRigid) {
  std::mt19937_64 rng(77);
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  m.perturbation = 0.15;
  m.seed = 5;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  ASSERT_EQ(sys.num_unknowns(), 12);
  ASSERT_EQ(sys.num_rows(), 12);
  for (int trial = 0; trial < 5; ++trial) {
    const RankResult r = jacobian_rank(jacobian_at(sys, random_vector(12, rng, 1.0)));
    EXPECT_EQ(r.dof, 0);
    EXPECT_GT(r.sigma_kept, 1e-4);
  }
  m.perturbation = 0.0;
  const CreasePattern q = generators::miura_ori(m);
  const ClosureSystem control(q, build_topology(q));
  const Eigen::VectorXd small = control.unknowns_from_edges(miura_edge_angles(q, m, 0.1));
  for (int trial = 0; trial < 3; ++trial) {
    NewtonOptions opt;
    opt.max_iterations = 50;
    opt.held_unknowns = {0};
    Eigen::VectorXd x0 = small + random_vector(12, rng, 0.02);
    x0[0] = small[0];
    const NewtonResult bad = newton_project(sys, x0, opt);
    std::cout << "[ rank     ] perturbed miura, crease held at " << x0[0] << ": residual after " << bad.iterations
              << " steps " << bad.residual_history.back() << "\n";
    EXPECT_FALSE(bad.converged);
    EXPECT_GT(bad.residual_history.back(), 1e-6);
    const NewtonResult good = newton_project(control, x0, opt);
    EXPECT_TRUE(good.converged);
  }
}

// At the flat state every crease axis lies in the sheet, so the z row of every vertex
// vanishes: rank <= 2 * (interior vertices) and the first-order DOF count exceeds 1 although
// the pattern has one folding mode. The flat state is a bifurcation point.
TEST(SolverRank, FlatMiuraIsSingular) {
  for (int size : {3, 5}) {
    generators::MiuraParams m;
    m.rows = m.cols = size;
    const CreasePattern p = generators::miura_ori(m);
    const ClosureSystem sys(p, build_topology(p));
    const Eigen::SparseMatrix<double> J = jacobian_at(sys, Eigen::VectorXd::Zero(sys.num_unknowns()));
    const RankResult r = jacobian_rank(J);
    print_rank("miura flat", r);
    RankOptions o;
    o.method = RankMethod::kSubspace;
    EXPECT_EQ(jacobian_rank(J, o).dof, r.dof) << "subspace count at the flat state";
    EXPECT_GT(r.dof, 1);
    EXPECT_LE(r.rank, 2 * sys.num_vertices());
    EXPECT_GE(r.dof, sys.num_unknowns() - 2 * sys.num_vertices());
  }
}

}}  // namespace
}  // namespace rigidfold

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// A sheet with no interior vertex has no closure row: every crease is free. (Eigen's SVD
// crashed on a 0 x n matrix before this case was handled.)
TEST(SolverRank, NoRowsMeansEveryColumnIsFree) {
  const Eigen::SparseMatrix<double> empty(0, 4);
  const RankResult r = jacobian_rank(empty);
  EXPECT_EQ(r.rank, 0);
  EXPECT_EQ(r.dof, 4);
  ASSERT_EQ(r.null_space.cols(), 4);
  EXPECT_LE((r.null_space.transpose() * r.null_space - Eigen::MatrixXd::Identity(4, 4)).norm(), 1e-15);
  const RankResult none = jacobian_rank(Eigen::SparseMatrix<double>(3, 0));
  EXPECT_EQ(none.dof, 0);
}

}}  // namespace
}  // namespace rigidfold
