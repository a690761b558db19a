// The box of six five-crease vertices (sectors pi/6, pi/2, 2pi/3, pi/2, pi/6),
// built, traced and shown mobile (seed 003 §4.3, Fig. 4-8): the hexagonal box
// (data/generators/hexagonal_box.hpp) with every vertex the Myard thick model
// (kernel/thick/thick_vertex_models.hpp, a = pi/6) made of hinge heights
// (vertex_height_steps.hpp), closed and traced by the core's ClosureSystem (one SE(3) hole
// per vertex) and checked with thick_mobility.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "data/generators/hexagonal_box.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/thick_mobility.hpp"
#include "kernel/thick/thick_vertex_models.hpp"
#include "kernel/thick/vertex_height_steps.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;
constexpr double kA = kPi / 6;

struct Box {
  CreasePattern flat = generators::hexagonal_box({});
  Topology topology = build_topology(flat);
  ThickVertexModel model = myard_vertex(kA, 0.02);
  std::vector<int> first;  // per vertex: fan position of the model's crease 0 (-1: not interior)

  Box() {
    first.assign(flat.num_vertices(), -1);
    for (int v : topology.interior_vertices) {
      const Fan& fan = topology.stars[v].fans[0];
      for (int k = 0; k < static_cast<int>(fan.sectors.size()) && first[v] < 0; ++k) {
        bool ok = fan.sectors.size() == model.sectors.size();
        for (std::size_t i = 0; ok && i < model.sectors.size(); ++i)
          ok = std::abs(fan.sectors[(k + i) % fan.sectors.size()] - model.sectors[i]) < 1e-9;
        if (ok) first[v] = k;
      }
    }
  }
  // Fold angles of the uniform motion: every vertex on the Myard relation (4-23 corrected)
  // from the radial crease's fold angle rho0 (valley, > 0).
  Eigen::VectorXd uniform_state(double rho0) const {
    const std::vector<double> rho = myard_zero_thickness(kA, rho0);
    Eigen::VectorXd fold = Eigen::VectorXd::Zero(flat.num_edges());
    for (int v : topology.interior_vertices) {
      const Fan& fan = topology.stars[v].fans[0];
      for (int i = 0; i < 5; ++i) fold[fan.edges[(first[v] + i) % 5]] = rho[i];
    }
    return fold;
  }
  // Height steps of the model at every vertex: the link lengths with the signs (+, +, +, -, -)
  // round the vertex from crease 0 (heights 0, a12, a12 + a23, same, a51).
  std::vector<std::vector<double>> steps() const {
    const std::vector<double> sign{1, 1, 1, -1, -1};
    std::vector<std::vector<double>> out(flat.num_vertices());
    for (int v : topology.interior_vertices) {
      out[v].assign(5, 0.0);
      for (int i = 0; i < 5; ++i) out[v][(first[v] + i) % 5] = sign[i] * model.thick.loops[0].joints[i].link.length;
    }
    return out;
  }
};

TEST(ThickBox, SixMyardVerticesAreMobileWithOneDofAndFollowTheZeroThicknessMotion) {
  const Box box;
  ASSERT_EQ(box.topology.interior_vertices.size(), 6u);
  for (int v : box.topology.interior_vertices) ASSERT_GE(box.first[v], 0) << "vertex " << v << " is not the Myard vertex";

  // Zero thickness: the uniform motion closes the core; the pattern has more than one DOF.
  const ClosureSystem zero(box.flat, box.topology);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  zero.evaluate(zero.unknowns_from_edges(box.uniform_state(1.0)), r, J);
  EXPECT_LE(r.cwiseAbs().maxCoeff(), 1e-14);
  const int zero_dof = jacobian_rank(J).dof;
  EXPECT_GT(zero_dof, 1);

  // Thick: heights agree across the box (hexagon sides are a34 = 0 links at every vertex).
  const std::vector<double> heights = hinge_heights_from_steps(box.flat, box.topology, box.steps());
  const auto [low, high] = std::minmax_element(heights.begin(), heights.end());
  EXPECT_NEAR(*high - *low, 3 * 0.02, 1e-15);  // a12 + a23 = t (1 + 1/sin a): the hinges are not coplanar
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(box.flat, box.topology, heights);
  const ClosureSystem thick(sheet.pattern, sheet.topology, sheet.options);
  EXPECT_EQ(thick.num_holes(), 6);
  double worst = 0.0;
  std::vector<Eigen::VectorXd> zero_states;
  for (int k = 1; k < 40; ++k) {
    zero_states.push_back(box.uniform_state(kPi * k / 40));
    worst = std::max(worst, thick.residual(thick.unknowns_from_edges(sheet.sheet_edge_angles(zero_states.back()))).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(worst, 1e-13);

  // Traced with the general corrector, radial crease of the first vertex driven.
  const int driven = box.topology.stars[box.topology.interior_vertices[0]].fans[0].edges[box.first[box.topology.interior_vertices[0]]];
  NewtonOptions newton;
  newton.tolerance = 1e-14;
  newton.held_unknowns = {thick.unknown_of_edge(driven)};
  Eigen::VectorXd state = box.uniform_state(0.05 * kPi);
  double off = 0.0;
  int steps = 0;
  for (int k = 1; k <= 19; ++k) {
    const double rho0 = kPi * 0.05 * k;
    state[driven] = rho0;
    const NewtonResult result = newton_project(thick, thick.unknowns_from_edges(sheet.sheet_edge_angles(state)), newton);
    ASSERT_TRUE(result.converged) << "rho0 = " << rho0;
    state = sheet.fold_angles(thick.edges_from_unknowns(result.x));
    off = std::max(off, (state - box.uniform_state(rho0)).cwiseAbs().maxCoeff());
    const ThickMobilityReport m = thick_mobility(sheet, state, {}, 1e-12);
    EXPECT_EQ(m.dof, 1) << "rho0 = " << rho0;
    EXPECT_GT(m.rank.sigma_kept, 1e3 * m.rank.threshold) << "rho0 = " << rho0;
    ++steps;
  }
  EXPECT_LE(off, 1e-10);
  const ThickMobilityReport folded = thick_mobility(sheet, box.uniform_state(1.0), zero_states, 1e-12);
  EXPECT_EQ(folded.dof, 1);
  EXPECT_TRUE(folded.locked_vertices.empty());
  EXPECT_TRUE(folded.off_motion_vertices.empty());
  for (const ThickVertexMobility& v : folded.vertices) EXPECT_EQ(v.dof_alone, 1) << "vertex " << v.vertex;
  std::printf("thick hexagonal box (6 Myard vertices, a = pi/6): zero-thickness states close it to %.1e; traced %d steps to "
              "rho0 = 0.95 pi, %.1e off the zero-thickness motion; DOF %d (sigma_kept %.2e, cut %.1e; zero thickness %d)\n",
              worst, steps, off, folded.dof, folded.rank.sigma_kept, folded.rank.threshold, zero_dof);
}

}}  // namespace
}  // namespace rigidfold
