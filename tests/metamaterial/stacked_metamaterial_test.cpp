// Stacked metamaterials 1-4 of seed 003 §3.2.3 (Figs 3-10 ... 3-12) as geometry: the layer
// sheets (data/generators/stacked_metamaterial.hpp, a reconstruction: the figures are lost),
// traced by the general solver, stacked by their bonding vertices and compared with the
// element closed forms (design/metamaterial/stacked_metamaterial_check.hpp), then the seed's
// claims about Fig 3-12.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <map>
#include <set>
#include <tuple>

#include "data/generators/stacked_metamaterial.hpp"
#include "design/metamaterial/corrugated_elements.hpp"
#include "design/metamaterial/stacked_metamaterial_check.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::metamaterial {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;
using generators::StackedMetamaterialParams;

StackedMetamaterialParams params(int m) {
  StackedMetamaterialParams p;
  p.metamaterial = m;
  p.alpha = 60 * kPi / 180;  // the CLI's element defaults (the seed's Fig 3-12 values are lost)
  p.beta = 70 * kPi / 180;
  p.l = 1.0;
  return p;
}

TEST(StackedMetamaterial, LayerSheetsAreFlatFoldableWithUnitCreases) {
  for (int m = 1; m <= 4; ++m) {
    const auto s = generators::stacked_layer_sheet(params(m));
    const auto r = generators::stacked_layer_sheet(params(m), true);
    const CreasePattern& p = s.pattern;
    ASSERT_EQ(p.num_vertices(), (s.ni + 1) * (s.nj + 1));
    const Topology t = build_topology(p);
    std::multiset<long> sectors_seen;
    int interior = 0;
    for (int e = 0; e < p.num_edges(); ++e) {
      EXPECT_NEAR((p.vertices[p.edges[e][0]] - p.vertices[p.edges[e][1]]).norm(), 1.0, 1e-12);
      if (p.assignments[e] == Assignment::Boundary) continue;
      ++interior;
      ASSERT_TRUE(p.assignments[e] == Assignment::Mountain || p.assignments[e] == Assignment::Valley);
      EXPECT_NE(p.assignments[e], r.pattern.assignments[e]);  // reversed M-V
    }
    EXPECT_EQ(interior, 52);
    // Interior vertices: sectors pi - beta, alpha, beta, pi - alpha (flat-foldable), Maekawa.
    const double want[4] = {kPi - params(m).beta, params(m).alpha, params(m).beta, kPi - params(m).alpha};
    int vertices = 0;
    for (int v = 0; v < p.num_vertices(); ++v) {
      if (t.stars[v].fans.size() != 1 || !t.stars[v].fans[0].closed) continue;
      ++vertices;
      std::vector<double> got(t.stars[v].fans[0].sectors.begin(), t.stars[v].fans[0].sectors.end());
      std::vector<double> w(want, want + 4);
      std::sort(got.begin(), got.end());
      std::sort(w.begin(), w.end());
      ASSERT_EQ(got.size(), 4u);
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], w[k], 1e-12);
    }
    EXPECT_EQ(vertices, 21);
    EXPECT_FALSE(s.bonding_vertices.empty());
    // Edge numbering is the lattice's: i-edges then j-edges.
    EXPECT_EQ(p.edges[s.i_edge(1, 2)][0], s.node(1, 2));
    EXPECT_EQ(p.edges[s.i_edge(1, 2)][1], s.node(2, 2));
    EXPECT_EQ(p.edges[s.j_edge(3, 5)][0], s.node(3, 5));
    EXPECT_EQ(p.edges[s.j_edge(3, 5)][1], s.node(3, 6));
    // The analytic motion (the traces' start) closes at every vertex, with the letters' signs.
    const ClosureSystem sys(p, t);
    for (double tt : {3.0, 2.0, 1.2}) {
      const auto rho = generators::stacked_layer_fold_angles(params(m), false, tt);
      const Eigen::VectorXd x = sys.unknowns_from_edges(Eigen::Map<const Eigen::VectorXd>(rho.data(), rho.size()));
      EXPECT_LE(sys.residual(x).lpNorm<Eigen::Infinity>(), 1e-12) << m << " " << tt;
      for (int e = 0; e < p.num_edges(); ++e) {
        if (p.assignments[e] != Assignment::Boundary) {
          EXPECT_EQ(rho[e] > 0, p.assignments[e] == Assignment::Valley) << m << " edge " << e;
        }
      }
    }
  }
  auto bad = [](StackedMetamaterialParams p, const char* place) {
    try {
      generators::stacked_layer_sheet(p);
      ADD_FAILURE() << place;
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), place);
    }
  };
  auto p = params(1);
  p.metamaterial = 5;
  bad(p, "metamaterial");
  p = params(1);
  p.alpha = kPi;
  bad(p, "alpha");
  p = params(2);
  p.beta = NAN;
  bad(p, "beta");
  p = params(3);
  p.l = 0;
  bad(p, "l");
  p = params(4);
  p.beta = kPi - p.alpha;
  bad(p, "beta");
}

// One check per (metamaterial, alpha, beta), shared by the tests below (each ~0.1 s Release).
const StackedMetamaterialCheck& check(int m, double alpha_deg = 60, double beta_deg = 70) {
  static std::map<std::tuple<int, double, double>, StackedMetamaterialCheck> cache;
  const auto key = std::make_tuple(m, alpha_deg, beta_deg);
  auto it = cache.find(key);
  if (it == cache.end()) {
    auto p = params(m);
    p.alpha = alpha_deg * kPi / 180;
    p.beta = beta_deg * kPi / 180;
    StackedMetamaterialOptions o;  // 4 layers, drive to 170 deg
    o.steps = 8;
    it = cache.emplace(key, stacked_metamaterial_check(p, o)).first;
  }
  return it->second;
}

void expect_stack(int m) {
  const StackedMetamaterialCheck& c = check(m);
  ASSERT_EQ(c.states.size(), 8u);
  EXPECT_LE(c.max_residual, 1e-12);
  EXPECT_LE(c.max_bond_gap, 1e-10);
  EXPECT_LE(c.max_dimension_difference, 1e-9);
  EXPECT_LE(c.max_ratio_difference, 1e-9);
  EXPECT_GT(c.bonding_vertices, 4);
  EXPECT_TRUE(c.has_maximum);
  // The traced path passes the height maximum, and no traced state is higher than it.
  EXPECT_GT(c.states.front().phi, c.phi_II);
  EXPECT_LT(c.states.back().phi, c.phi_II);
  for (const auto& st : c.states) EXPECT_LE(st.H, c.height_max + 1e-9);
  char text[64];
  std::snprintf(text, sizeof text, "%.3g %.3g %.3g", c.max_bond_gap, c.max_dimension_difference, c.max_ratio_difference);
  ::testing::Test::RecordProperty("bond_dims_ratios", text);
}

TEST(StackedMetamaterial, Metamaterial1StackMatchesElement1) { expect_stack(1); }
TEST(StackedMetamaterial, Metamaterial2StackMatchesElement2) { expect_stack(2); }
TEST(StackedMetamaterial, Metamaterial3StackMatchesElement2) { expect_stack(3); }
TEST(StackedMetamaterial, Metamaterial4StackMatchesElement3) {
  expect_stack(4);
  // Reconstruction finding: the printed (3-26) misses by more than a radian somewhere on the
  // path; its inverse tan(phi/2) = |k| tan(theta/2) holds to round-off.
  EXPECT_GT(check(4).printed_relation_difference, 0.5);
  EXPECT_LE(check(4).max_relation_difference, 1e-9);
}

// The seed's statements about Fig 3-12, as they come out of the traced stacks.
TEST(StackedMetamaterial, SeedClaimsOnFig3_12) {
  const auto &m1 = check(1), &m2 = check(2), &m3 = check(3), &m4 = check(4);
  // "1-3 reach maximum height at the same folding angle".
  EXPECT_NEAR(m2.phi_II, m1.phi_II, 1e-12);
  EXPECT_NEAR(m3.phi_II, m1.phi_II, 1e-12);
  // "The maximum heights of 2-4 are the same and double that of 1".
  EXPECT_NEAR(m2.height_max, 2 * m1.height_max, 1e-9);
  EXPECT_NEAR(m3.height_max, m2.height_max, 1e-9);
  EXPECT_NEAR(m4.height_max, m2.height_max, 1e-9);
  // "The dimension curves of 2 and 3 are identical" (traced, state by state), while the
  // layers differ (3 has one element-2 and two element-1 cells).
  ASSERT_EQ(m2.states.size(), m3.states.size());
  for (std::size_t k = 0; k < m2.states.size(); ++k) {
    EXPECT_NEAR(m2.states[k].W, m3.states[k].W, 1e-9);
    EXPECT_NEAR(m2.states[k].L, m3.states[k].L, 1e-9);
    EXPECT_NEAR(m2.states[k].H, m3.states[k].H, 1e-9);
    EXPECT_NEAR(m2.states[k].nu_out, m3.states[k].nu_out, 1e-9 * std::max(1.0, std::fabs(m2.states[k].nu_out)));
    EXPECT_NEAR(m1.states[k].H * 2, m2.states[k].H, 1e-9);
  }
  // "Between 0 and phi_II a negative Poisson's ratio in 3D; between phi_II and pi a negative
  // in-plane and a positive out-of-plane one": true for all four.
  for (const auto* m : {&m1, &m2, &m3, &m4}) {
    EXPECT_TRUE(m->negative_3d_before);
    EXPECT_TRUE(m->in_negative_out_positive_after);
  }
  // "phi_II of 4 is much larger than the other three": FALSE on the reconstruction. With the
  // consistent phi (tan(phi/2) = |k| tan(theta/2), |k| < 1) phi_II(4) < theta_II(4), and here
  // below phi_II(1) (60/70 deg: 22.8 vs 129.1 deg; also at the seed's unit example 135/60 deg).
  const double k = std::fabs(std::cos((params(4).alpha + params(4).beta) / 2) /
                             std::cos((params(4).beta - params(4).alpha) / 2));
  EXPECT_NEAR(m4.phi_II, 2 * std::atan(k * std::tan(m4.theta_II / 2)), 1e-12);
  EXPECT_LT(m4.phi_II, m4.theta_II);
  EXPECT_LT(m4.phi_II, m1.phi_II);
  EXPECT_LT(check(4, 135, 60).phi_II, check(1, 135, 60).phi_II);
  // Read through the printed (3-26) instead (phi with tan(theta_II/2) = |k| tan(phi/2)), the
  // claim holds at 135/60 deg but not at 60/70 deg: it depends on the lost parameters.
  auto printed_phi = [](const StackedMetamaterialCheck& c, double a, double b) {
    const double kk = std::fabs(std::cos((a + b) / 2) / std::cos((b - a) / 2));
    return 2 * std::atan(std::tan(c.theta_II / 2) / kk);
  };
  EXPECT_GT(printed_phi(check(4, 135, 60), 135 * kPi / 180, 60 * kPi / 180), check(1, 135, 60).phi_II);
  EXPECT_LT(printed_phi(m4, params(4).alpha, params(4).beta), m1.phi_II);
  EXPECT_NEAR(check(4, 135, 60).height_max, 2 * check(1, 135, 60).height_max, 1e-9);
}

}}  // namespace
}  // namespace rigidfold::metamaterial
