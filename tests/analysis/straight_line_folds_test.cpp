// Straight crease lines (kernel/analysis/straight_line_folds.hpp) and what check_foldability
// makes of them: a line of one letter from boundary to boundary folds alone (weak
// foldability, checked here by placing the faces, which shares no code with the closure
// residual), and crossing lettered lines rule out strict foldability.
#include <gtest/gtest.h>

#include <functional>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/straight_line_folds.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/validate_pattern.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// A 3 x 3 grid of unit squares: creases on x = 1, 2 and y = 1, 2 (four degree-4 vertices
// where two straight lines cross). letter(vertical, line, segment) gives each crease's
// assignment; the boundary is B.
CreasePattern grid(const std::function<Assignment(bool, int, int)>& letter) {
  CreasePattern p;
  auto id = [](int i, int j) { return 4 * j + i; };
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) p.vertices.emplace_back(i, j, 0.0);
  auto edge = [&](int a, int b, Assignment s) {
    p.edges.push_back({a, b});
    p.assignments.push_back(s);
  };
  for (int line = 0; line <= 3; ++line)
    for (int seg = 0; seg < 3; ++seg) {
      const bool inner = line == 1 || line == 2;
      edge(id(line, seg), id(line, seg + 1), inner ? letter(true, line, seg) : Assignment::Boundary);    // x = line
      edge(id(seg, line), id(seg + 1, line), inner ? letter(false, line, seg) : Assignment::Boundary);   // y = line
    }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  complete_and_validate(p, "grid");
  return p;
}

TEST(StraightLineFolds, ALineOfOneLetterFoldsAloneAndCrossingLinesForbidStrictFolding) {
  // x = 1 all valley; every other crease mountain, alternating along y = 1 so that only the
  // vertical lines keep one letter.
  const CreasePattern p = grid([](bool vertical, int line, int seg) {
    if (vertical) return line == 1 ? Assignment::Valley : Assignment::Mountain;
    return seg == 1 ? Assignment::Valley : Assignment::Mountain;
  });
  const Topology t = build_topology(p);
  const StraightLineAnalysis a = straight_line_folds(p, t);
  EXPECT_EQ(a.lines_found, 4);
  ASSERT_EQ(a.folds.size(), 2u);  // x = 1 (valley) and x = 2 (mountain)
  EXPECT_EQ(a.strict_obstruction_vertices.size(), 4u);
  for (const StraightLineFold& f : a.folds) {
    EXPECT_EQ(f.creases.size(), 3u);
    EXPECT_FALSE(t.stars[f.vertices.front()].interior());
    EXPECT_FALSE(t.stars[f.vertices.back()].interior());
    EXPECT_LE(f.max_residual, 1e-14);
    // Independent check: the faces placed at every sample close up (no closure code).
    for (const Eigen::VectorXd& rho : f.path)
      EXPECT_LE(place_faces(p, t, rho, reference_fold_angles(p, t)).relative_mismatch(), 1e-12);
    for (int e : f.creases) EXPECT_EQ(assigned_fold_sign(p.assignments[e]), f.sign);
  }

  const FoldabilityReport r = check_foldability(p, t);
  // Strict question (the headline): crossing lettered lines, no motion folds them all.
  EXPECT_EQ(r.verdict, FoldabilityClass::kNotFoldableProof) << r.reason;
  EXPECT_TRUE(r.is_proof);
  EXPECT_TRUE(r.folds_in_part);
  ASSERT_TRUE(r.obstruction.has_value());
  EXPECT_EQ(r.obstruction->kind, "crossing lettered lines");
  EXPECT_GE(r.dof, 1);  // of the weak motion: a line folds alone
  ASSERT_TRUE(r.strictness.has_value());
  EXPECT_FALSE(r.strictness->strict);
  EXPECT_EQ(r.strictness->strict_obstruction_vertices.size(), 4u);
  // Weak: the crossing lines stay flat (at least the 6 horizontal creases).
  EXPECT_GE(r.strictness->flat_lettered.size(), 6u);
}

TEST(StraightLineFolds, LinesWhoseLettersAlternateDoNotFoldAndTheVerdictNeverSaysYes) {
  // Every line M, V, M along its three segments: no line can fold alone (a straight line
  // through a crossing folds its two creases equally while the other line is flat), and at
  // a crossing no other motion leaves flat.
  const CreasePattern p = grid([](bool, int, int seg) { return seg == 1 ? Assignment::Valley : Assignment::Mountain; });
  const Topology t = build_topology(p);
  const StraightLineAnalysis a = straight_line_folds(p, t);
  EXPECT_EQ(a.lines_found, 4);
  EXPECT_TRUE(a.folds.empty());
  const FoldabilityReport r = check_foldability(p, t);
  EXPECT_FALSE(r.foldable()) << r.reason;
  // Letters ignored, every line folds alone.
  StraightLineOptions so;
  so.use_assignment = false;
  EXPECT_EQ(straight_line_folds(p, t, so).folds.size(), 4u);
}

}}  // namespace
}  // namespace rigidfold
