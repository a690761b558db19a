// The mu = 1/2 waterbomb pattern, shown to lose mobility with the locking
// named: the traditional waterbomb pattern (data/generators/traditional_waterbomb.hpp, seed
// 003 §4.4.2: D and W vertices) as a network of thick Bricard loops
// (kernel/thick/waterbomb_network.hpp), checked with the general SE(3) closure
// (ThickClosureSystem) and kernel/thick/thick_network_mobility.hpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>
#include <numbers>

#include "tests/closure/closure_test_utils.hpp"
#include "data/generators/traditional_waterbomb.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/thick_vertex_models.hpp"
#include "kernel/thick/vertex_height_steps.hpp"
#include "kernel/thick/thick_closure_system.hpp"
#include "kernel/thick/thick_network_mobility.hpp"
#include "kernel/thick/waterbomb_network.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

struct Pattern {
  CreasePattern flat = generators::traditional_waterbomb({3, 3});
  Topology topology = build_topology(flat);
  WaterbombNetwork network(double mu) const { return waterbomb_network(flat, topology, mu, 0.1, 0.1, 0.05); }
  int count(const WaterbombNetwork& net, WaterbombVertexKind kind) const {
    int n = 0;
    for (WaterbombVertexKind k : net.kind) n += k == kind;
    return n;
  }
};

// Height steps round each vertex from its crease 0 (model order): the diamond's
// (t1, -t2, -(t1+t2), t1+t2, t2, -t1) (tests/thick/vertex_heights_test.cpp) and the
// waterbomb's (1+mu, 1, -mu, mu, -1, -(1+mu)) t (heights 0, 2t, 3t, 2t, 3t, 2t there at mu = 1)
// negated for its mirror image. Each closes alone on its zero-thickness motion (checked).
std::vector<double> d_steps(double t1, double t2) { return {t1, -t2, -(t1 + t2), t1 + t2, t2, -t1}; }
std::vector<double> w_steps(double mu, double t) { return {-(1 + mu) * t, -t, mu * t, -mu * t, t, (1 + mu) * t}; }

double single_vertex_residual(const std::vector<double>& sectors, const std::vector<double>& steps,
                              const std::function<std::vector<double>(double)>& zero) {
  const CreasePattern flat = testing::single_vertex_from_sectors(sectors);
  const Topology topology = build_topology(flat);
  std::vector<double> h(flat.num_edges(), 0.0);
  for (int i = 0; i + 1 < 6; ++i) h[i + 1] = h[i] + steps[i];
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(flat, topology, h);
  const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
  double worst = 0.0;
  for (int k = 1; k < 20; ++k) {
    const std::vector<double> rho = zero(kPi * k / 20);
    Eigen::VectorXd fold = Eigen::VectorXd::Zero(flat.num_edges());
    for (int i = 0; i < 6; ++i) fold[i] = rho[i];
    worst = std::max(worst, system.residual(system.unknowns_from_edges(sheet.sheet_edge_angles(fold))).cwiseAbs().maxCoeff());
  }
  return worst;
}

// Why the pattern is analysed as a network of loops: the hinge heights of these models do
// not agree across the traditional waterbomb pattern for any D thickness, even at mu = 1.
// Every D's two midline creases are crease 0 of a W, and all W profiles are tied together by
// the W-W creases, so both midlines of a D would need one height, which its Bricard profile
// (0 and -2 t2) does not allow.
TEST(ThickWaterbombPattern, HingeHeightsOfTheModelsDisagreeAcrossThePattern) {
  const Pattern p;
  const double q = 0.25 * kPi;
  EXPECT_LE(single_vertex_residual({q, 2 * q, q, q, 2 * q, q}, d_steps(0.1, 0.05),
                                   [&](double r) { return diamond_zero_thickness(q, r); }),
            1e-12);
  EXPECT_LE(single_vertex_residual({2 * q, q, q, q, q, 2 * q}, w_steps(1.0, 0.1),
                                    [](double r) {
                                      std::vector<double> rho = waterbomb_zero_thickness(-r);
                                      for (double& x : rho) x = -x;
                                      return rho;
                                    }),
            1e-12);
  for (double mu : {1.0, 0.5})
    for (const auto& [t1, t2] : {std::pair{0.1, 0.05}, std::pair{0.2, 0.1}, std::pair{0.05, 0.3}}) {
      const WaterbombNetwork net = waterbomb_network(p.flat, p.topology, mu, 0.1, t1, t2);
      std::vector<std::vector<double>> steps(p.flat.num_vertices());
      for (std::size_t l = 0; l < net.vertex_of_loop.size(); ++l) {
        const int v = net.vertex_of_loop[l];
        const Fan& fan = p.topology.stars[v].fans[0];
        const int k0 = static_cast<int>(std::find(fan.edges.begin(), fan.edges.end(), net.creases[l][0]) - fan.edges.begin());
        const std::vector<double> model = net.kind[l] == WaterbombVertexKind::kD ? d_steps(t1, t2) : w_steps(mu, 0.1);
        steps[v].assign(6, 0.0);
        for (int i = 0; i < 6; ++i) steps[v][(k0 + i) % 6] = model[i];
      }
      EXPECT_THROW(hinge_heights_from_steps(p.flat, p.topology, steps), HingeHeightConflict) << "mu " << mu << " t1 " << t1 << " t2 " << t2;
    }
}

TEST(ThickWaterbombPattern, ZeroThicknessUniformMotionClosesTheGeneralSolver) {
  const Pattern p;
  const WaterbombNetwork net = p.network(1.0);
  EXPECT_EQ(p.count(net, WaterbombVertexKind::kD), 9);
  EXPECT_GE(p.count(net, WaterbombVertexKind::kW), 4);
  const ClosureSystem zero(p.flat, p.topology);
  double worst = 0.0;
  for (int k = 1; k < 20; ++k) {
    const Eigen::VectorXd state = waterbomb_network_uniform_state(p.flat, net, kPi * k / 20);
    worst = std::max(worst, zero.residual(zero.unknowns_from_edges(state)).cwiseAbs().maxCoeff());
    for (int e = 0; e < p.flat.num_edges(); ++e) {  // the generator's letters are the motion's signs
      if (state[e] == 0.0) continue;
      EXPECT_EQ(state[e] > 0, p.flat.assignments[e] == Assignment::Valley) << "edge " << e;
    }
  }
  EXPECT_LE(worst, 1e-13);
  std::printf("traditional waterbomb 3x3: %d D + %d W vertices; uniform zero-thickness motion closes the core to %.1e\n",
              p.count(net, WaterbombVertexKind::kD), p.count(net, WaterbombVertexKind::kW), worst);
}

// Drives the midline crease of the first D loop from flat to rho_end in steps, each step a
// least-squares closure (thick_network_hold) from the previous state. The flat state is a
// bifurcation (seed §4.4.2: creases 2 and 6 of W are collinear there), so the first step
// starts on the zero-thickness branch: its uniform state at the first driver angle.
struct Trace {
  double worst_residual = 0.0;      // largest ||r||_inf over the steps
  double least_residual = 1e300;    // smallest ||r||_inf over the steps
  double off_uniform = 0.0;         // largest |rho - rho_uniform| over the steps
  bool all_stationary = true;
  std::vector<int> open_loops;      // union over the steps
};

Trace trace(const Pattern& p, const WaterbombNetwork& net, double rho_end, int steps) {
  Trace out;
  const int driver = net.creases[0][0];
  Eigen::VectorXd state = waterbomb_network_uniform_state(p.flat, net, rho_end / steps);
  for (int k = 1; k <= steps; ++k) {
    const double rho = rho_end * k / steps;
    const ThickHoldResult h = thick_network_hold(net.thick, driver, rho, state, 1e-10);
    state = h.creases;
    out.worst_residual = std::max(out.worst_residual, h.residual);
    out.least_residual = std::min(out.least_residual, h.residual);
    out.all_stationary = out.all_stationary && (h.stationary || h.residual <= 1e-13);
    const Eigen::VectorXd uniform = waterbomb_network_uniform_state(p.flat, net, rho);
    for (Eigen::Index e = 0; e < state.size(); ++e)
      out.off_uniform = std::max(out.off_uniform, std::abs(std::remainder(state[e] - uniform[e], 2 * kPi)));
    for (int l : h.open_loops)
      if (std::find(out.open_loops.begin(), out.open_loops.end(), l) == out.open_loops.end()) out.open_loops.push_back(l);
  }
  return out;
}

// Largest residual of each loop's rows over uniform zero-thickness states.
std::vector<double> off_motion(const Pattern& p, const WaterbombNetwork& net) {
  const ThickClosureSystem system(net.thick);
  std::vector<double> worst(net.thick.loops.size(), 0.0);
  for (int k = 1; k < 20; ++k) {
    const Eigen::VectorXd r = system.residual(system.unknowns_from_creases(waterbomb_network_uniform_state(p.flat, net, kPi * k / 20)));
    for (std::size_t l = 0; l < worst.size(); ++l) worst[l] = std::max(worst[l], r.segment(6 * static_cast<Eigen::Index>(l), 6).cwiseAbs().maxCoeff());
  }
  return worst;
}

// mu = 1 (4-60): every thick loop closes on the zero-thickness motion, the general solver
// traces the network from flat with it, and at folded states the network has one DOF with a
// clear gap (each loop alone one DOF: Bricard).
TEST(ThickWaterbombPattern, MuOneFollowsTheZeroThicknessMotionWithOneDof) {
  const Pattern p;
  const WaterbombNetwork net = p.network(1.0);
  double worst = 0.0;
  for (double r : off_motion(p, net)) worst = std::max(worst, r);
  EXPECT_LE(worst, 1e-13);
  const Trace t = trace(p, net, 2.5, 50);
  EXPECT_LE(t.worst_residual, 1e-12);
  EXPECT_LE(t.off_uniform, 1e-10);
  EXPECT_TRUE(t.open_loops.empty());
  for (double rho : {0.3, 1.0, 2.0, 2.8}) {
    const ThickNetworkMobility m = thick_network_mobility(net.thick, waterbomb_network_uniform_state(p.flat, net, rho), 1e-12);
    EXPECT_EQ(m.dof, 1) << "rho = " << rho;
    EXPECT_GT(m.rank.sigma_kept, 1e3 * m.rank.threshold) << "rho = " << rho;
    EXPECT_TRUE(m.locked_loops.empty());
    for (const ThickLoopMobility& l : m.loops) EXPECT_EQ(l.dof_alone, 1) << net.thick.loops[l.loop].name;
  }
  const ThickNetworkMobility m = thick_network_mobility(net.thick, waterbomb_network_uniform_state(p.flat, net, 1.0), 1e-12);
  std::printf("thick waterbomb pattern mu = 1: loops on the zero-thickness motion to %.1e; traced to rho = 2.5 (residual <= %.1e, "
              "off the uniform motion %.1e); DOF %d of %d creases (sigma_kept %.2e, cut %.1e)\n",
              worst, t.worst_residual, t.off_uniform, m.dof, m.free_creases, m.rank.sigma_kept, m.rank.threshold);
}

// mu = 1/2: every D loop still closes on the zero-thickness motion, every W loop leaves it
// (the W's shared creases with its D's disagree: seed §4.4.2), and the network cannot be
// driven off flat: the least-squares closure with the driver held stays open (stationary,
// residual far above the tolerance) at every step, where mu = 1 closes to round-off. The
// flat state itself closes; its first-order DOF (5, as for mu = 1: the flat state is a
// bifurcation of every Bricard loop, two DOF alone) does not decide mobility there.
TEST(ThickWaterbombPattern, MuOneHalfLosesMobilityAndTheWVerticesAreNamed) {
  const Pattern p;
  const WaterbombNetwork net = p.network(0.5);
  const std::vector<double> off = off_motion(p, net);
  std::vector<int> named, w_vertices;
  for (std::size_t l = 0; l < off.size(); ++l) {
    if (off[l] > 1e-10) named.push_back(net.vertex_of_loop[l]);
    if (net.kind[l] == WaterbombVertexKind::kW) w_vertices.push_back(net.vertex_of_loop[l]);
    if (net.kind[l] == WaterbombVertexKind::kD) {
      EXPECT_LE(off[l], 1e-13) << net.thick.loops[l].name;
    } else {
      EXPECT_GT(off[l], 1e-3) << net.thick.loops[l].name;
    }
  }
  EXPECT_EQ(named, w_vertices);

  const ThickNetworkMobility flat = thick_network_mobility(net.thick, Eigen::VectorXd::Zero(p.flat.num_edges()), 1e-12);
  const ThickNetworkMobility flat_mu1 = thick_network_mobility(p.network(1.0).thick, Eigen::VectorXd::Zero(p.flat.num_edges()), 1e-12);
  EXPECT_EQ(flat.dof, flat_mu1.dof);  // first order cannot tell them apart

  // From perturbed starts (every crease moved by up to 0.15 rad) the same driver angle is
  // reached with closure at mu = 1 and stays open at mu = 1/2.
  const WaterbombNetwork net1 = p.network(1.0);
  double open_least = 1e300, closed_worst = 0.0;
  for (double rho : {0.3, 0.8})
    for (int seed = 1; seed <= 4; ++seed) {
      Eigen::VectorXd start = waterbomb_network_uniform_state(p.flat, net, rho);
      for (Eigen::Index e = 0; e < start.size(); ++e)
        if (start[e] != 0.0) start[e] += 0.15 * std::sin(12.9898 * (e + 1) * seed + 78.233 * seed);
      const int driver = net.creases[0][0];
      open_least = std::min(open_least, thick_network_hold(net.thick, driver, rho, start).residual);
      closed_worst = std::max(closed_worst, thick_network_hold(net1.thick, driver, rho, start).residual);
    }
  EXPECT_GT(open_least, 1e-5);
  EXPECT_LE(closed_worst, 1e-12);
  std::printf("  from 8 perturbed starts: mu = 1/2 least residual %.2e, mu = 1 closes to %.1e\n", open_least, closed_worst);

  const Trace t = trace(p, net, 1.0, 20);
  EXPECT_TRUE(t.all_stationary);
  EXPECT_GT(t.least_residual, 1e-5);
  EXPECT_FALSE(t.open_loops.empty());
  std::printf("thick waterbomb pattern mu = 1/2: W loops off the zero-thickness motion by >= %.2e, D loops <= %.1e; named:",
              [&] { double m = 1e300; for (std::size_t l = 0; l < off.size(); ++l) if (net.kind[l] == WaterbombVertexKind::kW) m = std::min(m, off[l]); return m; }(),
              [&] { double m = 0; for (std::size_t l = 0; l < off.size(); ++l) if (net.kind[l] == WaterbombVertexKind::kD) m = std::max(m, off[l]); return m; }());
  for (int v : named) std::printf(" W%d", v);
  std::printf("\n  driven from flat to 1 rad in 20 steps: least-squares closure stays open, residual %.2e .. %.2e (stationary: %s); "
              "flat first-order DOF %d (mu = 1: %d)\n",
              t.least_residual, t.worst_residual, t.all_stationary ? "yes" : "no", flat.dof, flat_mu1.dof);
}

}}  // namespace
}  // namespace rigidfold
