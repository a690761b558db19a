// Circular CORE joints forced on a pattern's crease (PatternSorceRequest::circular_edges): on
// the seed 002 vertex A (data/sorce/vertex_a.fold) traced by the general solver, fold 2 made
// circular has both profiles on arcs of radius h/2 (convexity 2/h at every sample, seed
// section 3's circle oracle, here through the traced spline path), its faces end at -h/2 (a
// valley at pi: the digest's sign law), and bad requests name the place.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "design/sorce/sorce_pattern.hpp"
#include "tests/sorce/sorce_pattern_requests.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::kVertexA;
PatternSorceRequest vertex_a_request(double h) { return testing::single_vertex_request(h); }

TEST(SorcePatternCircular, ForcedCircularFoldRollsOnArcsOfHalfTheThickness) {
  const CreasePattern p = read_fold(kVertexA);
  const double h = 0.1;
  PatternSorceRequest rq = vertex_a_request(h);
  rq.circular_edges = {1};
  const PatternSorce s = pattern_sorce(p, rq);
  const CreaseJoint* fold2 = nullptr;
  for (const CreaseJoint& j : s.creases)
    if (j.edge == 1) fold2 = &j;
  ASSERT_NE(fold2, nullptr);
  const FoldReport& r = fold2->report;
  for (double c : {r.min_convexity_left, r.max_convexity_left, r.min_convexity_right, r.max_convexity_right})
    EXPECT_NEAR(c, 2 / h, 1e-9 * 2 / h);
  EXPECT_TRUE(r.concave_left.empty() && r.concave_right.empty() && r.cusps.empty());
  for (int f : {fold2->left_face, fold2->right_face}) EXPECT_NEAR(s.faces[f].end_value, -h / 2, 1e-12) << f;
  EXPECT_TRUE(r.stacks);
  EXPECT_LE(s.checks.consistency, 1e-12);
  EXPECT_LE(s.checks.contact, 1e-10);
}

TEST(SorcePatternCircular, BadRequestsNameThePlace) {
  const CreasePattern p = read_fold(kVertexA);
  auto place = [&](std::vector<int> edges) -> std::string {
    PatternSorceRequest rq = vertex_a_request(0.1);
    rq.circular_edges = std::move(edges);
    try {
      pattern_sorce(p, rq);
    } catch (const InputError& e) {
      return e.place();
    }
    return "no error";
  };
  EXPECT_EQ(place({5}), "circular_edges[0]");     // a boundary edge
  EXPECT_EQ(place({1, 0}), "circular_edges[1]");  // face 0 is on folds 1 and 2, whose angles differ
}

}}  // namespace
}  // namespace rigidfold::sorce
