// The M-V assignment count of the Miura-ori (up to 6 x 6 panels, with a count and the time),
// enumerated by the kernel (enumerate_assignments) against an
// independent count: Ginepro and Hull (2014, "Counting Miura-ori foldings") put the locally
// flat-foldable assignments of an r x c-panel Miura-ori in bijection with the proper
// 3-colourings of the r x c grid graph (one node per panel) with one node's colour fixed, so
//     count = colourings(r x c grid, 3 colours) / 3,
// here counted by a row-by-row transfer matrix (no crease pattern involved). Measured for
// 6 x 6 panels with `rigidfold assignments` (shared machine): 33865632 assignments,
// 8466590 classes, 4.6 s without verdicts; the test stops at 5 x 5 (193662) to stay fast.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <numbers>
#include <vector>

#include "data/generators/miura.hpp"
#include "kernel/analysis/assignment_enumeration.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// Proper 3-colourings of the r x c grid graph, by rows of c colours.
long grid_three_colourings(int r, int c) {
  std::vector<std::vector<int>> rows;
  std::vector<int> row(c, 0);
  for (;;) {
    bool ok = true;
    for (int i = 0; i + 1 < c; ++i) ok = ok && row[i] != row[i + 1];
    if (ok) rows.push_back(row);
    int k = 0;
    while (k < c && ++row[k] == 3) row[k++] = 0;
    if (k == c) break;
  }
  std::vector<long> count(rows.size(), 1);
  for (int step = 1; step < r; ++step) {
    std::vector<long> next(rows.size(), 0);
    for (std::size_t a = 0; a < rows.size(); ++a)
      for (std::size_t b = 0; b < rows.size(); ++b) {
        bool ok = true;
        for (int i = 0; i < c; ++i) ok = ok && rows[a][i] != rows[b][i];
        if (ok) next[a] += count[b];
      }
    count = next;
  }
  long total = 0;
  for (long v : count) total += v;
  return total;
}

TEST(MiuraAssignmentCount, EnumerationMatchesGridThreeColourings) {
  EXPECT_EQ(grid_three_colourings(2, 2), 18);  // the 4-cycle: (k - 1)^4 + (k - 1) = 16 + 2
  EXPECT_EQ(grid_three_colourings(1, 3), 12);  // a path of 3 nodes: 3 * 2 * 2
  for (const auto& [r, c] : {std::pair{2, 2}, std::pair{3, 3}, std::pair{2, 5}, std::pair{4, 3}, std::pair{5, 5}}) {
    generators::MiuraParams mp;
    mp.rows = r;
    mp.cols = c;
    mp.alpha = 55 * std::numbers::pi / 180;
    const CreasePattern p = generators::miura_ori(mp);
    AssignmentEnumerationOptions o;
    o.max_verdicts = 0;
    const AssignmentEnumeration e = enumerate_assignments(p, build_topology(p), o);
    ASSERT_TRUE(e.complete);
    EXPECT_EQ(e.assignments, grid_three_colourings(r, c) / 3) << r << "x" << c;
    std::printf("[ count ] Miura %dx%d: %ld assignments, %ld classes, %.3f s\n", r, c, e.assignments, e.class_count,
                e.seconds);
  }
}

}}  // namespace
}  // namespace rigidfold
