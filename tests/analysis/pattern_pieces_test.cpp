// A sheet of several pieces (kernel/pattern/pattern_components.hpp): the split keeps every
// face, crease and coordinate, and check_foldability checks each piece alone; the whole
// sheet's verdict agrees with what the pieces imply (it folds when a piece folds, its DOF
// is the sum).
#include <gtest/gtest.h>

#include <string>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/pattern_components.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// Two patterns side by side (the second shifted by `shift` in x), as one sheet of two pieces.
CreasePattern side_by_side(const CreasePattern& a, const CreasePattern& b, double shift) {
  CreasePattern s = a;
  const int nv = a.num_vertices();
  for (Eigen::Vector3d v : b.vertices) {
    v.x() += shift;
    s.vertices.push_back(v);
  }
  for (const auto& e : b.edges) s.edges.push_back({e[0] + nv, e[1] + nv});
  s.assignments.insert(s.assignments.end(), b.assignments.begin(), b.assignments.end());
  s.fold_angles.insert(s.fold_angles.end(), b.fold_angles.begin(), b.fold_angles.end());
  for (auto f : b.faces) {
    for (int& v : f) v += nv;
    s.faces.push_back(f);
  }
  return s;
}

CreasePattern strip_with_valley() {  // a 2 x 1 strip folded along its middle line
  return parse_fold(R"({"vertices_coords":[[0,0],[1,0],[2,0],[2,1],[1,1],[0,1]],
    "edges_vertices":[[0,1],[1,2],[2,3],[3,4],[4,5],[5,0],[1,4]],
    "edges_assignment":["B","B","B","B","B","B","V"],
    "faces_vertices":[[0,1,4,5],[1,2,3,4]]})",
                    "strip");
}

CreasePattern plain_square() {
  return parse_fold(R"({"vertices_coords":[[0,0],[1,0],[1,1],[0,1]],"edges_vertices":[[0,1],[1,2],[2,3],[3,0]],
    "edges_assignment":["B","B","B","B"],"faces_vertices":[[0,1,2,3]]})",
                    "square");
}

CreasePattern bundled(const std::string& name) {
  return read_fold(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/" + name);
}

TEST(PatternPieces, SplitKeepsEveryFaceCreaseAndCoordinate) {
  const CreasePattern whole = side_by_side(bundled("miura_4x4_alpha60.fold"), strip_with_valley(), 20.0);
  const Topology t = build_topology(whole);
  ASSERT_EQ(t.components.size(), 2u);
  const std::vector<PatternComponent> pieces = split_components(whole, t);
  ASSERT_EQ(pieces.size(), 2u);
  int faces = 0, edges = 0;
  for (const PatternComponent& piece : pieces) {
    const CreasePattern& p = piece.pattern;
    faces += p.num_faces();
    edges += p.num_edges();
    for (int v = 0; v < p.num_vertices(); ++v) EXPECT_EQ(p.vertices[v], whole.vertices[piece.vertex_of[v]]);
    for (int e = 0; e < p.num_edges(); ++e) {
      const int w = piece.edge_of[e];
      EXPECT_EQ(p.assignments[e], whole.assignments[w]);
      EXPECT_EQ(piece.vertex_of[p.edges[e][0]], whole.edges[w][0]);
      EXPECT_EQ(piece.vertex_of[p.edges[e][1]], whole.edges[w][1]);
    }
    for (int f = 0; f < p.num_faces(); ++f)
      for (std::size_t k = 0; k < p.faces[f].size(); ++k)
        EXPECT_EQ(piece.vertex_of[p.faces[f][k]], whole.faces[piece.face_of[f]][k]);
    EXPECT_EQ(build_topology(p).components.size(), 1u);
  }
  EXPECT_EQ(faces, whole.num_faces());
  EXPECT_EQ(edges, whole.num_edges());
  EXPECT_EQ(pieces[0].pattern.num_faces() + pieces[1].pattern.num_faces(), whole.num_faces());
}

TEST(PatternPieces, EachPieceCheckedAloneAndTheWholeAgrees) {
  // A Miura 4 x 4 (DOF 1) beside a strip with one valley (DOF 1): the sheet has DOF 2.
  const CreasePattern two = side_by_side(bundled("miura_4x4_alpha60.fold"), strip_with_valley(), 20.0);
  const FoldabilityReport r = check_foldability(two, build_topology(two));
  ASSERT_EQ(r.pieces.size(), 2u);
  EXPECT_EQ(r.verdict, FoldabilityClass::kFoldable);
  for (const auto& v : r.pieces) {
    EXPECT_EQ(v.verdict, FoldabilityClass::kFoldable) << v.reason;
    EXPECT_EQ(v.dof, 1);
  }
  EXPECT_EQ(r.pieces[0].faces + r.pieces[1].faces, two.num_faces());
  EXPECT_EQ(r.dof, 2);
  EXPECT_NE(r.reason.find("2 pieces checked separately (they agree)"), std::string::npos) << r.reason;

  // A square with no crease beside the strip: that piece cannot fold (proof), the sheet can.
  const CreasePattern mixed = side_by_side(strip_with_valley(), plain_square(), 5.0);
  const FoldabilityReport m = check_foldability(mixed, build_topology(mixed));
  ASSERT_EQ(m.pieces.size(), 2u);
  EXPECT_EQ(m.pieces[0].verdict, FoldabilityClass::kFoldable);
  EXPECT_EQ(m.pieces[1].verdict, FoldabilityClass::kNotFoldableProof);
  EXPECT_EQ(m.pieces[1].creases, 0);
  EXPECT_EQ(m.verdict, FoldabilityClass::kFoldable);
  EXPECT_EQ(m.dof, 1);
  EXPECT_NE(m.reason.find("(they agree)"), std::string::npos) << m.reason;

  // The general model on the whole sheet agrees with the pieces too.
  FoldabilityOptions general;
  general.force_general = true;
  const FoldabilityReport g = check_foldability(two, build_topology(two), general);
  EXPECT_EQ(g.verdict, FoldabilityClass::kFoldable) << g.reason;
  EXPECT_EQ(g.dof, 2) << g.reason;
  EXPECT_NE(g.reason.find("(they agree)"), std::string::npos) << g.reason;

  // One piece: no piece list.
  const CreasePattern one = strip_with_valley();
  EXPECT_TRUE(check_foldability(one, build_topology(one)).pieces.empty());
}

}}  // namespace
}  // namespace rigidfold
