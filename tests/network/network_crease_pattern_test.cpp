// network_crease_pattern (kernel/network/network_crease_pattern.hpp) and `rigidfold network
// --out`: the eq 2-34 assembly (seed 003 Fig 2-12) laid out as a crease pattern whose vertex
// sectors, read back from the coordinates, are the linkages' twists, whose creases fold by
// rho = -theta of the network's configuration (the pattern's own loops close there with a
// 1-D null space), and which the kernel's front door finds rigidly foldable with 1 DOF.
// Networks that break (2-33), (2-32), the four-linkage cycle or the one-angle-per-crease rule
// are refused naming the place; the command then writes nothing and exits 2.
#include <gtest/gtest.h>

#include <unistd.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/network/network_closure.hpp"
#include "kernel/network/network_crease_pattern.hpp"
#include "kernel/network/network_json.hpp"
#include "kernel/network/network_trace.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

std::string data(const std::string& name) { return std::string(RIGIDFOLD_SOURCE_DIR) + "/data/network/" + name; }

struct Solved {
  NetworkSpec spec;
  Eigen::VectorXd q;
};

Solved solve(const std::string& name) {
  Solved s{read_network_json(data(name)), {}};
  const NetworkClosure system(s.spec.network);
  const NetworkConfiguration c = find_network_configuration(system, s.spec.input, s.spec.input_start, s.spec.guess);
  EXPECT_TRUE(c.found) << name;
  s.q = c.q;
  return s;
}

double angle_diff(double a, double b) { return std::fabs(std::remainder(a - b, 2 * kPi)); }

void check_pattern(const std::string& name, bool expect_foldable) {
  const Solved s = solve(name);
  const LinkageNetwork& net = s.spec.network;
  const NetworkCreasePattern cp = network_crease_pattern(net, s.q, name);
  EXPECT_LE(cp.residual, 1e-12) << name;
  EXPECT_NEAR(cp.central_angle_sum, 2 * kPi, 1e-9) << name;
  const CreasePattern& p = cp.pattern;
  ASSERT_EQ(p.num_vertices(), 12) << name;
  const Topology topo = build_topology(p);
  // Every interior vertex: its creases, counter-clockwise from the coordinates, are the
  // linkage's joints in loop order (or reversed, as reported) with the twists as sectors.
  for (int v = 0; v < 4; ++v) {
    ASSERT_TRUE(topo.stars[v].interior()) << name << " vertex " << v;
    const Fan& fan = topo.stars[v].fans[0];
    ASSERT_EQ(fan.edges.size(), 4u);
    const auto it = std::find_if(net.linkages.begin(), net.linkages.end(),
                                 [&](const NetworkLinkage& l) { return l.name == cp.vertex_linkage[v]; });
    ASSERT_NE(it, net.linkages.end());
    const int k = static_cast<int>(it - net.linkages.begin());
    const NetworkLinkage& l = *it;
    const int o = cp.orientation[k];
    // The slot of the first fan crease.
    int first = -1;
    for (int i = 0; i < 4; ++i)
      if (l.joints[i].joint == cp.edge_joint[fan.edges[0]]) first = i;
    ASSERT_GE(first, 0) << name;
    const std::vector<double> t = linkage_joint_angles(l, std::vector<double>(s.q.data(), s.q.data() + s.q.size()));
    for (int r = 0; r < 4; ++r) {
      const int slot = ((first + o * r) % 4 + 4) % 4;
      const int e = fan.edges[r];
      EXPECT_EQ(cp.edge_joint[e], l.joints[slot].joint) << name << " vertex " << v << " crease " << r;
      const double sector = o > 0 ? l.twists[slot] : l.twists[(slot + 3) % 4];
      EXPECT_NEAR(fan.sectors[r], sector, 1e-12) << name << " vertex " << v << " sector " << r;
      ASSERT_TRUE(p.fold_angles[e].has_value());
      EXPECT_LE(angle_diff(*p.fold_angles[e], -o * t[slot]), 1e-12) << name << " crease " << e;
      const Assignment want = *p.fold_angles[e] > 0 ? Assignment::Valley : Assignment::Mountain;
      EXPECT_EQ(p.assignments[e], want) << name << " crease " << e;
    }
  }
  // The pattern's closure at those fold angles, and its 1-D null space there (1 DOF).
  const ClosureSystem sys(p, topo);
  Eigen::VectorXd rho(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) rho[e] = p.fold_angles[e].value_or(0.0);
  const Eigen::VectorXd x = sys.unknowns_from_edges(rho);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(x, r, J);
  EXPECT_LE(r.lpNorm<Eigen::Infinity>(), 1e-12) << name;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(J)};
  const Eigen::VectorXd sv = svd.singularValues();
  const int n = static_cast<int>(J.cols());
  ASSERT_EQ(n, 12);
  ASSERT_EQ(sv.size(), 12);
  EXPECT_LE(sv[n - 1], 1e-10) << name;
  EXPECT_GE(sv[n - 2], 1e-4) << name;
  // The FOLD text reads back to the same pattern.
  const CreasePattern back = parse_fold(write_fold_string(p), name);
  ASSERT_EQ(back.num_edges(), p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) EXPECT_EQ(back.assignments[e], p.assignments[e]);
  if (expect_foldable) {
    const FoldabilityReport f = check_foldability(p, topo);
    EXPECT_EQ(f.verdict, FoldabilityClass::kFoldable) << name << ": " << f.reason;
    EXPECT_EQ(f.dof, 1) << name;
  }
}

TEST(NetworkCreasePattern, Eq234IsTheFig212PatternWithOneDof) { check_pattern("eq2-34.json", true); }

// A Table A4 row (twist variants, still flat paper around a flat panel): the layout and the
// configuration's fold angles are checked the same way. (The kernel's verdict on this
// pattern's letters is not asserted: the configuration at input 30 deg is not reached from
// flat with these letters, `rigidfold check` reports evidence against.)
TEST(NetworkCreasePattern, TableA4RowLayout) { check_pattern("a4_R3R13R12.json", false); }

// The same assembly with linkages B and D given clockwise (joints reversed, twists
// (alpha_2, alpha_1, alpha_0, alpha_3), every joint angle negated: sign -1), the two-fold
// case's coupling (2-15). The reversed loops close at the same q (the network's own closure
// says so); the conversion lays B and D out reversed and gives the same crease pattern: the
// same fold angle and letter for every network joint, the same vertex positions.
TEST(NetworkCreasePattern, ClockwiseLinkagesWithNegatedCouplingGiveTheSamePattern) {
  const Solved s = solve("eq2-34.json");
  LinkageNetwork mirrored = s.spec.network;
  for (int k : {1, 3}) {
    NetworkLinkage& l = mirrored.linkages[k];
    const NetworkLinkage given = l;
    l.twists = {given.twists[2], given.twists[1], given.twists[0], given.twists[3]};
    for (int i = 0; i < 4; ++i) {
      l.joints[i] = given.joints[3 - i];
      l.joints[i].sign = -given.joints[3 - i].sign;
      l.joints[i].offset = -given.joints[3 - i].offset;
    }
  }
  EXPECT_LE(NetworkClosure(mirrored).residual(s.q).lpNorm<Eigen::Infinity>(), 1e-12);
  const NetworkCreasePattern a = network_crease_pattern(s.spec.network, s.q, "given");
  const NetworkCreasePattern b = network_crease_pattern(mirrored, s.q, "mirrored");
  EXPECT_EQ(b.orientation, (std::vector<int>{1, -1, 1, -1}));
  EXPECT_EQ(a.orientation, (std::vector<int>{1, 1, 1, 1}));
  EXPECT_LE(b.residual, 1e-12);
  ASSERT_EQ(a.pattern.num_edges(), b.pattern.num_edges());
  for (int e = 0; e < a.pattern.num_edges(); ++e) {
    if (a.edge_joint[e] < 0) continue;
    int f = -1;
    for (int g = 0; g < b.pattern.num_edges(); ++g)
      if (b.edge_joint[g] == a.edge_joint[e]) f = g;
    ASSERT_GE(f, 0);
    EXPECT_EQ(b.pattern.assignments[f], a.pattern.assignments[e]) << "joint " << a.edge_joint[e];
    EXPECT_LE(angle_diff(*b.pattern.fold_angles[f], *a.pattern.fold_angles[e]), 1e-12) << "joint " << a.edge_joint[e];
  }
  for (int v = 0; v < 4; ++v) EXPECT_LE((b.pattern.vertices[v] - a.pattern.vertices[v]).norm(), 1e-12) << v;
  // Reversing B alone breaks the coupling with its neighbours (sign -1 now against +1).
  LinkageNetwork half = s.spec.network;
  half.linkages[1] = mirrored.linkages[1];
  for (auto& r : half.linkages[1].joints) r.sign = -r.sign;  // the angles as given: not the same loop
  try {
    network_crease_pattern(half, s.q, "half");
    ADD_FAILURE() << "a reversed linkage with unnegated couplings was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different angles"), std::string::npos) << e.what();
  }
}

std::string place_of(const LinkageNetwork& net, const Eigen::VectorXd& q) {
  try {
    network_crease_pattern(net, q, "net.json");
  } catch (const InputError& e) {
    return e.place();
  }
  return "none";
}

TEST(NetworkCreasePattern, RefusalsNameThePlace) {
  {
    const Solved s = solve("fig2-7_rotation.json");  // twists sum to 330 deg
    EXPECT_EQ(place_of(s.spec.network, s.q), "net.json: linkages[0].twists_deg");
  }
  {
    const NetworkSpec spec = read_network_json(data("eq2-34_perturbed.json"));  // panel 361 deg
    EXPECT_EQ(place_of(spec.network, Eigen::VectorXd::Zero(spec.network.num_joints())), "net.json: linkages");
    try {
      network_crease_pattern(spec.network, Eigen::VectorXd::Zero(spec.network.num_joints()), "net.json");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("2-32"), std::string::npos) << e.what();
    }
  }
  {
    const NetworkSpec spec = read_network_json(data("fig2-1_base.json"));  // one linkage
    EXPECT_EQ(place_of(spec.network, Eigen::VectorXd::Zero(spec.network.num_joints())), "net.json: linkages");
  }
  const Solved s = solve("eq2-34.json");
  {
    // A shared joint entering one linkage with sign -1: two fold angles for one crease.
    LinkageNetwork net = s.spec.network;
    net.linkages[1].joints[1].sign = -1;
    EXPECT_EQ(place_of(net, s.q), "net.json: linkages[1].joints[1]");
  }
  {
    // A twist outside (0, 180) deg.
    LinkageNetwork net = s.spec.network;
    net.linkages[2].twists[0] = -net.linkages[2].twists[0];
    EXPECT_EQ(place_of(net, s.q), "net.json: linkages[2].twists_deg[0]");
  }
  {
    // Shared joints that are not neighbours in the loop: B shares its joints 0 and 2.
    LinkageNetwork net = s.spec.network;
    std::swap(net.linkages[1].joints[0], net.linkages[1].joints[1]);
    EXPECT_EQ(place_of(net, s.q), "net.json: linkages[1]");
  }
}

TEST(NetworkCreasePatternCli, OutWritesFoldAndRefusesNonFlatNetworks) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_network_out_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = (dir / "p.fold").string();
  const auto r = test::run_command(test::cli() + " network " + data("eq2-34.json") + " --json --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_LE(j["crease_pattern"]["vertex_loop_residual_rad"].get<double>(), 1e-12);
  EXPECT_EQ(j["crease_pattern"]["creases"], 12);
  ASSERT_TRUE(fs::exists(out));
  const auto check = test::run_command(test::cli() + " check " + out);
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_NE(check.out.find(": foldable"), std::string::npos) << check.out;
  fs::remove(out);
  for (const char* bad : {"fig2-7_rotation.json", "eq2-34_perturbed.json", "fig2-1_base.json"}) {
    const auto b = test::run_command(test::cli() + " network " + data(bad) + " --out " + out);
    EXPECT_EQ(b.status, 2) << bad << ": " << b.err;
    EXPECT_NE(b.err.find(bad), std::string::npos) << b.err;
    EXPECT_FALSE(fs::exists(out)) << bad;
  }
  // --out -: the FOLD alone on standard output, the summary on stderr.
  const auto piped = test::run_command(test::cli() + " network " + data("eq2-34.json") + " --out -");
  ASSERT_EQ(piped.status, 0) << piped.err;
  const CreasePattern fromstdout = parse_fold(piped.out, "stdout");
  EXPECT_EQ(fromstdout.num_vertices(), 12);
  EXPECT_NE(piped.err.find("crease pattern: 12 vertices"), std::string::npos) << piped.err;
  const auto nodir = test::run_command(test::cli() + " network " + data("eq2-34.json") + " --out " + (dir / "no/such/p.fold").string());
  EXPECT_EQ(nodir.status, 2) << nodir.err;
  EXPECT_NE(nodir.err.find("--out"), std::string::npos) << nodir.err;
  fs::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
