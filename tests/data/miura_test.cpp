// Miura-ori generator: counts, sectors, flat-foldability of the assignment, the closed-form
// rigid fold (every vertex loop closes), and the perturbed non-flat-foldable variant.
#include <gtest/gtest.h>

#include "data/generators/miura.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/data/generator_test_utils.hpp"

namespace rigidfold::test {
namespace { namespace RIGIDFOLD_UNITY_ID {

using generators::MiuraCrease;
using generators::MiuraParams;

MiuraParams params(int rows, int cols, double alpha_deg) {
  MiuraParams p;
  p.rows = rows;
  p.cols = cols;
  p.alpha = to_radians(alpha_deg);
  p.a = 1.25;
  p.b = 0.75;
  return p;
}

TEST(GeneratorMiura, CountsDegreesAndLayout) {
  const MiuraParams mp = params(3, 5, 60);
  const CreasePattern p = generators::miura_ori(mp);
  EXPECT_EQ(p.num_vertices(), 4 * 6);
  EXPECT_EQ(p.num_edges(), 5 * 4 + 6 * 3);
  EXPECT_EQ(p.num_faces(), 15);
  EXPECT_FALSE(p.extra["file_title"].get<std::string>().empty());
  EXPECT_FALSE(p.extra["frame_title"].get<std::string>().empty());
  for (const auto& r : p.fold_angles) EXPECT_FALSE(r.has_value());
  const Topology topo = build_topology(p);
  EXPECT_EQ(topo.interior_vertices.size(), 4u * 2u);
  for (int v : topo.interior_vertices) EXPECT_EQ(topo.stars[v].fans[0].edges.size(), 4u);
  const auto kinds = generators::miura_crease_kinds(mp);
  for (int e = 0; e < p.num_edges(); ++e) {
    const Eigen::Vector3d d = p.vertices[p.edges[e][1]] - p.vertices[p.edges[e][0]];
    EXPECT_EQ(kinds[e] == MiuraCrease::Boundary, p.assignments[e] == Assignment::Boundary) << e;
    if (e < 5 * 4) {  // straight: along +x, length b
      EXPECT_NEAR(d.y(), 0.0, 1e-15);
      EXPECT_NEAR(d.x(), 0.75, 1e-15);
    } else {  // zig-zag: length a at +-alpha from the y axis's side
      EXPECT_NEAR(d.norm(), 1.25, 1e-14);
      EXPECT_NEAR(std::fabs(d.x()), 1.25 * std::cos(to_radians(60)), 1e-14);
    }
  }
}

TEST(GeneratorMiura, SectorsAndFlatFoldability) {
  for (double alpha : {15.0, 45.0, 60.0, 85.0}) {
    const CreasePattern p = generators::miura_ori(params(4, 4, alpha));
    const Topology topo = build_topology(p);
    const auto kinds = generators::miura_crease_kinds(params(4, 4, alpha));
    for (int v : topo.interior_vertices) {
      const Fan& fan = topo.stars[v].fans[0];
      std::vector<double> s = fan.sectors;
      std::sort(s.begin(), s.end());
      EXPECT_NEAR(s[0], to_radians(alpha), 1e-12);
      EXPECT_NEAR(s[1], to_radians(alpha), 1e-12);
      EXPECT_NEAR(s[2], kPi - to_radians(alpha), 1e-12);
      EXPECT_NEAR(s[3], kPi - to_radians(alpha), 1e-12);
      EXPECT_NEAR(kawasaki_residual(topo, v), 0.0, 1e-12);
      const auto [m, vv] = mountains_valleys(p, topo, v);
      EXPECT_EQ(std::abs(m - vv), 2);
      // The odd crease is the straight crease between the two acute sectors.
      for (int k = 0; k < 4; ++k) {
        const bool between_acute = std::fabs(fan.sectors[(k + 3) % 4] - to_radians(alpha)) < 1e-9 &&
                                   std::fabs(fan.sectors[k] - to_radians(alpha)) < 1e-9;
        int same = 0;
        for (int j = 0; j < 4; ++j) same += p.assignments[fan.edges[j]] == p.assignments[fan.edges[k]];
        EXPECT_EQ(same == 1, between_acute) << "alpha " << alpha << " vertex " << v;
        if (between_acute) {
          EXPECT_EQ(kinds[fan.edges[k]], MiuraCrease::Straight);
        }
      }
    }
  }
}

TEST(GeneratorMiura, ClosedFormFoldClosesEveryVertexLoop) {
  for (double alpha : {20.0, 60.0, 80.0}) {
    const MiuraParams mp = params(4, 5, alpha);
    const CreasePattern p = generators::miura_ori(mp);
    const Topology topo = build_topology(p);
    for (double rho_s : {1e-6, 0.3, -0.3, 1.5, 2.9, -3.1}) {
      const auto folds = generators::miura_fold_angles(p, mp, rho_s);
      std::vector<double> rho(folds.size(), 0.0);
      for (std::size_t e = 0; e < folds.size(); ++e) {
        EXPECT_EQ(folds[e].has_value(), p.assignments[e] != Assignment::Boundary);
        if (!folds[e]) continue;
        rho[e] = *folds[e];
        // Folds as assigned (V > 0) for rho_s > 0, mirrored for rho_s < 0.
        EXPECT_GT(rho[e] * sign_of(p.assignments[e]) * rho_s, 0.0);
      }
      double worst = 0;
      for (int v : topo.interior_vertices) worst = std::max(worst, loop_residual(topo, v, rho));
      EXPECT_LE(worst, 1e-12) << "alpha " << alpha << " rho_s " << rho_s;
      EXPECT_LE(place(p, topo, rho).mismatch, 1e-12);
      // tan(|rho_s|/2) = cos(alpha) tan(|rho_z|/2)
      const double z = generators::miura_zigzag_fold_angle(mp.alpha, rho_s);
      EXPECT_NEAR(std::tan(std::fabs(rho_s) / 2), std::cos(mp.alpha) * std::tan(z / 2), 1e-12 * (1 + std::tan(z / 2)));
    }
  }
}

TEST(GeneratorMiura, ClosedFormAgreesWithMultiplierPropagation) {
  const MiuraParams mp = params(3, 3, 50);
  const CreasePattern p = generators::miura_ori(mp);
  const auto w = propagate_multipliers(p, build_topology(p));
  ASSERT_TRUE(w.has_value());
  const auto folds = generators::miura_fold_angles(p, mp, 0.8);
  // tan(rho_e/2) = scale * w_e with one scale for every crease.
  int ref = 0;
  while (!folds[ref]) ++ref;
  const double scale = std::tan(*folds[ref] / 2) / (*w)[ref];
  for (int e = 0; e < p.num_edges(); ++e)
    if (folds[e]) {
      EXPECT_NEAR(std::tan(*folds[e] / 2), scale * (*w)[e], 1e-12);
    }
}

TEST(GeneratorMiura, PerturbedViolatesKawasakiAndIsReproducible) {
  MiuraParams mp = params(3, 3, 60);
  mp.perturbation = 0.05;
  mp.seed = 7;
  const CreasePattern p = generators::miura_ori(mp);
  const Topology topo = build_topology(p);
  ASSERT_EQ(topo.interior_vertices.size(), 4u);
  for (int v : topo.interior_vertices) {
    EXPECT_EQ(topo.stars[v].fans[0].edges.size(), 4u);
    EXPECT_NEAR(topo.stars[v].sector_sum(), 2 * kPi, 1e-12);  // still a flat sheet
    EXPECT_GT(std::fabs(kawasaki_residual(topo, v)), 1e-4) << "vertex " << v;
  }
  // Only interior vertices move; the same seed gives the same coordinates.
  const CreasePattern exact = generators::miura_ori(params(3, 3, 60));
  for (int v = 0; v < p.num_vertices(); ++v) {
    const bool interior = std::find(topo.interior_vertices.begin(), topo.interior_vertices.end(), v) != topo.interior_vertices.end();
    const double moved = (p.vertices[v] - exact.vertices[v]).norm();
    if (interior) {
      EXPECT_GT(moved, 0.0);
      EXPECT_LE(moved, 0.05 * std::sqrt(2.0));
    } else {
      EXPECT_EQ(moved, 0.0);
    }
  }
  EXPECT_EQ(generators::miura_ori(mp).vertices, p.vertices);
  mp.seed = 8;
  EXPECT_NE(generators::miura_ori(mp).vertices, p.vertices);
  EXPECT_THROW(generators::miura_fold_angles(p, mp, 0.3), std::invalid_argument);
}

TEST(GeneratorMiura, RoundTripsThroughFold) {
  const CreasePattern p = generators::miura_ori(params(4, 4, 60));
  const CreasePattern q = round_trip(p, "miura");
  EXPECT_EQ(q.vertices, p.vertices);
  EXPECT_EQ(q.edges, p.edges);
  EXPECT_EQ(q.assignments, p.assignments);
  EXPECT_EQ(q.num_faces(), p.num_faces());
  EXPECT_EQ(q.extra["file_title"], p.extra["file_title"]);
  EXPECT_EQ(q.extra["frame_title"], p.extra["frame_title"]);
}

TEST(GeneratorMiura, BadParametersNameTheParameter) {
  auto place_of = [](MiuraParams mp) {
    try {
      generators::miura_ori(mp);
    } catch (const InputError& e) {
      return e.place();
    }
    return std::string("no error");
  };
  MiuraParams mp = params(2, 2, 60);
  mp.alpha = to_radians(90);
  EXPECT_EQ(place_of(mp), "alpha");
  mp = params(0, 2, 60);
  EXPECT_EQ(place_of(mp), "rows");
  mp = params(2, 2, 60);
  mp.b = 0;
  EXPECT_EQ(place_of(mp), "b");
  mp = params(2, 2, 60);
  mp.perturbation = 0.5;
  EXPECT_EQ(place_of(mp), "perturbation");
  mp.perturbation = std::nan("");
  EXPECT_EQ(place_of(mp), "perturbation");
}

}}  // namespace
}  // namespace rigidfold::test
