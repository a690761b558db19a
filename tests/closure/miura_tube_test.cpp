// Miura tube (data/generators/miura_tube.hpp): mobility with the SE(3) hole closure. The known
// answer (Tachi 2009; Filipov, Tachi and Paulino 2015): 1 DOF, each strip following the
// Miura-ori's own rigid mode. Checked three ways: rank of the closure Jacobian, a traced
// motion whose strip-A fold angles match the Miura-ori closed form (miura_fold_angles, an
// independent formula) and whose strip B stays the mirror image of strip A, and the faces
// placed from the traced angles closing up around the tube.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "data/generators/miura.hpp"
#include "data/generators/miura_tube.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/closure/hole_closure.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {


ClosureSystem tube_system(const CreasePattern& p, const Topology& t) {
  ClosureOptions o;
  o.close_holes = true;
  return ClosureSystem(p, t, o);
}

int dof_of_rows(const Eigen::SparseMatrix<double>& J, int rows) {
  const Eigen::SparseMatrix<double> top = J.topRows(rows);
  return jacobian_rank(top).dof;
}

TEST(MiuraTube, TopologyIsAnAnnulus) {
  generators::MiuraTubeParams tp;
  tp.rows = 5;
  const CreasePattern p = generators::miura_tube(tp);
  const Topology t = build_topology(p);
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.components[0].holes, 1);
  EXPECT_EQ(t.components[0].genus, 0);
  EXPECT_EQ(t.interior_vertices.size(), 4u * (tp.rows - 1));
  EXPECT_EQ(find_hole_loops(p, t).size(), 1u);
  // Bond vertices are not developable: their sectors sum to 4 alpha or 4 (pi - alpha).
  int bond_cones = 0;
  for (int v : t.interior_vertices)
    if (std::abs(t.stars[v].sector_sum() - 2 * kPi) > 1e-6) ++bond_cones;
  EXPECT_EQ(bond_cones, 2 * (tp.rows - 1));
}

// Known mobility 1 over sizes, panel angles and reference states, and what the hole rows add.
TEST(MiuraTube, HasOneDofOnlyWithTheHoleClosure) {
  for (int rows : {1, 2, 4, 7}) {
    for (double alpha_deg : {45.0, 60.0, 75.0}) {
      for (double fold_deg : {60.0, 120.0}) {
        generators::MiuraTubeParams tp;
        tp.rows = rows;
        tp.alpha = to_radians(alpha_deg);
        tp.b = 1.3;
        tp.fold = to_radians(fold_deg);
        const CreasePattern p = generators::miura_tube(tp);
        const Topology t = build_topology(p);
        const ClosureSystem sys = tube_system(p, t);
        ASSERT_EQ(sys.num_holes(), 1);
        const Eigen::VectorXd x = sys.unknowns_from_edges(reference_fold_angles(p, t));
        Eigen::VectorXd r;
        Eigen::SparseMatrix<double> J;
        sys.evaluate(x, r, J);
        const std::string where = "rows " + std::to_string(rows) + " alpha " + std::to_string(alpha_deg) + " fold " +
                                  std::to_string(fold_deg);
        EXPECT_LE(r.lpNorm<Eigen::Infinity>(), 1e-12) << where;
        EXPECT_EQ(jacobian_rank(J).dof, 1) << where;
        // Vertex rows alone: a one-cell tube has no interior vertex, so its four bond and
        // middle creases are free (4) until the hole rows make it a 4-bar loop (1). From two
        // cells on, the ring of four degree-4 vertices around each level already ties the
        // motion to 1 DOF to first order, and the hole rows agree with it (they add no rank).
        EXPECT_EQ(dof_of_rows(J, sys.hole_row_begin()), rows == 1 ? 4 : 1) << where;
      }
    }
  }
}

TEST(MiuraTube, TracedMotionIsTheMiuraModeOnBothStrips) {
  generators::MiuraTubeParams tp;
  tp.rows = 4;
  tp.alpha = to_radians(55);
  tp.a = 1.0;
  tp.b = 1.4;
  tp.fold = 1.2;
  const CreasePattern p = generators::miura_tube(tp);
  const Topology t = build_topology(p);
  const ClosureSystem sys = tube_system(p, t);
  const Eigen::VectorXd reference = reference_fold_angles(p, t);
  const Eigen::VectorXd x0 = sys.unknowns_from_edges(reference);

  generators::MiuraParams mp;
  mp.rows = tp.rows;
  mp.cols = 2;
  mp.alpha = tp.alpha;
  mp.a = tp.a;
  mp.b = tp.b;
  const CreasePattern strip = generators::miura_ori(mp);
  const int drive = generators::miura_tube_a_straight(tp, 0, 1);  // an interior straight crease of A

  int points = 0;
  double worst_residual = 0, worst_mode = 0, worst_mirror = 0, worst_mismatch = 0, lo = kPi, hi = 0;
  for (double sense : {1.0, -1.0}) {
    Eigen::VectorXd direction = Eigen::VectorXd::Zero(sys.num_unknowns());
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(p.num_edges(), drive) * sense;
    direction = sys.unknowns_from_edges(e);
    ContinuationOptions co;
    co.max_step = 0.1;
    co.max_points = 400;
    const ContinuationResult cr = continue_one_dof(
        sys, x0, direction,
        [&](const Eigen::VectorXd& x) {
          const double s = std::abs(sys.edges_from_unknowns(x)[drive]);
          return s < 0.15 || s > 2.9;
        },
        co);
    ASSERT_TRUE(cr.stopped) << cr.reason;
    for (const ContinuationPoint& pt : cr.points) {
      ++points;
      worst_residual = std::max(worst_residual, pt.residual);
      const Eigen::VectorXd rho = sys.edges_from_unknowns(pt.x);
      // The strip keeps folding the way it is assigned (miura_fold_angles' positive side).
      const double s = std::abs(rho[drive]);
      lo = std::min(lo, s);
      hi = std::max(hi, s);
      const auto mode = generators::miura_fold_angles(strip, mp, s);
      for (int j = 1; j < tp.rows; ++j)
        for (int i : {0, 1})
          worst_mode = std::max(worst_mode, std::abs(rho[generators::miura_tube_a_straight(tp, i, j)] -
                                                     *mode[generators::miura_tube_a_straight(tp, i, j)]));
      for (int j = 0; j < tp.rows; ++j) {
        worst_mode = std::max(worst_mode, std::abs(rho[generators::miura_tube_a_zigzag(tp, 1, j)] -
                                                   *mode[generators::miura_tube_a_zigzag(tp, 1, j)]));
        worst_mirror = std::max(worst_mirror, std::abs(rho[generators::miura_tube_b_zigzag(tp, j)] -
                                                       rho[generators::miura_tube_a_zigzag(tp, 1, j)]));
      }
      for (int j = 1; j < tp.rows; ++j)
        for (int side : {0, 1})
          worst_mirror = std::max(worst_mirror, std::abs(rho[generators::miura_tube_b_straight(tp, side, j)] -
                                                         rho[generators::miura_tube_a_straight(tp, side, j)]));
      const FoldedGeometry g = place_faces(p, t, rho, reference);
      worst_mismatch = std::max(worst_mismatch, g.relative_mismatch());
    }
  }
  std::printf("[MiuraTube] %d points, straight crease %.1f..%.1f deg: residual %.2g, vs Miura mode %.2g rad, "
              "mirror %.2g rad, closure mismatch %.2g\n",
              points, to_degrees(lo), to_degrees(hi), worst_residual, worst_mode, worst_mirror, worst_mismatch);
  EXPECT_GE(points, 10);
  EXPECT_LE(lo, 0.16);
  EXPECT_GE(hi, 2.9);
  EXPECT_LE(worst_residual, 1e-12);
  EXPECT_LE(worst_mode, 1e-10);
  EXPECT_LE(worst_mirror, 1e-10);
  EXPECT_LE(worst_mismatch, 1e-10);
}

TEST(MiuraTube, BadParametersNameTheirField) {
  auto place_of = [](generators::MiuraTubeParams tp) -> std::string {
    try {
      generators::miura_tube(tp);
    } catch (const InputError& e) {
      return e.place();
    }
    return "";
  };
  generators::MiuraTubeParams tp;
  tp.fold = 0;
  EXPECT_EQ(place_of(tp), "fold");
  tp = {};
  tp.fold = kPi;
  EXPECT_EQ(place_of(tp), "fold");
  tp = {};
  tp.alpha = kPi / 2;
  EXPECT_EQ(place_of(tp), "alpha");
  tp = {};
  tp.rows = 0;
  EXPECT_EQ(place_of(tp), "rows");
}

}}  // namespace
}  // namespace rigidfold
