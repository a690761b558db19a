// A thick waterbomb tessellation (data/generators/waterbomb_tessellation.hpp: every interior
// vertex a diamond vertex with a = pi/4, sectors 45, 90, 45, 45, 90, 45 deg) with every
// vertex a plane-symmetric Bricard linkage (seed 003 §4.4.1, eqs 4-40, 4-41) made of hinge
// heights, traced by the core's ClosureSystem with one SE(3) loop per vertex.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "data/generators/waterbomb_tessellation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/thick_mobility.hpp"
#include "kernel/thick/thick_vertex_models.hpp"
#include "kernel/thick/vertex_height_steps.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

struct Tessellation {
  generators::WaterbombTessellationParams params{3, 3};
  CreasePattern flat = generators::waterbomb_tessellation(params);
  Topology topology = build_topology(flat);

  bool horizontal(int e) const { return std::abs(flat.vertices[flat.edges[e][0]].y() - flat.vertices[flat.edges[e][1]].y()) < 1e-12; }
  // The uniform zero-thickness motion: every vertex on the diamond relation (4-39) with the
  // horizontal creases at rho0 (valley) and every diagonal at the mountain angle it gives.
  Eigen::VectorXd uniform_state(double rho0) const {
    const std::vector<double> diamond = diamond_zero_thickness(kPi / 4, rho0);  // creases 0 and 3 horizontal
    Eigen::VectorXd fold = Eigen::VectorXd::Zero(flat.num_edges());
    for (int e = 0; e < flat.num_edges(); ++e)
      if (flat.assignments[e] != Assignment::Boundary) fold[e] = horizontal(e) ? diamond[0] : diamond[1];
    return fold;
  }
  // Per interior vertex, the diamond model's height steps (t1, -t2, -t34, +t34, +t2, -t1)
  // from its crease pointing along +x, counter-clockwise (tests/thick/vertex_heights_test.cpp
  // found this order for the Bricard diamond).
  std::vector<std::vector<double>> steps(double t1, double t2, double t34) const {
    const std::vector<double> model{t1, -t2, -t34, t34, t2, -t1};
    std::vector<std::vector<double>> out(flat.num_vertices());
    for (int v : topology.interior_vertices) {
      const Fan& fan = topology.stars[v].fans[0];
      int first = -1;
      for (int k = 0; k < 6; ++k) {
        const int e = fan.edges[k];
        const int w = flat.edges[e][0] == v ? flat.edges[e][1] : flat.edges[e][0];
        if (horizontal(e) && flat.vertices[w].x() > flat.vertices[v].x()) first = k;
      }
      for (int k = 0; k < 6; ++k) out[v].push_back(model[((k - first) % 6 + 6) % 6]);
    }
    return out;
  }
};

// Creases that touch no interior vertex: free flaps along the boundary, one DOF each at any
// thickness.
int free_flaps(const Tessellation& tess) {
  int flaps = 0;
  for (int e = 0; e < tess.flat.num_edges(); ++e) {
    if (tess.flat.assignments[e] == Assignment::Boundary) continue;
    bool touches = false;
    for (int v : tess.topology.interior_vertices) touches = touches || tess.flat.edges[e][0] == v || tess.flat.edges[e][1] == v;
    if (!touches) ++flaps;
  }
  return flaps;
}

// With the compact-folding lengths a34 = a45 = a12 + a23 (4-41c) the vertices' height
// profiles agree on every shared crease, and the thick tessellation follows the uniform
// zero-thickness motion over the whole range. Its mobility drops from 7 DOF (+ the flaps) at
// zero thickness to 1 (+ the flaps): every Bricard vertex has one DOF of its own.
TEST(ThickWaterbombTessellation, CompactBricardHeightsFollowTheUniformMotionWithOneDof) {
  const Tessellation tess;
  ASSERT_EQ(tess.topology.interior_vertices.size(), 4u);
  const int flaps = free_flaps(tess);
  EXPECT_EQ(flaps, 2);
  const ClosureSystem zero(tess.flat, tess.topology);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  zero.evaluate(zero.unknowns_from_edges(tess.uniform_state(1.0)), r, J);
  EXPECT_LE(r.cwiseAbs().maxCoeff(), 1e-14);  // the uniform diamond motion is a zero-thickness motion
  EXPECT_EQ(jacobian_rank(J).dof, 7 + flaps);

  const double t1 = 0.05, t2 = 0.08;
  const std::vector<double> heights = hinge_heights_from_steps(tess.flat, tess.topology, tess.steps(t1, t2, t1 + t2));
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(tess.flat, tess.topology, heights);
  const ClosureSystem thick(sheet.pattern, sheet.topology, sheet.options);
  EXPECT_EQ(thick.num_holes(), 4);
  double worst = 0.0;
  for (int k = 1; k < 40; ++k)
    worst = std::max(worst, thick.residual(thick.unknowns_from_edges(sheet.sheet_edge_angles(tess.uniform_state(kPi * k / 40))))
                                .cwiseAbs()
                                .maxCoeff());
  EXPECT_LE(worst, 1e-14);
  const ThickMobilityReport folded = thick_mobility(sheet, tess.uniform_state(1.0), {});
  EXPECT_EQ(folded.dof, 1 + flaps);
  EXPECT_GT(folded.rank.sigma_kept, 1e-3);  // a clear gap to the cut
  for (const ThickVertexMobility& v : folded.vertices) EXPECT_EQ(v.dof_alone, 1) << "vertex " << v.vertex;
  // The flat state is a bifurcation of every Bricard vertex (first-order DOF 2 alone there),
  // as the seed notes for the flat state of these vertices; the count there is not the mobility.
  const ThickMobilityReport flat = thick_mobility(sheet, Eigen::VectorXd::Zero(tess.flat.num_edges()), {});
  for (const ThickVertexMobility& v : flat.vertices) EXPECT_EQ(v.dof_alone, 2) << "vertex " << v.vertex;
  std::printf("thick waterbomb tessellation (3 x 3, 4 Bricard vertices): uniform zero-thickness states close it to %.2e; DOF %d "
              "(zero thickness %d), %d of them free boundary flaps\n",
              worst, folded.dof, 7 + flaps, flaps);
}

// Without the compact condition (a34 = a12 + a23 + 0.03) no heights agree across the
// tessellation: the conflict names the crease and the two vertices.
TEST(ThickWaterbombTessellation, NonCompactBricardLengthsHaveNoCommonHeights) {
  const Tessellation tess;
  try {
    hinge_heights_from_steps(tess.flat, tess.topology, tess.steps(0.05, 0.08, 0.16));
    FAIL() << "no conflict";
  } catch (const HingeHeightConflict& conflict) {
    EXPECT_NE(conflict.vertex_a, conflict.vertex_b);
    EXPECT_NE(std::string(conflict.what()).find("crease " + std::to_string(conflict.edge)), std::string::npos);
  }
}

}}  // namespace
}  // namespace rigidfold
