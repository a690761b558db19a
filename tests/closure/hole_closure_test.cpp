// SE(3) hole closures (kernel/closure/hole_closure.hpp) on prism tubes (data/generators/tube.hpp):
// loop finding, exact Jacobian vs finite differences, mobility of 4-bar and 3-bar tubes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "data/generators/tube.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/closure/hole_closure.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

ClosureOptions with_holes() {
  ClosureOptions o;
  o.close_holes = true;
  return o;
}

generators::TubeParams rectangle_tube() {
  generators::TubeParams t;
  t.section = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  t.height = 1.5;
  return t;
}

Eigen::VectorXd reference_unknowns(const CreasePattern& p, const Topology& t, const ClosureSystem& sys) {
  return sys.unknowns_from_edges(reference_fold_angles(p, t));
}

TEST(ClosureHoles, TubeTopologyAndLoop) {
  const CreasePattern p = generators::prism_tube(rectangle_tube());
  const Topology t = build_topology(p);
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.components[0].holes, 1);
  EXPECT_EQ(t.components[0].genus, 0);
  EXPECT_TRUE(t.interior_vertices.empty());
  const auto loops = find_hole_loops(p, t);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].steps.size(), 4u);  // once around, across each vertical crease
  EXPECT_EQ(loops[0].faces.size(), 4u);
}

TEST(ClosureHoles, RejectedWithoutOption) {
  const CreasePattern p = generators::prism_tube(rectangle_tube());
  const Topology t = build_topology(p);
  EXPECT_THROW(ClosureSystem(p, t), std::runtime_error);
}

TEST(ClosureHoles, JacobianMatchesFiniteDifferences) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  for (int layers : {1, 2, 3}) {
    for (double top : {1.0, 0.6}) {
      generators::TubeParams tp;
      tp.section = generators::regular_polygon(5, 1.0, 0.2);
      tp.section[1] *= 1.3;  // irregular
      tp.layers = layers;
      tp.top_scale = top;
      const CreasePattern p = generators::prism_tube(tp);
      const Topology t = build_topology(p);
      const ClosureSystem sys(p, t, with_holes());
      ASSERT_EQ(sys.num_holes(), 1);
      Eigen::VectorXd x = reference_unknowns(p, t, sys);
      EXPECT_LE(sys.residual(x).lpNorm<Eigen::Infinity>(), 1e-13);
      for (int k = 0; k < x.size(); ++k) x[k] += u(rng);
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> J;
      sys.evaluate(x, r, J);
      EXPECT_LE((r - sys.residual(x)).lpNorm<Eigen::Infinity>(), 1e-15);
      const Eigen::MatrixXd Jd(J);
      const double h = 1e-6;
      Eigen::MatrixXd Jfd(sys.num_rows(), sys.num_unknowns());
      for (int k = 0; k < x.size(); ++k) {
        Eigen::VectorXd xp = x, xm = x;
        xp[k] += h;
        xm[k] -= h;
        Jfd.col(k) = (sys.residual(xp) - sys.residual(xm)) / (2 * h);
      }
      const double rel = (Jd - Jfd).lpNorm<Eigen::Infinity>() / Jd.lpNorm<Eigen::Infinity>();
      EXPECT_LE(rel, 1e-7) << "layers " << layers << " top " << top;
      const Eigen::MatrixXd hole_block = Jd.bottomRows(6);
      EXPECT_GT(hole_block.lpNorm<Eigen::Infinity>(), 0.1);
    }
  }
}

struct Mobility {
  int dof_reference = -1, dof_folded = -1;
  double residual = -1, mismatch = -1;
  bool converged = false;
};

Mobility mobility(const generators::TubeParams& tp, double drive) {
  const CreasePattern p = generators::prism_tube(tp);
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t, with_holes());
  Mobility m;
  const Eigen::VectorXd x0 = reference_unknowns(p, t, sys);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(x0, r, J);
  m.dof_reference = jacobian_rank(J).dof;
  Eigen::VectorXd start = x0;
  start[0] += drive;
  NewtonOptions no;
  no.held_unknowns = {0};
  const NewtonResult nr = newton_project(sys, start, no);
  m.converged = nr.converged;
  m.residual = nr.residual_history.back();
  sys.evaluate(nr.x, r, J);
  m.dof_folded = jacobian_rank(J).dof;
  const FoldedGeometry g = place_faces(p, t, sys.edges_from_unknowns(nr.x), reference_fold_angles(p, t));
  m.mismatch = g.relative_mismatch();
  return m;
}

TEST(ClosureHoles, FourPanelTubeHasOneDof) {
  const Mobility m = mobility(rectangle_tube(), 0.3);
  EXPECT_EQ(m.dof_reference, 1);
  EXPECT_TRUE(m.converged);
  EXPECT_LE(m.residual, 1e-12);
  EXPECT_LE(m.mismatch, 1e-12);  // the folded panels really close up
  EXPECT_EQ(m.dof_folded, 1);
  std::printf("[ClosureHoles] 4-panel prism: DOF %d (reference) %d (folded), residual %.3g, mismatch %.3g\n",
              m.dof_reference, m.dof_folded, m.residual, m.mismatch);
}

TEST(ClosureHoles, FourPanelFrustumIsSpherical4Bar) {
  generators::TubeParams tp = rectangle_tube();
  tp.top_scale = 0.5;
  const Mobility m = mobility(tp, 0.2);
  EXPECT_EQ(m.dof_reference, 1);
  EXPECT_TRUE(m.converged);
  EXPECT_LE(m.mismatch, 1e-12);
  EXPECT_EQ(m.dof_folded, 1);
}

TEST(ClosureHoles, FivePanelTubeHasTwoDof) {
  generators::TubeParams tp;
  tp.section = generators::regular_polygon(5);
  const Mobility m = mobility(tp, 0.2);
  EXPECT_EQ(m.dof_reference, 2);
  EXPECT_TRUE(m.converged);
  EXPECT_LE(m.mismatch, 1e-12);
  EXPECT_EQ(m.dof_folded, 2);
}

TEST(ClosureHoles, TriangularTubeIsRigid) {
  generators::TubeParams tp;
  tp.section = {{0, 0}, {2, 0}, {0.5, 1.2}};
  const CreasePattern p = generators::prism_tube(tp);
  const Topology t = build_topology(p);
  const ClosureSystem sys(p, t, with_holes());
  ASSERT_EQ(sys.num_unknowns(), 3);
  ASSERT_EQ(sys.num_rows(), 6);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(reference_unknowns(p, t, sys), r, J);
  const RankResult rr = jacobian_rank(J);
  EXPECT_EQ(rr.rank, 3);
  EXPECT_EQ(rr.dof, 0);
  // Driving one crease cannot be closed.
  Eigen::VectorXd start = reference_unknowns(p, t, sys);
  start[0] += 0.2;
  NewtonOptions no;
  no.held_unknowns = {0};
  EXPECT_FALSE(newton_project(sys, start, no).converged);
}

}}  // namespace
}  // namespace rigidfold
