// FOLD reading/writing: round trip of every modelled and unknown key, and the corpus of
// files written by other tools (tests/data/corpus).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/expect_same_pattern.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

const char* kSquareWithDiagonal = R"({
  "file_spec": 1.2, "file_creator": "hand", "file_classes": ["singleModel"],
  "frame_classes": ["creasePattern"], "vendor:custom": {"keep": [1, 2, 3]},
  "vertices_coords": [[0,0],[1,0],[1,1],[0,1]],
  "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],
  "edges_assignment": ["B","B","B","B","V"],
  "edges_foldAngle": [0, 0, 0, 0, 37.5],
  "faces_vertices": [[0,1,2],[0,2,3]],
  "file_frames": [{"frame_parent": 0, "frame_inherit": true, "frame_classes": ["foldedForm"],
                    "vertices_coords": [[0,0,0],[1,0,0],[1,1,0],[0.2,0.8,0.5]]}]
})";

TEST(FoldIo, RoundTripKeepsModelledAndUnknownKeys) {
  const CreasePattern a = parse_fold(kSquareWithDiagonal, "square.fold");
  ASSERT_EQ(a.num_vertices(), 4);
  ASSERT_EQ(a.num_edges(), 5);
  ASSERT_EQ(a.num_faces(), 2);
  EXPECT_FALSE(a.faces_derived);
  EXPECT_NEAR(*a.fold_angles[4], to_radians(37.5), 1e-16);

  const std::string text = write_fold_string(a);
  const CreasePattern b = parse_fold(text, "roundtrip.fold");
  test::expect_same_pattern(a, b, 4e-16 * to_radians(37.5));
  EXPECT_EQ(b.extra["vendor:custom"]["keep"][2], 3);
  EXPECT_EQ(b.extra["file_frames"][0]["frame_classes"][0], "foldedForm");
  // A second round trip is byte-identical: writing is a fixed point.
  EXPECT_EQ(write_fold_string(b), text);
}

TEST(FoldIo, DerivesFacesWhenMissing) {
  const char* text = R"({"vertices_coords": [[0,0],[2,0],[2,1],[0,1],[1,0],[1,1]],
    "edges_vertices": [[0,4],[4,1],[1,2],[2,5],[5,3],[3,0],[4,5]],
    "edges_assignment": ["B","B","B","B","B","B","M"]})";
  const CreasePattern p = parse_fold(text, "two-squares.fold");
  EXPECT_TRUE(p.faces_derived);
  ASSERT_EQ(p.num_faces(), 2);
  for (const auto& f : p.faces) {
    EXPECT_EQ(f.size(), 4u);
    EXPECT_GT(newell_normal(p, f).z(), 0.0);  // counter-clockwise
  }
}

TEST(FoldIo, MissingAssignmentsAreFilledFromFaces) {
  const char* text = R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]]})";
  const CreasePattern p = parse_fold(text, "x.fold");
  EXPECT_EQ(p.assignments[0], Assignment::Boundary);
  EXPECT_EQ(p.assignments[4], Assignment::Unassigned);
}

TEST(FoldIo, ClockwiseFacesAreReversedWithWarning) {
  const char* text = R"({"vertices_coords": [[0,0],[1,0],[1,1],[0,1]],
    "edges_vertices": [[0,1],[1,2],[2,3],[3,0],[0,2]],
    "faces_vertices": [[0,2,1],[0,3,2]]})";
  const CreasePattern p = parse_fold(text, "cw.fold");
  for (const auto& f : p.faces) EXPECT_GT(newell_normal(p, f).z(), 0.0);
  EXPECT_FALSE(p.warnings.empty());
}

TEST(FoldIo, WriteIsAtomicAndLeavesNoFileOnFailure) {
  const CreasePattern p = parse_fold(kSquareWithDiagonal, "square.fold");
  const std::string bad = "/nonexistent-dir/out.fold";
  EXPECT_THROW(write_fold(p, bad), InputError);
  EXPECT_FALSE(std::filesystem::exists(bad));
  const auto dir = std::filesystem::temp_directory_path() / "rigidfold_io_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / "ok.fold").string();
  write_fold(p, path);
  EXPECT_EQ(read_fold(path).num_edges(), 5);
  std::filesystem::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
