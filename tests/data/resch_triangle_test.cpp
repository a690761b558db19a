// Resch's triangle tessellation (data/generators/resch_triangle.hpp): its construction checked
// against the crease pattern Origami Simulator ships (the same vertex stars: degree 6, the
// centroid's three M spokes and three V creases, the grid vertex's four M grid edges, its M
// spoke and its V crease in line), and `check` on tessellations of a few hundred creases:
// strictly foldable, certified, with no branch exploration of their high-DOF flat state.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "data/generators/resch_triangle.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

int folding_creases(const CreasePattern& p) {
  return static_cast<int>(std::count_if(p.assignments.begin(), p.assignments.end(), [](Assignment a) {
    return a == Assignment::Mountain || a == Assignment::Valley;
  }));
}

// An interior vertex's star, independent of scale and rotation: its creases' letters and
// lengths (relative to the shortest), counter-clockwise from the shortest valley, e.g.
// "M1.00 V2.00 M1.00 V2.00 M1.00 V2.00" for a star's centroid.
std::map<std::string, int> vertex_stars(const CreasePattern& p) {
  const Topology t = build_topology(p);
  std::vector<std::vector<std::pair<double, int>>> around(p.num_vertices());
  for (int e = 0; e < p.num_edges(); ++e)
    for (int end : {0, 1}) {
      const int v = p.edges[e][end], w = p.edges[e][1 - end];
      const Eigen::Vector3d d = p.vertices[w] - p.vertices[v];
      around[v].push_back({std::atan2(d.y(), d.x()), e});
    }
  std::map<std::string, int> stars;
  for (int v : t.interior_vertices) {
    std::vector<std::pair<double, int>>& fan = around[v];
    std::sort(fan.begin(), fan.end());
    double shortest = INFINITY;
    for (const auto& [angle, e] : fan) shortest = std::min(shortest, (p.vertices[p.edges[e][0]] - p.vertices[p.edges[e][1]]).norm());
    std::vector<std::string> words;
    for (const auto& [angle, e] : fan) {
      char w[32];
      std::snprintf(w, sizeof w, "%c%.2f", p.assignments[e] == Assignment::Mountain ? 'M' : p.assignments[e] == Assignment::Valley ? 'V' : '?',
                    (p.vertices[p.edges[e][0]] - p.vertices[p.edges[e][1]]).norm() / shortest);
      words.push_back(w);
    }
    // The rotation that puts the lexicographically least word sequence first.
    std::string best;
    for (std::size_t r = 0; r < words.size(); ++r) {
      std::string s;
      for (std::size_t k = 0; k < words.size(); ++k) s += words[(r + k) % words.size()] + " ";
      if (best.empty() || s < best) best = s;
    }
    ++stars[best];
  }
  return stars;
}

TEST(ReschTriangle, HasOrigamiSimulatorsVertexStars) {
  generators::ReschTriangleParams params;
  params.rows = 10;
  params.cols = 12;
  const CreasePattern p = generators::resch_triangle(params);
  EXPECT_EQ(folding_creases(p), 463);
  const std::map<std::string, int> ours = vertex_stars(p);
  ASSERT_EQ(ours.size(), 2u);  // the centroids and the grid vertices
  // Origami Simulator's file, drawn by hand to 0.01 of its 69-unit side: the same two stars
  // (lengths to 2 decimals of the shortest crease), and nothing else at its interior vertices.
  const CreasePattern os = read_pattern(std::string(RIGIDFOLD_CORPUS_DIR) + "/origami-simulator/reschTriTessellation.svg");
  std::map<std::string, int> theirs = vertex_stars(os);
  for (const auto& [star, count] : ours) EXPECT_GT(theirs[star], 0) << star;
  int matched = 0, all = 0;
  for (const auto& [star, count] : theirs) {
    all += count;
    if (ours.count(star)) matched += count;
  }
  // Near the sheet's edge its lines are clipped shorter (the 20- and 59-unit valleys), so a
  // few of its interior vertices have other lengths.
  EXPECT_GE(matched, all - 10) << matched << " of " << all;
  const Topology t = build_topology(p);
  for (int v : t.interior_vertices) EXPECT_EQ(t.stars[v].fans[0].edges.size(), 6u) << v;
}

TEST(ReschTriangle, ARectangleOfFewHundredCreasesIsCertifiedStrictlyFoldable) {
  for (const auto& [rows, cols] : {std::pair{10, 10}, std::pair{10, 12}}) {
    generators::ReschTriangleParams params;
    params.rows = rows;
    params.cols = cols;
    const CreasePattern p = generators::resch_triangle(params);
    const FoldabilityReport r = check_foldability(p, build_topology(p));
    const std::string what = std::to_string(rows) + " x " + std::to_string(cols) + ", " +
                             std::to_string(folding_creases(p)) + " creases";
    EXPECT_GE(folding_creases(p), 376) << what;
    EXPECT_EQ(r.verdict, FoldabilityClass::kFoldable) << what << ": " << r.reason;
    EXPECT_TRUE(r.is_proof) << what;
    ASSERT_TRUE(r.strictness) << what;
    EXPECT_TRUE(r.strictness->strict) << what;
    EXPECT_GT(r.dof, 16) << what;
    EXPECT_FALSE(r.branches_explored) << what;  // a DOF-50 flat state: its cone is not sampled
    EXPECT_NE(r.exploration_note.find("more than 16"), std::string::npos) << r.exploration_note;
  }
}

TEST(ReschTriangle, BadParametersNameTheirPlace) {
  generators::ReschTriangleParams params;
  params.rows = 0;
  try {
    generators::resch_triangle(params);
    FAIL() << "rows 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "rows");
  }
  params.rows = 4;
  params.side = -1;
  try {
    generators::resch_triangle(params);
    FAIL() << "side -1 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "side");
  }
}

}}  // namespace
}  // namespace rigidfold
