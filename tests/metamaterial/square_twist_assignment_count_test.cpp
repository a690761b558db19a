// The M-V assignment count of square-twist tessellations (at scale),
// enumerated by the kernel (enumerate_assignments: Maekawa + big-little-big at every vertex,
// backtracking) against an independent count.
//
// Independent count. Every interior vertex of data/generators' square-twist tessellation has
// the sectors pi/2, pi - t, pi/2, t (0 < t < pi/2): t is the only smallest sector, bounded by
// the twist side S (vertex k -> k+1) and the outer crease o_b; the other two creases are the
// previous side P and o_a. Big-little-big makes S and o_b differ; Maekawa (3:1) then leaves,
// for given side letters P and S, exactly one completion: P != S -> odd crease S, o_a = o_b = P;
// P == S -> odd crease o_b, o_a = P, o_b = -P. In both cases o_a = P and o_b = -S. So an
// assignment is fixed by the 4 r c side letters, and it exists iff every crease joining two
// twists gets the same letter from both. A pleat between neighbouring twists X, Y is two
// creases; the pleat's creases leave X at the two ends of X's side facing Y, one as o_a of
// the vertex after that side (letter = that side) and one as o_b of the vertex before it
// (letter = -that side), and likewise at Y, so both creases say "facing side of X = facing
// side of Y": one equation per pleat, and each side faces at most one neighbour, so the
// equations never close a cycle. Hence
//     count(r x c) = 2^(4 r c - r (c - 1) - c (r - 1)),
// e.g. 16 for one twist (its 2^4 side letters), 4096 for 2 x 2 (the number
// square_twist_tessellation.hpp reports from enumerating side letters with the multiplier
// verdict). The test asserts it for 1 x 1 .. 2 x 3 on two twist angles; 4 x 4 would hold
// 2^40 ~ 1.1e12 assignments, beyond any enumeration.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "data/generators/square_twist_tessellation.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

long independent_count(int r, int c) { return 1L << (4 * r * c - r * (c - 1) - c * (r - 1)); }

TEST(SquareTwistAssignmentCount, EnumerationMatchesTheSideLetterCount) {
  for (double t_deg : {30.0, 55.0}) {
    for (const auto& [r, c] : {std::pair{1, 1}, std::pair{1, 2}, std::pair{2, 2}, std::pair{2, 3}}) {
      generators::SquareTwistTessellationParams sp;
      sp.rows = r;
      sp.cols = c;
      sp.twist = t_deg * std::numbers::pi / 180;
      sp.side = 1.0;
      sp.spacing = 2.5;
      const CreasePattern p = generators::square_twist_tessellation(sp);
      AssignmentEnumerationOptions o;
      o.max_verdicts = 0;  // the count alone
      const AssignmentEnumeration e = enumerate_assignments(p, build_topology(p), o);
      ASSERT_TRUE(e.complete) << r << "x" << c;
      EXPECT_EQ(e.assignments, independent_count(r, c)) << r << "x" << c << " t " << t_deg;
      // The classes' orbits partition the assignments (symmetry group and flip).
      EXPECT_GE(e.class_count * 2L * e.symmetry_order, e.assignments) << r << "x" << c;
      EXPECT_LE(e.class_count, e.assignments) << r << "x" << c;
      std::printf("[ count ] %dx%d t %g: %ld assignments, %ld classes (|G| %d), %.3f s\n", r, c, t_deg, e.assignments,
                  e.class_count, e.symmetry_order, e.seconds);
    }
  }
}

}}  // namespace
}  // namespace rigidfold
