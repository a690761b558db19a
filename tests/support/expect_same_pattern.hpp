#pragma once
// Field-by-field comparison of two crease patterns, for round-trip tests: everything
// exact except fold angles, which pass through degrees and may differ in the last bits.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::test {

inline void expect_same_pattern(const CreasePattern& a, const CreasePattern& b, double angle_tolerance) {
  EXPECT_EQ(b.vertices, a.vertices);
  EXPECT_EQ(b.coords_2d, a.coords_2d);
  EXPECT_EQ(b.edges, a.edges);
  EXPECT_EQ(b.assignments, a.assignments);
  EXPECT_EQ(b.faces, a.faces);
  EXPECT_EQ(b.extra, a.extra);  // unknown and non-modelled spec keys, including file_frames
  ASSERT_EQ(b.fold_angles.size(), a.fold_angles.size());
  for (std::size_t e = 0; e < a.fold_angles.size(); ++e) {
    // FOLD 1.2 numbers: a B, F or J edge with no angle is written as 0 (it cannot fold).
    const Assignment k = a.assignments[e];
    if (!a.fold_angles[e] && (k == Assignment::Boundary || k == Assignment::Flat || k == Assignment::Join) &&
        b.fold_angles[e]) {
      EXPECT_EQ(*b.fold_angles[e], 0.0) << "edge " << e;
      continue;
    }
    ASSERT_EQ(b.fold_angles[e].has_value(), a.fold_angles[e].has_value()) << "edge " << e;
    if (a.fold_angles[e]) {
      EXPECT_NEAR(*b.fold_angles[e], *a.fold_angles[e], angle_tolerance) << "edge " << e;
    }
  }
}

}  // namespace rigidfold::test
