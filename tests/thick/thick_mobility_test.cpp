// Where thickness breaks motion (kernel/thick/thick_mobility.hpp): the thick Type 3 square
// twist with Bennett hinge heights keeps one DOF at its (regular) flat state; raising one
// outer hinge of vertex 2 by 0.01 turns that vertex into a generic spatial 4R loop, which
// locks it and with it the whole pattern, and the report names it.
#include <gtest/gtest.h>

#include <numbers>

#include "data/generators/square_twist.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/thick/bennett_heights.hpp"
#include "kernel/thick/thick_mobility.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

struct ThickSquareTwist {
  CreasePattern flat = generators::square_twist(generators::SquareTwistParams{}, generators::SquareTwistType::Type3);
  Topology topology = build_topology(flat);
  FoldFamily family = *verdict_with_assignment(flat, topology).family;
  std::vector<double> heights = bennett_hinge_heights(flat, topology, family.angles(family.parameter_for(0, 1.0)), 0.05);
  std::vector<Eigen::VectorXd> zero_states() const {
    std::vector<Eigen::VectorXd> states;
    const double sign = family.angles(1.0)[0] > 0 ? 1.0 : -1.0;
    for (int k = 1; k < 10; ++k) states.push_back(family.angles(family.parameter_for(0, sign * kPi * k / 10)));
    return states;
  }
};

TEST(ThickMobility, BennettSquareTwistIsMobileAtItsRegularFlatState) {
  const ThickSquareTwist twist;
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(twist.flat, twist.topology, twist.heights);
  const ThickMobilityReport report = thick_mobility(sheet, Eigen::VectorXd::Zero(twist.flat.num_edges()), twist.zero_states());
  EXPECT_EQ(report.dof, 1);
  // A clear gap: the smallest kept singular value is far above the cut (and above round-off).
  EXPECT_GT(report.rank.sigma_kept, 1e-3);
  EXPECT_LT(report.rank.sigma_dropped, 1e-14);
  ASSERT_EQ(report.vertices.size(), 4u);
  for (const ThickVertexMobility& v : report.vertices) {
    EXPECT_EQ(v.creases, 4);
    EXPECT_EQ(v.dof_alone, 1) << "vertex " << v.vertex;
    EXPECT_LE(v.off_motion, 1e-13) << "vertex " << v.vertex;
  }
  EXPECT_TRUE(report.locked_vertices.empty());
  EXPECT_TRUE(report.off_motion_vertices.empty());
}

TEST(ThickMobility, OneNonBennettVertexLocksTheSquareTwistAndIsNamed) {
  ThickSquareTwist twist;
  twist.heights[8] += 0.01;  // edge 8: outer crease o_a of vertex C (= 2); its heights are no longer a Bennett staircase
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(twist.flat, twist.topology, twist.heights);
  const ThickMobilityReport report = thick_mobility(sheet, Eigen::VectorXd::Zero(twist.flat.num_edges()), twist.zero_states());
  // DOF 0 at a regular point (the smallest singular value far above the cut): the flat state
  // is isolated, the thick pattern is rigid.
  EXPECT_EQ(report.dof, 0);
  EXPECT_GT(report.rank.sigma_kept, 1e-4);
  EXPECT_EQ(report.locked_vertices, std::vector<int>{2});
  EXPECT_EQ(report.off_motion_vertices, std::vector<int>{2});
  std::printf("square twist with vertex 2 off Bennett: pattern DOF %d (smallest singular value %.2e, cut %.2e); locked: vertex %d\n",
              report.dof, report.rank.sigma_kept, report.rank.threshold, report.locked_vertices.empty() ? -1 : report.locked_vertices[0]);
}

TEST(ThickMobility, RejectsAStateThatDoesNotClose) {
  ThickSquareTwist twist;
  twist.heights[8] += 0.01;
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(twist.flat, twist.topology, twist.heights);
  EXPECT_THROW(thick_mobility(sheet, twist.zero_states()[3], {}), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold
