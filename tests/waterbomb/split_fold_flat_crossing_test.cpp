// The split-fold waterbomb's loaded path through the flat state: the branch past
// flat comes from the tangent cone of the symmetric closure system (waterbomb_flat_crossing
// with the split fold's motion classes), never from the printed forms; the printed forms
// (seed 004 eqs 3.13-3.30) are the cross-check on the far side.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "design/waterbomb/split_fold_bistability.hpp"
#include "design/waterbomb/split_fold_kinematics.hpp"
#include "design/waterbomb/waterbomb_flat_crossing.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/waterbomb/stopped_curve_expectations.hpp"

namespace rigidfold::waterbomb {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::vector<int> half_valleys(int n) {
  std::vector<int> v;
  for (int i = 0; i < 4 * n; ++i)
    if (i % 4 < 2) v.push_back(i);
  return v;
}

Eigen::VectorXd per_edge(const CreasePattern& p, int n, FoldPair g) {
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
  for (int i = 0; i < 4 * n; ++i) rho[i] = i % 4 < 2 ? g.gamma_v : g.gamma_m;
  return rho;
}

// The printed forms' one-sided tangent at flat (side +1: theta > 90 deg), by difference
// quotients from flat (both angles are 0 there) with two Richardson levels: error O(delta^3)
// (measured <= 5e-9 on the unit directions below, compared to 1e-7),
// delta = 2e-3 rad (closer to flat the printed forms lose digits to cancellation).
FoldPair printed_tangent(int n, double b, int side) {
  auto quotient = [&](double delta) {
    const FoldPair g = split_fold_angles_printed(n, b, kPi / 2 + side * delta);
    return Eigen::Vector2d(g.gamma_m / delta, g.gamma_v / delta);
  };
  const double delta = 2e-3;
  const Eigen::Vector2d d1 = quotient(delta), d2 = quotient(delta / 2), d4 = quotient(delta / 4);
  const Eigen::Vector2d r1 = 2 * d2 - d1, r2 = 2 * d4 - d2, t = (4 * r2 - r1) / 3;
  return {side * t[0], side * t[1]};
}

TEST(SplitFoldFlatCrossing, ConeHasTwoLinesAndTheTakenRayIsThePrintedTangent) {
  for (int n : {3, 4, 6}) {
    for (double bdeg : {5.0, 20.0}) {
      if (bdeg >= 180.0 / n) continue;
      SCOPED_TRACE(std::to_string(n) + " / " + std::to_string(bdeg));
      const double b = to_radians(bdeg);
      const CreasePattern p = split_fold_base(n, b);
      const FlatCrossing c = waterbomb_flat_crossing(p, half_valleys(n), split_fold_motion_classes(n));
      EXPECT_EQ(c.kernel_dimension, 2);  // the symmetric (gamma_m, gamma_v) plane
      EXPECT_EQ(c.cone_lines, 2);
      ASSERT_EQ(c.branches.size(), 4u);
      ASSERT_EQ(c.far_side_branches, 2);
      ASSERT_TRUE(c.continues) << c.message;
      const FlatBranch& taken = c.branches[c.taken];
      EXPECT_TRUE(taken.far_side);
      EXPECT_TRUE(taken.keeps_letters);
      EXPECT_LT(taken.height_rate, 0.0);
      // Independent oracle: the printed forms' one-sided tangent at 90+ deg.
      Eigen::VectorXd expected = per_edge(p, n, printed_tangent(n, b, +1));
      expected.normalize();
      EXPECT_LE((taken.direction - expected).lpNorm<Eigen::Infinity>(), 1e-7);
      // The rejected far-side ray is the mirror of the way in: the 90- tangent (traversed
      // backwards and negated, i.e. d/dtheta itself), and it breaks a letter.
      Eigen::VectorXd mirror = per_edge(p, n, printed_tangent(n, b, -1));
      mirror.normalize();
      int rejected = 0;
      for (int i = 0; i < 4; ++i) {
        if (i == c.taken || !c.branches[i].far_side) continue;
        ++rejected;
        EXPECT_FALSE(c.branches[i].keeps_letters);
        EXPECT_GE(c.branches[i].first_wrong_crease, 0);
        EXPECT_LE((c.branches[i].direction - mirror).lpNorm<Eigen::Infinity>(), 1e-7);
      }
      EXPECT_EQ(rejected, 1);
    }
  }
}

// With the rotational symmetry alone (crease i with crease i mod 4) the symmetric family is
// 3-DOF (4 angles per period, one closure condition): the cone has no isolated line and the
// choice is refused, never made silently.
TEST(SplitFoldFlatCrossing, RotationalSymmetryAloneLeavesAContinuumAndStops) {
  const int n = 4;
  const CreasePattern p = split_fold_base(n, to_radians(5.0));
  std::vector<std::vector<int>> classes(4);
  for (int i = 0; i < 4 * n; ++i) classes[i % 4].push_back(i);
  const FlatCrossing c = waterbomb_flat_crossing(p, half_valleys(n), classes);
  EXPECT_EQ(c.kernel_dimension, 4);
  EXPECT_EQ(c.cone_lines, 0);
  EXPECT_FALSE(c.continues);
  EXPECT_EQ(c.taken, -1);
  EXPECT_NE(c.message.find("no isolated line"), std::string::npos) << c.message;
}

TEST(SplitFoldFlatCrossing, MotionClassesMustPartitionTheFan) {
  const int n = 3;
  const CreasePattern p = split_fold_base(n, to_radians(5.0));
  std::vector<std::vector<int>> missing = split_fold_motion_classes(n);
  missing[1].pop_back();
  EXPECT_THROW(waterbomb_flat_crossing(p, half_valleys(n), missing), std::invalid_argument);
  std::vector<std::vector<int>> twice = split_fold_motion_classes(n);
  twice[1].push_back(0);
  EXPECT_THROW(waterbomb_flat_crossing(p, half_valleys(n), twice), std::invalid_argument);
  std::vector<std::vector<int>> boundary = split_fold_motion_classes(n);
  boundary[0].push_back(4 * n);  // a boundary chord, not a crease of the centre
  EXPECT_THROW(waterbomb_flat_crossing(p, half_valleys(n), boundary), std::invalid_argument);
}

// The continued far side equals the printed forms (fold angles within 1e-9 rad, symmetric,
// force = dV/dh of the printed energy): every sample of the curve is checked.
TEST(SplitFoldFlatCrossing, CurvePastFlatEqualsThePrintedForms) {
  for (int n : {3, 4}) {
    SCOPED_TRACE(n);
    const double b = to_radians(5.0);
    const SplitFoldCurve curve = split_fold_curve(n, b, to_radians(60.0), 1.0, 2.0, 101);
    ASSERT_TRUE(curve.crosses_flat);
    ASSERT_FALSE(curve.stopped_at_flat) << curve.stop_message;
    EXPECT_TRUE(curve.stop_message.empty()) << curve.stop_message;
    EXPECT_TRUE(curve.flat_crossing.continues);
    EXPECT_EQ(curve.unchecked, 0);
    int far = 0;
    double first_far_force = 0.0, last_near_force = 0.0;
    for (const CurveSample& s : curve.samples) {
      SCOPED_TRACE(to_degrees(s.theta));
      EXPECT_TRUE(s.checked);
      if (s.theta > kPi / 2) {
        if (far++ == 0) first_far_force = s.force;
      } else {
        last_near_force = s.force;
      }
    }
    EXPECT_GE(far, 4);
    // The force jumps at the flat corner: a push before, a pull after (the samples next to
    // flat lie 1e-2 of the range from it).
    EXPECT_GT(last_near_force, 0.0);
    EXPECT_LT(first_far_force, 0.0);
  }
}

// The choice matters: leaving flat along the rejected (mirror) ray the same loaded solve lands
// elsewhere, off the printed forms and with a letter broken; along the taken ray it lands on them.
TEST(SplitFoldFlatCrossing, TheMirrorRayLeadsElsewhere) {
  const int n = 4;
  const double b = to_radians(5.0), theta0 = to_radians(60.0), theta = to_radians(91.0);
  const CreasePattern p = split_fold_base(n, b);
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  Eigen::VectorXd k = Eigen::VectorXd::Zero(p.num_edges());
  for (int i = 0; i < 4 * n; ++i) k[i] = 1.0;
  const CreaseSprings springs = make_crease_springs(p, k, per_edge(p, n, split_fold_angles_printed(n, b, theta0)));
  VertexHeightLoad load;
  load.vertex = 0;
  load.support_edges = half_valleys(n);
  load.height = std::cos(b / 2) * std::cos(theta);
  const FlatCrossing c = waterbomb_flat_crossing(p, load.support_edges, split_fold_motion_classes(n));
  ASSERT_TRUE(c.continues) << c.message;
  const Eigen::VectorXd printed = per_edge(p, n, split_fold_angles_printed(n, b, theta));
  int far = 0;
  for (int i = 0; i < static_cast<int>(c.branches.size()); ++i) {
    const FlatBranch& br = c.branches[i];
    if (!br.far_side) continue;
    ++far;
    const auto eq = vertex_height_equilibrium(p, sys, topo, springs, load,
                                              sys.unknowns_from_edges(br.direction * (load.height / br.height_rate)));
    ASSERT_TRUE(eq.converged) << eq.message;
    const double gap = (eq.edge_angles - printed).lpNorm<Eigen::Infinity>();
    if (i == c.taken) {
      EXPECT_LE(gap, 1e-9);
    } else {
      EXPECT_GT(gap, 1e-2);
      EXPECT_LT(eq.edge_angles[0], 0.0);  // a half-valley turned mountain
    }
  }
  EXPECT_EQ(far, 2);
}

TEST(SplitFoldFlatCrossing, FlippedLetterStopsTheCurveAtFlat) {
  const int n = 4;
  const double b = to_radians(5.0);
  CreasePattern p = split_fold_base(n, b);
  p.assignments[2] = Assignment::Valley;  // a half-mountain
  const FlatCrossing c = waterbomb_flat_crossing(p, half_valleys(n), split_fold_motion_classes(n));
  EXPECT_EQ(c.cone_lines, 2);
  EXPECT_EQ(c.far_side_branches, 2);
  EXPECT_EQ(c.letter_keeping, 0);
  EXPECT_FALSE(c.continues);
  EXPECT_NE(c.message.find("keeps the M/V letters"), std::string::npos) << c.message;

  SplitFoldCurveOptions opt;
  opt.flipped_letters = {2};
  const SplitFoldCurve curve = split_fold_curve(n, b, to_radians(60.0), 1.0, 1.0, 9, opt);
  EXPECT_EQ(curve.stop_message, c.message);
  test::expect_only_the_near_side_checked(curve);

  for (int bad : {-1, 4 * n}) {
    opt.flipped_letters = {bad};
    try {
      split_fold_curve(n, b, to_radians(60.0), 1.0, 1.0, 9, opt);
      ADD_FAILURE() << "no InputError for crease " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), "flipped_letters");
    }
  }
}

}}  // namespace
}  // namespace rigidfold::waterbomb
