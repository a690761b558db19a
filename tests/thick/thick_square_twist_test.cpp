// The thick square twist (seed 003 §4.2, Fig. 4-4): four Bennett vertices around the central
// square, built from hinge heights (kernel/thick/bennett_heights.hpp) and traced by the
// core's ClosureSystem with one SE(3) hole closure per vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <numbers>

#include "data/generators/square_twist.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/bennett_heights.hpp"
#include "kernel/thick/hinge_heights.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

struct ZeroThicknessSquareTwist {
  CreasePattern flat;
  Topology topology;
  FoldFamily family;
  int driven = -1;        // the family's fastest crease (first to reach 180 deg)
  double driven_sign = 1;  // its sign on the branch
  explicit ZeroThicknessSquareTwist(generators::SquareTwistType type)
      : flat(generators::square_twist(generators::SquareTwistParams{}, type)), topology(build_topology(flat)) {
    const FoldabilityVerdict verdict = verdict_with_assignment(flat, topology);
    if (verdict.verdict != Verdict::kRigidlyFoldable) throw std::runtime_error("square twist: not rigidly foldable");
    family = *verdict.family;
    driven = family.fastest_crease(0);
    driven_sign = family.angles(1.0)[driven] > 0 ? 1.0 : -1.0;
  }
  // Zero-thickness fold angles (per edge) with the driven crease at |rho| = magnitude.
  Eigen::VectorXd state(double magnitude) const { return family.angles(family.parameter_for(driven, driven_sign * magnitude)); }
};

// Type 3 (seed 003's T1, rigid): the per-vertex Bennett staircases agree on the four sides
// of the central square, so the thick pattern exists with one thickness; it folds with the
// zero-thickness fold angles over the whole range with one DOF.
TEST(ThickSquareTwist, Type3WithBennettHeightsFoldsLikeZeroThickness) {
  const ZeroThicknessSquareTwist zero(generators::SquareTwistType::Type3);
  const double thickness = 0.05;
  const std::vector<double> heights = bennett_hinge_heights(zero.flat, zero.topology, zero.state(1.0), thickness);
  // Around the central square (sides 0..3) the hinges climb and fall by the square's
  // thickness, thickness * sin(pi/2), at each corner.
  for (int side = 0; side < 4; ++side) EXPECT_NEAR(std::abs(heights[(side + 1) % 4] - heights[side]), thickness, 1e-15);
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(zero.flat, zero.topology, heights);
  const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
  ASSERT_EQ(system.num_holes(), 4);
  ASSERT_EQ(system.num_vertices(), 0);  // every vertex is a truncated thick one
  ASSERT_EQ(system.num_unknowns(), 12);
  std::vector<int> holes = sheet.vertex_of_hole;  // each hole surrounds one square vertex (0..3)
  std::sort(holes.begin(), holes.end());
  EXPECT_EQ(holes, (std::vector<int>{0, 1, 2, 3}));

  auto unknowns = [&](const Eigen::VectorXd& fold) { return system.unknowns_from_edges(sheet.sheet_edge_angles(fold)); };
  auto folds = [&](const Eigen::VectorXd& x) { return sheet.fold_angles(system.edges_from_unknowns(x)); };
  NewtonOptions newton;
  newton.tolerance = 1e-14;
  newton.held_unknowns = {system.unknown_of_edge(zero.driven)};
  double worst = 0.0, worst_closed_form_residual = 0.0;
  int samples = 0;
  for (int direction : {+1, -1}) {
    Eigen::VectorXd x = unknowns(zero.state(kPi / 2)), previous = x;
    for (int k = 0; k < 100; ++k) {
      const double magnitude = kPi / 2 + direction * (kPi / 2) * k / 100.0;
      const Eigen::VectorXd expected = zero.state(magnitude);
      worst_closed_form_residual = std::max(worst_closed_form_residual, system.residual(unknowns(expected)).cwiseAbs().maxCoeff());
      Eigen::VectorXd guess = k >= 2 ? Eigen::VectorXd(2 * x - previous) : x;  // secant predictor, equal steps
      Eigen::VectorXd fold = folds(guess);
      fold[zero.driven] = expected[zero.driven];
      const NewtonResult result = newton_project(system, unknowns(fold), newton);
      ASSERT_TRUE(result.converged) << "driven |rho| = " << magnitude;
      previous = x;
      x = result.x;
      const Eigen::VectorXd traced = folds(x);
      for (int e = 0; e < 12; ++e) worst = std::max(worst, std::abs(std::remainder(traced[e] - expected[e], 2 * kPi)));
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> J;
      system.evaluate(x, r, J);
      if (k > 0) {
        EXPECT_EQ(jacobian_rank(J).dof, 1) << "driven |rho| = " << magnitude;
      }
      ++samples;
    }
  }
  EXPECT_LE(worst_closed_form_residual, 1e-13);
  EXPECT_LE(worst, 1e-10);
  std::printf("thick square twist Type 3: %d samples, driven crease |rho| in [0.0157, 3.126]: max |rho - rho_zero| %.2e rad, "
              "zero-thickness states close the 4 thick loops to %.2e\n",
              samples, worst, worst_closed_form_residual);
}

// Type 4 (seed 003's T2, also rigid at zero thickness): its per-vertex Bennett staircases
// cannot agree on the central square with one thickness; the conflict is named.
TEST(ThickSquareTwist, Type4HasNoUniformBennettHeights) {
  const ZeroThicknessSquareTwist zero(generators::SquareTwistType::Type4);
  try {
    bennett_hinge_heights(zero.flat, zero.topology, zero.state(1.0), 0.05);
    FAIL() << "no conflict";
  } catch (const HingeHeightConflict& conflict) {
    EXPECT_LT(conflict.edge, 4);  // a side of the central square
    EXPECT_NE(conflict.vertex_a, conflict.vertex_b);
    EXPECT_NE(std::string(conflict.what()).find("crease " + std::to_string(conflict.edge)), std::string::npos);
  }
}

}}  // namespace
}  // namespace rigidfold
