// Mobility from the given 3D state of sheets with holes (kernel/analysis/reference_mobility):
// the Miura tube (known: 1 DOF, folds from flat to flat-folded), prism tubes (planar n-bar
// loops: n - 3 DOF), and a given state that contradicts its own letters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "data/generators/miura_tube.hpp"
#include "data/generators/tube.hpp"
#include "kernel/analysis/reference_mobility.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {


TEST(ReferenceMobility, MiuraTubeFoldsBothWaysToItsFoldLimits) {
  generators::MiuraTubeParams tp;
  tp.rows = 5;
  tp.alpha = 50 * kPi / 180;
  tp.fold = 1.0;
  const CreasePattern p = generators::miura_tube(tp);
  const Topology t = build_topology(p);
  const ReferenceMobility m = reference_mobility(p, t);
  EXPECT_EQ(m.verdict, Verdict::kRigidlyFoldable) << m.reason;
  EXPECT_EQ(m.dof, 1);
  EXPECT_EQ(m.holes, 1);
  EXPECT_LE(m.reference_residual, 1e-13);
  EXPECT_LE(m.max_residual, 1e-11);
  ASSERT_EQ(m.branches.size(), 2u);
  for (const TracedBranch& b : m.branches) {
    EXPECT_EQ(b.stopped_by, StopReason::kFoldLimit);
    EXPECT_TRUE(b.signs_match_assignment);
    EXPECT_EQ(b.global_interference_faces.first, -1);
    std::printf("[ReferenceMobility] Miura tube branch %d: crease %d %.2f -> %.2f deg, %zu points, stopped by %s\n", b.id,
                b.driving_edge, b.driving_begin * 180 / kPi, b.driving_end * 180 / kPi, b.path.size(), b.stop_text().c_str());
  }
  // One way flattens the tube (the strips unfold: straight creases back to 0 while the bonds
  // close to 180 deg); the other flat-folds it (straight creases to 180 deg).
  double min_end = kPi, max_end = 0;
  for (const TracedBranch& b : m.branches) {
    min_end = std::min(min_end, std::abs(b.path.back()[generators::miura_tube_a_straight(tp, 0, 1)]));
    max_end = std::max(max_end, std::abs(b.path.back()[generators::miura_tube_a_straight(tp, 0, 1)]));
  }
  EXPECT_LE(min_end, 5 * kPi / 180);
  EXPECT_GE(max_end, 170 * kPi / 180);
}

TEST(ReferenceMobility, PrismTubesAreNMinusThreeBarLoops) {
  generators::TubeParams tp;
  tp.height = 1.2;
  tp.section = generators::regular_polygon(3);
  {
    const CreasePattern p = generators::prism_tube(tp);
    const ReferenceMobility m = reference_mobility(p, build_topology(p));
    EXPECT_EQ(m.dof, 0);
    EXPECT_EQ(m.verdict, Verdict::kNotRigidlyFoldable);
    EXPECT_TRUE(m.branches.empty());
  }
  tp.section = generators::regular_polygon(5, 1.0, 0.1);
  {
    const CreasePattern p = generators::prism_tube(tp);
    const ReferenceMobility m = reference_mobility(p, build_topology(p), {});
    EXPECT_EQ(m.dof, 2);
    EXPECT_EQ(m.verdict, Verdict::kRigidlyFoldable) << m.reason;
    EXPECT_LE(m.max_residual, 1e-11);
    ASSERT_EQ(m.branches.size(), 2u);
    for (const TracedBranch& b : m.branches) {
      std::printf("[ReferenceMobility] pentagon branch %d: %zu points, stopped by %s (crease %d)\n", b.id, b.path.size(),
                  b.stop_text().c_str(), b.stop_crease);
      EXPECT_GE(b.path.size(), 5u) << b.stop_text();
    }
  }
}

TEST(ReferenceMobility, GivenStateAgainstItsLettersIsNotACertificate) {
  generators::MiuraTubeParams tp;
  tp.rows = 3;
  CreasePattern p = generators::miura_tube(tp);
  const int e = generators::miura_tube_a_zigzag(tp, 1, 1);
  p.assignments[e] = p.assignments[e] == Assignment::Mountain ? Assignment::Valley : Assignment::Mountain;
  const Topology t = build_topology(p);
  const ReferenceMobility with_letters = reference_mobility(p, t);
  EXPECT_EQ(with_letters.dof, 1);
  EXPECT_NE(with_letters.verdict, Verdict::kRigidlyFoldable);
  for (const TracedBranch& b : with_letters.branches) {
    EXPECT_FALSE(b.signs_match_assignment);
    EXPECT_EQ(b.first_wrong_crease, e);
  }
  ReferenceMobilityOptions ignore;
  ignore.use_assignment = false;
  EXPECT_EQ(reference_mobility(p, t, ignore).verdict, Verdict::kRigidlyFoldable);
}

}}  // namespace
}  // namespace rigidfold
