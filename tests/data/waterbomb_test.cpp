// Waterbomb base generator (seed 004): counts, equal sectors, alternating assignment, and
// seed 004's symmetric fold (gamma_m, gamma_v) closing the vertex loop.
#include <gtest/gtest.h>

#include "data/generators/waterbomb.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/data/generator_test_utils.hpp"

namespace rigidfold::test {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(GeneratorWaterbomb, TraditionalBaseIsTheSquare) {
  const CreasePattern p = generators::waterbomb_base({});
  EXPECT_EQ(p.num_vertices(), 9);
  EXPECT_EQ(p.num_edges(), 16);
  EXPECT_EQ(p.num_faces(), 8);
  // Square of side 2 cos(45 deg) = sqrt 2, axis-aligned: corners at (+-1, +-1)/sqrt 2.
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d x = p.vertices[1 + k];
    if (k % 2 == 1) {
      EXPECT_NEAR(std::fabs(x.x()), std::sqrt(0.5), 1e-15);
      EXPECT_NEAR(std::fabs(x.y()), std::sqrt(0.5), 1e-15);
      EXPECT_EQ(p.assignments[k], Assignment::Mountain);  // diagonal
    } else {
      EXPECT_NEAR(std::min(std::fabs(x.x()), std::fabs(x.y())), 0.0, 1e-15);
      EXPECT_EQ(p.assignments[k], Assignment::Valley);  // mid-line
    }
  }
}

TEST(GeneratorWaterbomb, GeneralisedBasesAlternateWithEqualSectors) {
  for (int n = 3; n <= 8; ++n)
    for (bool corners_m : {true, false}) {
      generators::WaterbombParams wp;
      wp.n = n;
      wp.radius = 2.5;
      wp.corners_mountain = corners_m;
      const CreasePattern p = generators::waterbomb_base(wp);
      EXPECT_EQ(p.num_vertices(), 2 * n + 1);
      EXPECT_EQ(p.num_edges(), 4 * n);
      EXPECT_EQ(p.num_faces(), 2 * n);
      const Topology topo = build_topology(p);
      ASSERT_EQ(topo.interior_vertices, std::vector<int>{0});
      const Fan& fan = topo.stars[0].fans[0];
      ASSERT_EQ(fan.edges.size(), static_cast<std::size_t>(2 * n));
      for (int i = 0; i < 2 * n; ++i) {
        EXPECT_NEAR(fan.sectors[i], kPi / n, 1e-12);
        EXPECT_NE(p.assignments[fan.edges[i]], p.assignments[fan.edges[(i + 1) % (2 * n)]]);
      }
      EXPECT_NEAR(kawasaki_residual(topo, 0), 0.0, 1e-12);
      const auto [m, v] = mountains_valleys(p, topo, 0);
      EXPECT_EQ(m, n);
      EXPECT_EQ(v, n);  // Maekawa fails on purpose: no flat-folded state
      EXPECT_EQ(p.assignments[1] == Assignment::Mountain, corners_m);
      const CreasePattern q = round_trip(p, "waterbomb");
      EXPECT_EQ(q.vertices, p.vertices);
      EXPECT_EQ(q.assignments, p.assignments);
    }
}

// Seed 004 eqs. (3.4)-(3.6) (with the digest's simplified gamma_m = -|180 - 2 theta|): the
// symmetric state of the generated base closes its loop. Valley positive, as the FOLD sign.
TEST(GeneratorWaterbomb, Seed004SymmetricFoldCloses) {
  for (int n : {3, 4, 6, 10}) {
    generators::WaterbombParams wp;
    wp.n = n;
    const CreasePattern p = generators::waterbomb_base(wp);
    const Topology topo = build_topology(p);
    const double alpha = kPi / n, beta = 2 * kPi / n;
    for (double theta_deg : {20.0, 45.0, 70.0, 89.0}) {
      const double th = to_radians(theta_deg);
      const double d = std::acos(std::cos(th) * std::cos(th) + std::sin(th) * std::sin(th) * std::cos(beta));
      const double gm = -std::fabs(kPi - 2 * th);
      const double gv = 2 * (std::acos(std::tan(d / 2) / std::tan(th)) + std::acos(std::tan(d / 2) / std::tan(alpha))) - kPi;
      std::vector<double> rho(p.num_edges(), 0.0);
      for (int e = 0; e < 2 * n; ++e) rho[e] = p.assignments[e] == Assignment::Mountain ? gm : gv;
      EXPECT_LE(loop_residual(topo, 0, rho), 1e-12) << "n " << n << " theta " << theta_deg;
    }
  }
}

TEST(GeneratorWaterbomb, BadParameters) {
  generators::WaterbombParams wp;
  wp.n = 2;
  try {
    generators::waterbomb_base(wp);
    FAIL() << "n = 2 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "n");
  }
  wp.n = 4;
  wp.radius = 0;
  EXPECT_THROW(generators::waterbomb_base(wp), InputError);
}

}}  // namespace
}  // namespace rigidfold::test
