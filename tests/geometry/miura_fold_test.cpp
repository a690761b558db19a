// Acceptance: folding a Miura-ori with its closed-form fold angles places every face with a
// closure mismatch <= 1e-12 of the pattern size, at every fold and several sizes; and the
// placed faces reproduce the closed-form fold angles when measured back from the geometry.
#include <gtest/gtest.h>


#include "data/generators/miura.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(MiuraFold, ClosedFormAnglesPlaceFacesWithoutMismatch) {
  for (int n : {2, 5, 20, 60}) {
    for (double alpha_deg : {30.0, 60.0, 80.0}) {
      generators::MiuraParams m;
      m.rows = n;
      m.cols = n + 1;
      m.alpha = to_radians(alpha_deg);
      m.a = 1.0;
      m.b = 1.7;
      const CreasePattern p = generators::miura_ori(m);
      const Topology t = build_topology(p);
      for (double straight : {1e-6, 0.4, 1.7, 3.0}) {
        const Eigen::VectorXd rho = fold_angle_vector(generators::miura_fold_angles(p, m, straight));
        const FoldedGeometry g = place_faces(p, t, rho, Eigen::VectorXd::Zero(p.num_edges()));
        EXPECT_LE(g.relative_mismatch(), 1e-12) << n << "x" << n + 1 << " alpha " << alpha_deg << " straight " << straight;
        EXPECT_GT(g.non_tree_hinges, 0);
        // Measure the fold angles back from the placed faces.
        CreasePattern folded = p;
        folded.vertices = g.vertices;
        folded.coords_2d = false;
        const Eigen::VectorXd measured = reference_fold_angles(folded, build_topology(folded));
        double worst = 0;
        for (int e = 0; e < p.num_edges(); ++e)
          if (t.edge_is_hinge[e]) worst = std::max(worst, std::fabs(measured[e] - rho[e]));
        EXPECT_LE(worst, 1e-11) << n << " alpha " << alpha_deg << " straight " << straight;
      }
    }
  }
}

TEST(MiuraFold, WrongAnglesShowAsMismatch) {
  generators::MiuraParams m;
  m.rows = m.cols = 6;
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const Eigen::VectorXd rho = 1.001 * fold_angle_vector(generators::miura_fold_angles(p, m, 1.2));  // a 0.1% error in every angle breaks the closure
  const FoldedGeometry g = place_faces(p, t, rho, Eigen::VectorXd::Zero(p.num_edges()));
  EXPECT_GT(g.relative_mismatch(), 1e-5);
}

}}  // namespace
}  // namespace rigidfold
