// square_twist_cross_check (design/metamaterial/square_twist_cross_check.hpp): the seed's
// square-twist closed forms against the T1 tessellation traced by the general solver, for
// the seed's alpha = 5 pi / 6 with a = b = c, a case with three stationary points of H
// (alpha = 105 deg), a rectangular unit cell (b != c, the generator's spacing_y) and a large
// a (lengths scale, differences do not). The heights are compared here again with the
// closed form (square_twist_unit.hpp), and the sign change of nu_HL at every stationary
// point is asserted from the traced values. Bad input: InputError naming the parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "data/generators/square_twist_tessellation.hpp"
#include "design/metamaterial/square_twist_cross_check.hpp"
#include "design/metamaterial/square_twist_unit.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

SquareTwistUnitParams unit(double alpha_deg, double a, double b, double c) {
  SquareTwistUnitParams p;
  p.alpha = alpha_deg * kPi / 180;
  p.a = a;
  p.b = b;
  p.c = c;
  return p;
}

void expect_agreement(const SquareTwistUnitParams& p, const std::string& where) {
  const SquareTwistCrossCheck cc = square_twist_cross_check(p);
  EXPECT_GE(cc.traced_steps, 30) << where;
  EXPECT_GE(cc.compared_steps, 30) << where;
  EXPECT_LE(cc.max_residual, kCrossCheckResidual) << where;
  EXPECT_LE(cc.max_phi_difference, kCrossCheckTolerance) << where;
  EXPECT_LE(cc.max_dimension_difference, kCrossCheckTolerance) << where;
  EXPECT_LE(cc.max_derivative_difference, kCrossCheckTolerance) << where;
  EXPECT_LE(cc.max_ratio_difference, kCrossCheckTolerance) << where;
  EXPECT_TRUE(cc.nu_SL_negative) << where;
  // The closed form's stationary points, computed here, one for one.
  const auto closed = square_twist_height_stationary_points(p);
  ASSERT_EQ(cc.stationary.size(), closed.size()) << where;
  for (std::size_t i = 0; i < closed.size(); ++i) {
    const auto& q = cc.stationary[i];
    EXPECT_EQ(q.maximum, closed[i].maximum) << where;
    EXPECT_NEAR(q.theta_traced, closed[i].theta, kCrossCheckTolerance) << where;
    EXPECT_NEAR(q.height_traced, closed[i].height, kCrossCheckTolerance * p.a) << where;
    // nu_HL changes sign there: positive before a maximum, negative after; it is 0 at it.
    EXPECT_GT(q.maximum ? q.nu_HL_before : q.nu_HL_after, 0.0) << where;
    EXPECT_LT(q.maximum ? q.nu_HL_after : q.nu_HL_before, 0.0) << where;
    EXPECT_LE(std::fabs(q.nu_HL_at), 1e-8) << where;
  }
  const SquareTwistHeightMaximum m = square_twist_height_maximum(p);
  EXPECT_NEAR(cc.height_maximum_traced, m.height, kCrossCheckTolerance * p.a) << where;
  EXPECT_NEAR(cc.height_maximum_theta_traced, m.theta, kCrossCheckTolerance) << where;
  char text[200];
  std::snprintf(text, sizeof text, "dims %.2e deriv %.2e nu %.2e stationary theta %.2e H %.2e, %zu points, %.2f s",
                cc.max_dimension_difference, cc.max_derivative_difference, cc.max_ratio_difference,
                cc.max_stationary_theta_difference, cc.max_stationary_height_difference, cc.stationary.size(),
                cc.seconds);
  std::printf("[ cross-check ] %s: %s\n", where.c_str(), text);
}

TEST(MetamaterialSquareTwistCrossCheck, SeedAlphaUnitCell) {
  expect_agreement(unit(150, 1, 1, 1), "alpha 150, a = b = c = 1");
}

TEST(MetamaterialSquareTwistCrossCheck, ThreeStationaryPointsAt105Degrees) {
  const auto p = unit(105, 1, 1, 1);
  ASSERT_EQ(square_twist_height_stationary_points(p).size(), 3u);
  expect_agreement(p, "alpha 105");
}

// Near the flat-foldable limits: alpha = 179 deg (H tiny, the second singular value of the
// closure Jacobian near 1e-4 at the end of the trace) and alpha = 95 deg (mu = 0.044: theta
// stays small while phi folds; two maxima of equal height and a minimum).
TEST(MetamaterialSquareTwistCrossCheck, NearTheLimitsOfAlpha) {
  expect_agreement(unit(179, 1, 1.5, 1.5), "alpha 179");
  const auto p = unit(95, 1, 1.5, 1.5);
  ASSERT_EQ(square_twist_height_stationary_points(p).size(), 3u);
  expect_agreement(p, "alpha 95");
}

TEST(MetamaterialSquareTwistCrossCheck, RectangularCellAndScale) {
  expect_agreement(unit(140, 1.3, 1.1, 1.6), "alpha 140, a 1.3, b 1.1, c 1.6");
  // Lengths scale with a; the relative differences are those of a = 1.
  const SquareTwistCrossCheck small = square_twist_cross_check(unit(125, 1, 0.8, 1.1));
  const SquareTwistCrossCheck large = square_twist_cross_check(unit(125, 250, 200, 275));
  EXPECT_NEAR(large.height_maximum_traced, 250 * small.height_maximum_traced, 1e-12 * large.height_maximum_traced);
  EXPECT_EQ(large.max_ratio_difference, small.max_ratio_difference);
  EXPECT_EQ(large.max_dimension_difference, small.max_dimension_difference);
}

TEST(MetamaterialSquareTwistCrossCheck, BadInputNamesTheParameter) {
  auto place = [](const SquareTwistUnitParams& p, const SquareTwistCrossCheckOptions& o) -> std::string {
    try {
      square_twist_cross_check(p, o);
    } catch (const InputError& e) {
      return e.place();
    }
    return "none";
  };
  const SquareTwistCrossCheckOptions o;
  // -a cos(150 deg) = 0.866: the pleat creases between twists vanish below it.
  EXPECT_EQ(place(unit(150, 1, 0.8, 1), o), "b");
  EXPECT_EQ(place(unit(150, 1, 1, 0.86), o), "c");
  EXPECT_EQ(place(unit(150, 1, 1, NAN), o), "c");
  EXPECT_EQ(place(unit(80, 1, 1, 1), o), "alpha");
  EXPECT_EQ(place(unit(150, 0, 1, 1), o), "a");
  SquareTwistCrossCheckOptions few;
  few.steps = 5;
  EXPECT_EQ(place(unit(150, 1, 1, 1), few), "steps");
  SquareTwistCrossCheckOptions far;
  far.to_deg = 180;
  EXPECT_EQ(place(unit(150, 1, 1, 1), far), "to_deg");
  EXPECT_NEAR(square_twist_cross_check_min_offset(150 * kPi / 180, 2), 2 * std::sqrt(3.0) / 2, 1e-15);
}

// The generator's spacing_y: 0 or equal to spacing gives the same sheet; another value moves
// only the y coordinates of the twists (row j by j (spacing_y - spacing)).
TEST(MetamaterialSquareTwistCrossCheck, GeneratorSpacingY) {
  generators::SquareTwistTessellationParams sp;
  sp.rows = 3;
  sp.cols = 2;
  sp.twist = 0.5;
  sp.spacing = 2.2;
  const CreasePattern base = generators::square_twist_tessellation(sp);
  sp.spacing_y = 2.2;
  const CreasePattern same = generators::square_twist_tessellation(sp);
  ASSERT_EQ(same.num_vertices(), base.num_vertices());
  for (int v = 0; v < base.num_vertices(); ++v) EXPECT_EQ((same.vertices[v] - base.vertices[v]).norm(), 0.0);
  sp.spacing_y = 3.0;
  const CreasePattern tall = generators::square_twist_tessellation(sp);
  ASSERT_EQ(tall.num_edges(), base.num_edges());
  for (int v = 0; v < 4 * 6; ++v) {
    const int j = v / 4 / 2;
    EXPECT_NEAR(tall.vertices[v].x(), base.vertices[v].x(), 1e-15);
    EXPECT_NEAR(tall.vertices[v].y() - base.vertices[v].y(), j * 0.8, 1e-14);
  }
  sp.spacing_y = 1.0;  // below side (sin t + cos t) = 1.357
  try {
    generators::square_twist_tessellation(sp);
    ADD_FAILURE() << "spacing_y below the twists' width accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "spacing_y");
  }
}

}}  // namespace
}  // namespace rigidfold::metamaterial
