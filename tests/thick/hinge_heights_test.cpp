// Thick patterns from hinge heights (kernel/thick/hinge_heights.hpp): a flat crease pattern
// with every hinge lifted to its height and every vertex truncated into a hole that
// ClosureSystem closes in SE(3).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernel/closure/closure_system.hpp"
#include "kernel/closure/hole_closure.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/thick_vertex_models.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

TEST(ThickHeights, HingeHeightOfEachPlacement) {
  EXPECT_EQ(hinge_height(0.5, 0.2, HingePlacement::kBottom), 0.5);
  EXPECT_EQ(hinge_height(0.5, 0.2, HingePlacement::kTop), 0.7);
  EXPECT_EQ(hinge_height(0.5, 0.2, HingePlacement::kMid), 0.6);
}

// One flat-foldable degree-4 vertex with sectors (a12, a23, pi - a12, pi - a23) and hinge
// heights h (creases 0..3; boundary at 0).
struct HeightVertex {
  CreasePattern flat;
  ThickHeightSheet sheet;
  ClosureSystem system;
  HeightVertex(double a12, double a23, const std::vector<double>& crease_heights)
      : flat(testing::single_vertex_pattern({0.0, a12, a12 + a23, kPi + a23})),
        sheet(make_sheet(flat, crease_heights)),
        system(sheet.pattern, sheet.topology, sheet.options) {}
  static ThickHeightSheet make_sheet(const CreasePattern& flat, const std::vector<double>& crease_heights) {
    std::vector<double> h(flat.num_edges(), 0.0);
    for (int i = 0; i < 4; ++i) h[i] = crease_heights[i];
    return thick_sheet_from_hinge_heights(flat, build_topology(flat), h);
  }
  Eigen::VectorXd unknowns(const std::vector<double>& rho) const {
    Eigen::VectorXd fold = Eigen::VectorXd::Zero(flat.num_edges());
    for (int i = 0; i < 4; ++i) fold[i] = rho[i];
    return system.unknowns_from_edges(sheet.sheet_edge_angles(fold));
  }
};

// Bennett thickness a12 : a23 = sin a12 : sin a23 (4-4) as hinge heights. Going round the
// vertex the height must step by +-A, +-B, -+A, -+B (opposite links equal). Two of those
// orders exist up to a shift: the staircase (0, A, A + B, B) - up A, up B, down A, down B -
// and the zigzag (0, A, A - B, -B). The staircase is the seed's Bennett: the zero-thickness
// fold angles close it over the whole range, with one DOF. The zigzag is not: its loop does
// not close at them.
TEST(ThickHeights, BennettThicknessAsHingeHeights) {
  const double a12 = 0.7, a23 = 1.1, t = 0.2;
  const double A = t * std::sin(a12), B = t * std::sin(a23);
  const HeightVertex zigzag(a12, a23, {0, A, A - B, -B});
  const HeightVertex staircase(a12, a23, {0, A, A + B, B});
  ASSERT_EQ(staircase.system.num_holes(), 1);
  ASSERT_EQ(staircase.system.num_unknowns(), 4);
  ASSERT_EQ(staircase.system.num_rows(), 6);
  EXPECT_EQ(staircase.sheet.vertex_of_hole, std::vector<int>{0});
  double worst = 0.0, zigzag_least = 1e9;
  for (int k = 1; k < 50; ++k) {
    const std::vector<double> rho = bennett_zero_thickness(a12, a23, kPi * k / 50);
    worst = std::max(worst, staircase.system.residual(staircase.unknowns(rho)).cwiseAbs().maxCoeff());
    zigzag_least = std::min(zigzag_least, zigzag.system.residual(zigzag.unknowns(rho)).cwiseAbs().maxCoeff());
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    staircase.system.evaluate(staircase.unknowns(rho), r, J);
    EXPECT_EQ(jacobian_rank(J).dof, 1) << "rho0 = " << rho[0];
  }
  EXPECT_LE(worst, 1e-14);
  EXPECT_GE(zigzag_least, 1e-4);
  std::printf("Bennett from hinge heights: zero-thickness states close the staircase to %.2e, the zigzag to no better than %.2e\n",
              worst, zigzag_least);
}

}}  // namespace
}  // namespace rigidfold
