// Large-tessellation generators: the graded Miura-ori (generic 1-DOF flat-foldable
// quad mesh), the waterbomb tessellation (multi-DOF) and the perturbed Miura (not
// foldable). Checked by first principles (loop closure of the closed form), by the
// multiplier verdict, and by the DOF of the general Jacobian on small instances.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "data/generators/graded_miura.hpp"
#include "data/generators/miura.hpp"
#include "data/generators/waterbomb_tessellation.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(GradedMiura, TrapezoidPanelsWithVaryingFlatFoldableVertices) {
  generators::GradedMiuraParams gp;
  gp.rows = 6;
  gp.cols = 8;
  const CreasePattern p = generators::graded_miura(gp);
  const Topology t = build_topology(p);
  EXPECT_EQ(p.num_faces(), 48);
  EXPECT_EQ(static_cast<int>(t.interior_vertices.size()), 5 * 7);
  const std::vector<double> th = generators::graded_miura_line_angles(gp);
  EXPECT_GT(th[4] - th[0], 0.3);  // really non-uniform: not a Miura-ori
  // Every interior vertex passes Kawasaki, so the exact multiplier model applies.
  EXPECT_TRUE(multiplier_model_applicable(p, t).applicable);
}

TEST(GradedMiura, ClosedFormClosesEveryLoopAndVerdictIsOneDof) {
  generators::GradedMiuraParams gp;
  gp.rows = 5;
  gp.cols = 7;
  const CreasePattern p = generators::graded_miura(gp);
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t);
  for (double s : {0.3, 1.2, 2.5, -1.0}) {
    const Eigen::VectorXd rho = fold_angle_vector(generators::graded_miura_fold_angles(gp, s));
    const Eigen::VectorXd r = sys.residual(sys.unknowns_from_edges(rho));
    EXPECT_LE(r.lpNorm<Eigen::Infinity>(), 1e-13) << "rho_s " << s;
  }
  const FoldabilityVerdict v = verdict_with_assignment(p, t);
  EXPECT_EQ(v.verdict, Verdict::kRigidlyFoldable) << v.reason;
  EXPECT_EQ(v.dof, 1);
  EXPECT_LE(v.max_loop_defect, 1e-12);
  // General Jacobian at a folded state: one DOF.
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(sys.unknowns_from_edges(fold_angle_vector(generators::graded_miura_fold_angles(gp, 1.0))), r, J);
  EXPECT_EQ(jacobian_rank(J).dof, 1);
}

TEST(GradedMiura, RejectsFoldedOverPanels) {
  generators::GradedMiuraParams gp;
  gp.theta_min = 0.2;
  gp.theta_max = 1.4;
  gp.b = 0.5;
  EXPECT_THROW(generators::graded_miura(gp), InputError);
}

TEST(WaterbombTessellation, TriangulatedDegreeSixSheet) {
  generators::WaterbombTessellationParams wp;
  wp.rows = 4;
  wp.cols = 3;
  const CreasePattern p = generators::waterbomb_tessellation(wp);
  const Topology t = build_topology(p);
  for (const auto& f : p.faces) EXPECT_EQ(f.size(), 3u);
  ASSERT_FALSE(t.interior_vertices.empty());
  for (int v : t.interior_vertices) EXPECT_EQ(t.stars[v].fans.at(0).edges.size(), 6u);
  // Degree-6 vertices: the multiplier model does not apply, the general solver must.
  EXPECT_FALSE(multiplier_model_applicable(p, t).applicable);
}

TEST(WaterbombTessellation, GenericFoldedStateHasBoundaryMinusThreeDof) {
  generators::WaterbombTessellationParams wp;
  wp.rows = 3;
  wp.cols = 3;
  const CreasePattern p = generators::waterbomb_tessellation(wp);
  const ClosureSystem sys(p, build_topology(p));
  // Project a random small fold onto the manifold, then count the DOF there.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  Eigen::VectorXd x0(sys.num_unknowns());
  for (int k = 0; k < x0.size(); ++k) x0[k] = u(rng);
  const NewtonResult nr = newton_project(sys, x0);
  ASSERT_TRUE(nr.converged);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(nr.x, r, J);
  EXPECT_EQ(jacobian_rank(J).dof, 2 * (wp.rows + wp.cols) - 3);
  EXPECT_GT(nr.x.cwiseAbs().maxCoeff(), 0.1);  // a real fold, not the flat state
}

TEST(PerturbedMiura, NotFlatFoldableAndTheMiuraFoldDoesNotClose) {
  generators::MiuraParams mp;
  mp.rows = mp.cols = 6;
  mp.perturbation = 0.05;
  const CreasePattern p = generators::miura_ori(mp);
  const Topology t = build_topology(p);
  EXPECT_FALSE(multiplier_model_applicable(p, t).applicable);  // Kawasaki fails
  const ClosureSystem sys(p, t);
  generators::MiuraParams exact = mp;
  exact.perturbation = 0;
  const Eigen::VectorXd guess =
      sys.unknowns_from_edges(fold_angle_vector(generators::miura_fold_angles(generators::miura_ori(exact), exact, 0.5)));
  const Eigen::VectorXd r = sys.residual(guess);
  EXPECT_GT(r.lpNorm<Eigen::Infinity>(), 1e-3);
}

}}  // namespace
}  // namespace rigidfold
