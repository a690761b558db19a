// The loaded waterbomb path through the flat state: the general model's
// far side is reached along the tangent-cone branch that keeps the M/V letters, and equals
// the closed-form symmetric curve there; the mirror branch exists and is rejected; with a
// letter flipped no branch keeps the letters and the path stops at flat.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "data/generators/waterbomb.hpp"
#include "design/waterbomb/waterbomb_curve.hpp"
#include "design/waterbomb/waterbomb_flat_crossing.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "design/waterbomb/waterbomb_loaded_path.hpp"
#include "design/waterbomb/waterbomb_force.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/vertex_height_control.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/waterbomb/stopped_curve_expectations.hpp"

namespace rigidfold::waterbomb {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::vector<int> valley_creases(const CreasePattern& p) {
  std::vector<int> v;
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] == Assignment::Valley) v.push_back(e);
  return v;
}

TEST(WaterbombFlatCrossing, ConeHasTheMirrorAndOnlyTheLetterKeepingBranchIsTaken) {
  for (int n : {4, 6}) {
    SCOPED_TRACE(n);
    generators::WaterbombParams wp;
    wp.n = n;
    const CreasePattern p = generators::waterbomb_base(wp);
    const FlatCrossing c = waterbomb_flat_crossing(p, valley_creases(p));
    EXPECT_EQ(c.kernel_dimension, 2);  // the symmetric (gamma_m, gamma_v) plane
    EXPECT_EQ(c.cone_lines, 2);        // the path's two one-sided tangents
    ASSERT_EQ(c.branches.size(), 4u);
    ASSERT_EQ(c.far_side_branches, 2);  // the letter-keeping branch and its mirror
    ASSERT_TRUE(c.continues) << c.message;
    ASSERT_GE(c.taken, 0);
    const FlatBranch& taken = c.branches[c.taken];
    EXPECT_TRUE(taken.far_side);
    EXPECT_TRUE(taken.keeps_letters);
    int rejected = 0;
    for (int i = 0; i < 4; ++i) {
      if (i == c.taken || !c.branches[i].far_side) continue;
      ++rejected;
      EXPECT_FALSE(c.branches[i].keeps_letters);
      EXPECT_GE(c.branches[i].first_wrong_crease, 0);
    }
    EXPECT_EQ(rejected, 1);
    // Independent oracle: the taken ray is the closed form's one-sided tangent at 90+ deg.
    const FoldPair d = waterbomb_fold_angle_derivatives(n, kPi / 2, +1);
    Eigen::VectorXd expected = waterbomb_edge_angles(p, d);
    expected.normalize();
    EXPECT_LE((taken.direction - expected).lpNorm<Eigen::Infinity>(), 1e-9);
    // The rejected far-side ray is the mirror of the way in (the 90- tangent, reversed and negated).
    const FoldPair din = waterbomb_fold_angle_derivatives(n, kPi / 2, -1);
    Eigen::VectorXd mirror = waterbomb_edge_angles(p, din);
    mirror.normalize();
    for (int i = 0; i < 4; ++i)
      if (i != c.taken && c.branches[i].far_side) {
        EXPECT_LE((c.branches[i].direction - mirror).lpNorm<Eigen::Infinity>(), 1e-9);
      }
  }
}

TEST(WaterbombFlatCrossing, GeneralCurvePastFlatEqualsTheClosedForm) {
  for (int n : {4, 6}) {
    SCOPED_TRACE(n);
    const double theta0 = to_radians(60.0);
    std::vector<double> thetas;
    for (double deg : {50.0, 75.0, 89.5, 90.5, 100.0, 115.0, 130.0}) thetas.push_back(to_radians(deg));
    const LoadedPath path = waterbomb_loaded_path(n, theta0, 1.0, 2.0, thetas);
    ASSERT_TRUE(path.crosses_flat);
    ASSERT_FALSE(path.stopped_at_flat) << path.stop_message;
    EXPECT_TRUE(path.flat_crossing.branches[path.flat_crossing.taken].keeps_letters);
    for (const LoadedPoint& q : path.points) {
      SCOPED_TRACE(to_degrees(q.theta));
      ASSERT_TRUE(q.converged);
      EXPECT_LE(std::fabs(q.force - q.force_closed_form), 1e-9 * std::max(1.0, std::fabs(q.force_closed_form)));
      EXPECT_LE(q.fold_angle_gap, 1e-9);
    }
    // Far side of flat the force is the return branch (negative past the jump).
    EXPECT_LT(path.points[3].force, 0.0);
    EXPECT_GT(path.points[2].force, 0.0);
  }
}

// The choice matters: leaving flat along the rejected (mirror) ray, the same loaded solve
// lands on another equilibrium, off the closed form, with its M/V letters broken.
TEST(WaterbombFlatCrossing, TheMirrorRayLeadsElsewhere) {
  const int n = 4;
  generators::WaterbombParams wp;
  wp.n = n;
  const CreasePattern p = generators::waterbomb_base(wp);
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  const WaterbombSprings ws = springs_at_rest_theta(n, to_radians(60.0), 1.0, 1.0);
  const CreaseSprings springs =
      make_crease_springs(p, stiffness_by_assignment(p, {1.0, 1.0, 0.0}), waterbomb_edge_angles(p, ws.rest));
  VertexHeightLoad load;
  load.vertex = 0;
  load.support_edges = valley_creases(p);
  const FlatCrossing c = waterbomb_flat_crossing(p, load.support_edges);
  ASSERT_TRUE(c.continues);
  const double r = std::cos(kPi / n), theta = to_radians(91.0);
  load.height = r * std::cos(theta);
  const Eigen::VectorXd closed = waterbomb_edge_angles(p, waterbomb_fold_angles(n, theta));
  for (int i = 0; i < static_cast<int>(c.branches.size()); ++i) {
    const FlatBranch& b = c.branches[i];
    if (!b.far_side) continue;
    const auto eq = vertex_height_equilibrium(p, sys, topo, springs, load,
                                              sys.unknowns_from_edges(b.direction * (load.height / b.height_rate)));
    ASSERT_TRUE(eq.converged);
    const double gap = (eq.edge_angles - closed).lpNorm<Eigen::Infinity>();
    if (i == c.taken) {
      EXPECT_LE(gap, 1e-9);
    } else {
      EXPECT_GT(gap, 1e-2);
      EXPECT_GT(eq.edge_angles[1], 0.0);  // the corner crease, M in the base, turned valley
      EXPECT_GT(std::fabs(eq.force - waterbomb_force(ws, to_radians(60.0), r, theta).force), 1e-3);
    }
  }
}

TEST(WaterbombFlatCrossing, FlippedLetterStopsTheCurveAtFlat) {
  generators::WaterbombParams wp;
  wp.n = 4;
  CreasePattern p = generators::waterbomb_base(wp);
  p.assignments[1] = Assignment::Valley;  // a corner crease, M in the base
  const FlatCrossing c = waterbomb_flat_crossing(p, {0, 2, 4, 6});
  EXPECT_EQ(c.cone_lines, 2);
  EXPECT_EQ(c.far_side_branches, 2);
  EXPECT_EQ(c.letter_keeping, 0);
  EXPECT_FALSE(c.continues);
  EXPECT_EQ(c.taken, -1);
  EXPECT_NE(c.message.find("keeps the M/V letters"), std::string::npos) << c.message;

  LoadedPathOptions opt;
  opt.flipped_letters = {1};
  const WaterbombCurve curve = waterbomb_curve(4, to_radians(60.0), 1.0, 1.0, 9, opt);
  EXPECT_EQ(curve.stop_message, c.message);
  test::expect_only_the_near_side_checked(curve);
}

}}  // namespace
}  // namespace rigidfold::waterbomb
