// Compatibility of adjacent thick vertices (kernel/thick/panel_compatibility.hpp) on the
// square twist (seed 003 Fig. 4-4): four Bennett vertices share the central square and the
// four parallelograms.
#include <gtest/gtest.h>

#include <numbers>

#include "data/generators/square_twist.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/panel_compatibility.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

std::vector<PanelThicknessClaim> square_twist_claims(const Topology& topology, double twist,
                                                     const std::vector<double>& thickness_of_vertex) {
  std::vector<PanelThicknessClaim> claims;
  for (int v = 0; v < 4; ++v) {
    // Square-twist vertex sectors CCW: pi/2, pi - t, pi/2, t; the Bennett model's
    // (a12, a23, pi - a12, pi - a23) with a12 = t, a23 = pi/2 is a cyclic shift of them.
    const auto mine = vertex_panel_claims(bennett_vertex(twist, kPi / 2, thickness_of_vertex[v]), topology, v);
    claims.insert(claims.end(), mine.begin(), mine.end());
  }
  return claims;
}

TEST(ThickCompatibility, SquareTwistOfEqualBennettVerticesAgrees) {
  generators::SquareTwistParams params;
  const CreasePattern pattern = generators::square_twist(params, generators::SquareTwistType::Type3);
  const Topology topology = build_topology(pattern);
  const double t = params.twist;
  const auto claims = square_twist_claims(topology, t, {0.2, 0.2, 0.2, 0.2});
  EXPECT_EQ(claims.size(), 16u);
  const std::vector<double> thickness = agreed_panel_thickness(pattern.num_faces(), claims);
  // The central square is asked for 0.2 sin(pi/2) by all four vertices, each parallelogram
  // for 0.2 sin t by the vertex at its angle t and 0.2 sin(pi - t) by the one at pi - t.
  int central = 0, parallelograms = 0;
  for (double value : thickness) {
    if (std::abs(value - 0.2) < 1e-15) ++central;
    if (std::abs(value - 0.2 * std::sin(t)) < 1e-15) ++parallelograms;
  }
  EXPECT_EQ(central, 1 + 4);  // the square, and the four corner rectangles (pi/2 sectors)
  EXPECT_EQ(parallelograms, 4);
}

TEST(ThickCompatibility, MismatchNamesThePanelAndBothVertices) {
  generators::SquareTwistParams params;
  const CreasePattern pattern = generators::square_twist(params, generators::SquareTwistType::Type3);
  const Topology topology = build_topology(pattern);
  const auto claims = square_twist_claims(topology, params.twist, {0.2, 0.2, 0.3, 0.2});
  try {
    agreed_panel_thickness(pattern.num_faces(), claims);
    FAIL() << "no conflict found";
  } catch (const PanelThicknessConflict& conflict) {
    const std::string message = conflict.what();
    EXPECT_NE(message.find("panel " + std::to_string(conflict.first.panel)), std::string::npos) << message;
    EXPECT_EQ(conflict.first.panel, conflict.second.panel);
    EXPECT_NE(message.find("vertex 2 (Bennett)"), std::string::npos) << message;
    EXPECT_NE(message.find("0.3"), std::string::npos) << message;
  }
}

TEST(ThickCompatibility, RejectsAVertexWhoseSectorsDoNotMatch) {
  generators::SquareTwistParams params;
  const CreasePattern pattern = generators::square_twist(params, generators::SquareTwistType::Type3);
  const Topology topology = build_topology(pattern);
  EXPECT_THROW(vertex_panel_claims(bennett_vertex(params.twist + 0.01, kPi / 2, 0.2), topology, 0), std::invalid_argument);
  EXPECT_THROW(vertex_panel_claims(bennett_vertex(params.twist, kPi / 2, 0.2), topology, 4), std::invalid_argument);  // boundary
  EXPECT_THROW(agreed_panel_thickness(2, {PanelThicknessClaim{"v", 0, 2, 0.1}}), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold
