// kernel/network: the closure system of a linkage network (exact Jacobian, Newton, DOF),
// checked against the single-4R closed form, and the seed-003 networks of data/network.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "kernel/math/angle_units.hpp"
#include "kernel/network/network_closure.hpp"
#include "kernel/network/network_json.hpp"
#include "kernel/network/network_trace.hpp"
#include "kernel/vertex/spherical_4r.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double pi = std::numbers::pi;

NetworkSpec load(const std::string& name) {
  return read_network_json(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/network/" + name);
}

double angle_gap(double a, double b) { return std::fabs(std::remainder(a - b, 2 * pi)); }

// Two linkages sharing joints with sign -1 and an offset: the Jacobian is exact.
TEST(NetworkClosure, JacobianMatchesFiniteDifferences) {
  LinkageNetwork net;
  net.joint_names = {"p", "q", "r", "s", "u", "v", "w"};
  net.linkages.push_back({"A", {0.4, 1.1, 2.0, 1.3}, {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}}});
  net.linkages.push_back({"B", {0.7, -0.5, 2.6, 1.9, 0.8}, {{1, -1, 0.3}, {4, 1, 0}, {5, 1, -1.0}, {6, -1, 0}, {3, 1, 0}}});
  const NetworkClosure system(net);
  Eigen::VectorXd q(7);
  q << 0.3, -0.7, 1.2, 0.5, -1.4, 0.9, 0.2;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(q, r, J);
  ASSERT_EQ(J.rows(), 6);
  ASSERT_EQ(J.cols(), 7);
  const Eigen::MatrixXd Jd(J);
  double worst = 0.0;
  for (int j = 0; j < 7; ++j) {
    const double h = 1e-6;
    Eigen::VectorXd qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    const Eigen::VectorXd fd = (system.residual(qp) - system.residual(qm)) / (2 * h);
    worst = std::max(worst, (fd - Jd.col(j)).lpNorm<Eigen::Infinity>());
  }
  EXPECT_LT(worst, 1e-8);
  // Joint u (index 4) is in B only: its column is zero in A's rows.
  EXPECT_EQ(Jd.block(0, 4, 3, 1).norm(), 0.0);
  EXPECT_GT(Jd.block(3, 4, 3, 1).norm(), 0.1);
}

// Fig 2-1 (non-developable, sum 400 deg): the general solver reproduces the closed form's
// two branches, converging quadratically, with DOF 1 and DOF 0 with the input held.
TEST(NetworkClosure, SingleLinkageAgreesWithClosedForm) {
  const NetworkSpec spec = load("fig2-1_base.json");
  const NetworkClosure system(spec.network);
  const auto& tw = spec.network.linkages[0].twists;
  const S4RSectors sectors{tw[0], tw[1], tw[2], tw[3]};
  for (double deg : {100.0, 130.0, 160.0, -120.0}) {
    const double x = to_radians(deg);
    const S4RBranches cf = s4r_branches_checked(sectors, x);
    ASSERT_EQ(cf.branches.size(), 2u) << deg;
    for (const S4RFoldAngles& b : cf.branches) {
      Eigen::VectorXd q0(4);
      q0 << x, b[1] + 0.03, b[2] - 0.03, b[3] + 0.02;
      NetworkNewtonOptions opt;
      opt.held = {0};
      const NetworkNewtonResult res = network_project(system, q0, opt);
      ASSERT_TRUE(res.converged) << deg;
      EXPECT_LE(res.iterations, 6);
      for (int k = 0; k < 4; ++k) EXPECT_LT(angle_gap(res.q[k], b[k]), 1e-10) << deg << " joint " << k;
      const RankResult mob = network_mobility(system, res.q);
      EXPECT_EQ(mob.dof, 1);
      EXPECT_GT(mob.sigma_kept, 1e-3 * mob.sigma_max);
      EXPECT_LT(mob.sigma_dropped, 1e-12 * mob.sigma_max);
      EXPECT_EQ(network_mobility(system, res.q, {0}).dof, 0);
    }
  }
}

// Fig 2-1's variant (2-6): driven with theta1' = theta1, it closes at
// (theta1, theta2 - pi, -theta3, theta4 - pi) (the digest's corrected (2-9)).
TEST(NetworkClosure, Fig21VariantTransmission) {
  const NetworkSpec base = load("fig2-1_base.json");
  const NetworkSpec var = load("fig2-1_variant.json");
  const NetworkClosure sb(base.network), sv(var.network);
  const NetworkConfiguration cb = find_network_configuration(sb, 0, to_radians(120), base.guess);
  ASSERT_TRUE(cb.found);
  Eigen::VectorXd expect(4);
  expect << cb.q[0], cb.q[1] - pi, -cb.q[2], cb.q[3] - pi;
  EXPECT_LT(sv.residual(expect).lpNorm<Eigen::Infinity>(), 1e-12);
  // Independently: the variant's own solve from a guess 0.05 rad off lands there.
  NetworkNewtonOptions opt;
  opt.held = {0};
  const NetworkNewtonResult res = network_project(sv, expect + Eigen::Vector4d(0, 0.05, -0.05, 0.05), opt);
  ASSERT_TRUE(res.converged);
  for (int k = 0; k < 4; ++k) EXPECT_LT(angle_gap(res.q[k], expect[k]), 1e-10) << k;
}

// Each linkage of a closed network configuration is one of its closed-form branches.
void expect_linkages_match_closed_form(const NetworkClosure& system, const Eigen::VectorXd& q) {
  const std::vector<double> qv(q.data(), q.data() + q.size());
  for (const NetworkLinkage& l : system.network().linkages) {
    ASSERT_EQ(l.twists.size(), 4u);
    const std::vector<double> t = linkage_joint_angles(l, qv);
    const S4RBranches cf = s4r_branches_checked({l.twists[0], l.twists[1], l.twists[2], l.twists[3]}, t[0]);
    double best = INFINITY;
    for (const S4RFoldAngles& b : cf.branches) {
      double gap = 0.0;
      for (int k = 0; k < 4; ++k) gap = std::max(gap, angle_gap(b[k], t[k]));
      best = std::min(best, gap);
    }
    EXPECT_LT(best, 1e-10) << l.name;
  }
}

class NetworkMobile : public ::testing::TestWithParam<const char*> {};

// Fig 2-7, eq (2-34) and the Table A4 rows R3R13R12, R4R11R5, R4R10R16, R4R9R12: closed at
// the input's start with DOF 1 (a clear gap), each linkage on a closed-form branch, and
// the trace over the file's input range keeps DOF 1 and closes to 1e-12 at every step.
TEST_P(NetworkMobile, ClosesWithOneDof) {
  const NetworkSpec spec = load(GetParam());
  const NetworkClosure system(spec.network);
  const NetworkConfiguration c = find_network_configuration(system, spec.input, spec.input_start, spec.guess);
  ASSERT_TRUE(c.found) << c.residual;
  EXPECT_LE(c.residual, 1e-12);
  const RankResult mob = network_mobility(system, c.q);
  EXPECT_EQ(mob.dof, 1);
  EXPECT_GT(mob.sigma_kept, 1e-3 * mob.sigma_max);
  EXPECT_LT(mob.sigma_dropped, 1e-12 * mob.sigma_max);
  EXPECT_EQ(network_mobility(system, c.q, {spec.input}).dof, 0);
  expect_linkages_match_closed_form(system, c.q);
  ASSERT_TRUE(spec.has_end);
  const NetworkTrace tr = trace_network(system, c.q, spec.input, spec.input_end, 12);
  ASSERT_TRUE(tr.complete) << tr.stop_reason;
  ASSERT_EQ(tr.points.size(), 13u);
  for (const NetworkTracePoint& p : tr.points) {
    EXPECT_LE(p.residual, 1e-12);
    EXPECT_EQ(p.dof, 1);
    expect_linkages_match_closed_form(system, p.q);
  }
  EXPECT_LT(angle_gap(tr.points.back().input, spec.input_end), 1e-15);
}

INSTANTIATE_TEST_SUITE_P(Seed003, NetworkMobile,
                         ::testing::Values("fig2-7_rotation.json", "fig2-5_twofold.json", "eq2-34.json", "a4_R3R13R12.json", "a4_R4R11R5.json",
                                           "a4_R4R10R16.json", "a4_R4R9R12.json"));

// The rotation case's transmission closes for identical linkages (2-26): driving a1 and
// following the closed forms A: a1 -> a2, B: a2 -> b3, C: b3 -> c4, D: c4 -> a1 returns a1
// on the traced branch, i.e. the network solver's outputs are the closed-form chain's.
TEST(NetworkClosure, Fig27TraceIsTheClosedFormChain) {
  const NetworkSpec spec = load("fig2-7_rotation.json");
  const NetworkClosure system(spec.network);
  const NetworkConfiguration c = find_network_configuration(system, spec.input, spec.input_start, spec.guess);
  ASSERT_TRUE(c.found);
  const NetworkTrace tr = trace_network(system, c.q, spec.input, spec.input_end, 6);
  ASSERT_TRUE(tr.complete);
  const LinkageNetwork& net = system.network();
  const int a1 = net.joint_index("a1"), a2 = net.joint_index("a2"), b3 = net.joint_index("b3"), c4 = net.joint_index("c4");
  for (const NetworkTracePoint& p : tr.points) {
    const auto& A = net.linkages[0].twists;
    const auto& B = net.linkages[1].twists;
    const auto& C = net.linkages[2].twists;
    const auto& D = net.linkages[3].twists;
    EXPECT_LT(std::fabs(s4r_pair_residual({A[0], A[1], A[2], A[3]}, 0, p.q[a1], p.q[a2])), 1e-12);
    EXPECT_LT(std::fabs(s4r_pair_residual({B[0], B[1], B[2], B[3]}, 1, p.q[a2], p.q[b3])), 1e-12);
    EXPECT_LT(std::fabs(s4r_pair_residual({C[0], C[1], C[2], C[3]}, 2, p.q[b3], p.q[c4])), 1e-12);
    EXPECT_LT(std::fabs(s4r_pair_residual({D[0], D[1], D[2], D[3]}, 3, p.q[c4], p.q[a1])), 1e-12);
  }
}

// eq (2-34) with vertex A perturbed (91, 70, 60, 139 deg; still flat): not mobile, with the
// evidence of docs/DESIGN.md's verdict classes. At each input a1 the least residual the
// Gauss-Newton search reaches from the unperturbed network's closed configuration there is
// far above the closure tolerance and grows with the fold amplitude, while the unperturbed
// network closes to 1e-12 at the same inputs.
TEST(NetworkClosure, PerturbedEq234IsRigid) {
  const NetworkSpec good = load("eq2-34.json");
  const NetworkSpec bad = load("eq2-34_perturbed.json");
  const NetworkClosure sg(good.network), sb(bad.network);
  const NetworkConfiguration cg = find_network_configuration(sg, good.input, good.input_start, good.guess);
  ASSERT_TRUE(cg.found);
  const NetworkTrace tr = trace_network(sg, cg.q, good.input, to_radians(10), 4);  // 30 -> 10 deg
  const NetworkTrace up = trace_network(sg, cg.q, good.input, to_radians(70), 4);  // 30 -> 70 deg
  ASSERT_TRUE(tr.complete && up.complete);
  std::vector<NetworkTracePoint> pts(tr.points.rbegin(), tr.points.rend());
  pts.insert(pts.end(), up.points.begin() + 1, up.points.end());
  double previous = 0.0;
  for (const NetworkTracePoint& p : pts) {
    EXPECT_LE(sg.residual(p.q).lpNorm<Eigen::Infinity>(), 1e-12);
    NetworkNewtonOptions opt;
    opt.held = {good.input};
    opt.max_iterations = 60;
    const NetworkNewtonResult res = network_project(sb, p.q, opt);
    EXPECT_FALSE(res.converged);
    double least = INFINITY;
    for (double r : res.residual_history) least = std::min(least, r);
    EXPECT_GT(least, 1e-5) << to_degrees(p.input);
    EXPECT_GT(least, previous) << to_degrees(p.input);  // grows with the amplitude
    previous = least;
  }
  // The CLI's search at the file's input (random starts too) finds nothing either.
  const NetworkConfiguration at_input = find_network_configuration(sb, bad.input, bad.input_start, bad.guess);
  EXPECT_FALSE(at_input.found);
  EXPECT_GT(at_input.residual, 1e-5);
}

// The Table A4 conditions are the Kokotsakis ones: the central panel is flat, (2-32)
// alpha12^a + alpha23^b + alpha34^c + alpha41^d = 2 pi, in each data file. The network's
// mobility does not need them: the same variants on a base that breaks the row's condition
// still close with DOF 1, while (2-32) fails.
TEST(NetworkClosure, TableA4ConditionsAreTheFlatPanel) {
  for (const char* f : {"a4_R3R13R12.json", "a4_R4R11R5.json", "a4_R4R10R16.json", "a4_R4R9R12.json", "eq2-34.json"}) {
    const NetworkSpec s = load(f);
    const auto& L = s.network.linkages;
    const double panel = L[0].twists[0] + L[1].twists[1] + L[2].twists[2] + L[3].twists[3];
    EXPECT_NEAR(panel, 2 * pi, 1e-12) << f;
  }
  // R4R11R5 on alpha = (50, 70, 135, 110) deg: alpha12 + alpha34 != pi.
  NetworkSpec s = load("a4_R4R11R5.json");
  const double a12 = to_radians(50), a23 = to_radians(70), a34 = to_radians(135), a41 = to_radians(110);
  s.network.linkages[0].twists = {pi - a12, pi - a23, pi - a34, pi - a41};
  s.network.linkages[1].twists = {a12, a23, pi - a34, pi - a41};
  s.network.linkages[2].twists = {a12, a23, pi - a34, pi - a41};
  s.network.linkages[3].twists = {a12, a23, a34, a41};
  const NetworkClosure system(s.network);
  const NetworkConfiguration c = find_network_configuration(system, s.input, to_radians(60), s.guess);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(network_mobility(system, c.q).dof, 1);
  const auto& L = s.network.linkages;
  EXPECT_GT(std::fabs(L[0].twists[0] + L[1].twists[1] + L[2].twists[2] + L[3].twists[3] - 2 * pi), 0.05);
}

// The two-fold-symmetric case (Path1, (2-15)) of identical linkages: by the central symmetry
// (2-10) the transmission a1 -> a2 -> b1 -> c2 -> d1 -> a1 closes with b1 = -a1, c2 = a2 on
// the traced branch, so it is mobile for any twists (no extra condition for identical ones).
TEST(NetworkClosure, TwofoldSymmetricFollowsCentralSymmetry) {
  const NetworkSpec spec = load("fig2-5_twofold.json");
  const NetworkClosure system(spec.network);
  const NetworkConfiguration c = find_network_configuration(system, spec.input, spec.input_start, spec.guess);
  ASSERT_TRUE(c.found);
  const NetworkTrace tr = trace_network(system, c.q, spec.input, spec.input_end, 6);
  ASSERT_TRUE(tr.complete);
  const LinkageNetwork& net = system.network();
  const int a1 = net.joint_index("a1"), a2 = net.joint_index("a2"), b1 = net.joint_index("b1"), c2 = net.joint_index("c2");
  for (const NetworkTracePoint& p : tr.points) {
    EXPECT_LT(angle_gap(p.q[b1], -p.q[a1]), 1e-10);
    EXPECT_LT(angle_gap(p.q[c2], p.q[a2]), 1e-10);
  }
}

// A flat degree-3 "vertex" (120, 120, 120 deg) closes at the flat state with first-order
// DOF 1 (its three axes lie in one plane), but it is rigid: the input does not move. The
// Fig 2-7 network moves both ways from its start.
TEST(NetworkClosure, ProbeSeparatesSingularFromMobile) {
  LinkageNetwork tri;
  tri.joint_names = {"a", "b", "c"};
  const double t = 2 * pi / 3;
  tri.linkages.push_back({"T", {t, t, t}, {{0, 1, 0}, {1, 1, 0}, {2, 1, 0}}});
  const NetworkClosure st(tri);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3);
  EXPECT_LE(st.residual(zero).lpNorm<Eigen::Infinity>(), 1e-15);
  EXPECT_EQ(network_mobility(st, zero).dof, 1);
  EXPECT_EQ(probe_input_motion(st, zero, 0), 0);

  const NetworkSpec spec = load("fig2-7_rotation.json");
  const NetworkClosure system(spec.network);
  const NetworkConfiguration c = find_network_configuration(system, spec.input, spec.input_start, spec.guess);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(probe_input_motion(system, c.q, spec.input), 2);
}

}}  // namespace
}  // namespace rigidfold
