// nearest_closed_state (design/target/nearest_state.hpp): from a rigidly folded square twist
// and a Miura-ori, target angles with noise added are brought back to a closed state within
// the noise (the true state closes, so the nearest one is no further from the target), with
// the closure residual at 1e-12; held creases keep their target angle exactly.
#include <gtest/gtest.h>

#include <random>

#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "design/target/nearest_state.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct Case {
  CreasePattern pattern;
  Topology topology;
  Eigen::VectorXd state;  // a closed state (per edge, radians)
};

Case folded(CreasePattern p, double t) {
  Case c{p, build_topology(p), {}};
  const FoldabilityVerdict v = verdict_with_assignment(c.pattern, c.topology);
  EXPECT_EQ(v.verdict, Verdict::kRigidlyFoldable);
  c.state = v.family->angles(t);
  return c;
}

Eigen::VectorXd with_noise(const Case& c, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  Eigen::VectorXd target = c.state;
  for (int e = 0; e < c.pattern.num_edges(); ++e)
    if (c.topology.edge_is_hinge[e]) target[e] += u(rng);
  return target;
}

TEST(NearestState, NoisyTargetsComeBackToAClosedStateWithinTheNoise) {
  generators::MiuraParams miura;
  miura.rows = miura.cols = 5;
  for (const Case& c : {folded(generators::square_twist({}, generators::SquareTwistType::Type3), 0.6), folded(generators::miura_ori(miura), 0.8)}) {
    const Eigen::VectorXd target = with_noise(c, 0.02, 4);
    const NearestState n = nearest_closed_state(c.pattern, c.topology, target);
    ASSERT_TRUE(n.converged) << n.message;
    EXPECT_GT(n.target_residual, 1e-3);
    EXPECT_LE(n.residual, 1e-12);
    const ClosureSystem system(c.pattern, c.topology);
    EXPECT_LE(system.residual(system.unknowns_from_edges(n.angles)).lpNorm<Eigen::Infinity>(), 1e-12);
    // The true state closes: the nearest one is no further from the target, and so lies within
    // twice the noise of the true state.
    EXPECT_LE((n.angles - target).norm(), (c.state - target).norm() * (1 + 1e-9));
    EXPECT_LE((n.angles - c.state).norm(), 2 * (c.state - target).norm());
    EXPECT_LE(n.stationarity, 1e-6);
  }
}

TEST(NearestState, HeldCreasesKeepTheirTargetAngle) {
  const Case c = folded(generators::square_twist({}, generators::SquareTwistType::Type3), 0.6);
  const Eigen::VectorXd target = with_noise(c, 0.02, 9);
  NearestStateOptions o;
  o.held_edges = {0};
  const NearestState n = nearest_closed_state(c.pattern, c.topology, target, o);
  ASSERT_TRUE(n.converged) << n.message;
  EXPECT_EQ(n.angles[0], target[0]);
  EXPECT_LE(n.residual, 1e-12);
  o.held_edges = {c.pattern.num_edges()};
  EXPECT_THROW(nearest_closed_state(c.pattern, c.topology, target, o), InputError);
}

}}  // namespace
}  // namespace rigidfold
