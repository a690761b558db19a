// The bad-input table: malformed FOLD files, each rejected with a message that names the
// place (JSON path), by the library (InputError) and by the CLI (exit 2, one line on
// stderr naming the file, no crash). The ASan/UBSan build in CI runs the same table.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct BadCase {
  const char* name;
  const char* text;
  const char* expected;  // must appear in the message: the place, then the reason
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

// A unit square split by its diagonal, the base most cases break.
#define SQUARE_V "\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1]]"
#define SQUARE_E "\"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[0,2]]"
#define SQUARE_A "\"edges_assignment\": [\"B\",\"B\",\"B\",\"B\",\"V\"]"

const BadCase kCases[] = {
    {"empty_file", "", "file is empty"},
    {"whitespace_only", "  \n\t ", "file is empty"},
    {"truncated_json", "{\"vertices_coords\": [[0,0],[1,0]", "not valid JSON"},
    {"top_level_array", "[[0,0],[1,0]]", "top level must be a JSON object"},
    {"missing_vertices", "{" SQUARE_E "}", "vertices_coords: missing"},
    {"vertices_wrong_type", "{\"vertices_coords\": \"square\", " SQUARE_E "}", "vertices_coords: must be an array"},
    {"coordinate_is_string", "{\"vertices_coords\": [[0,0],[1,\"0\"],[1,1],[0,1]], " SQUARE_E "}", "vertices_coords[1][1]: must be a number"},
    {"coordinate_overflow_inf", "{\"vertices_coords\": [[0,0],[1e400,0],[1,1],[0,1]], " SQUARE_E "}", "not valid JSON"},
    {"nan_literal", "{\"vertices_coords\": [[0,0],[NaN,0],[1,1],[0,1]], " SQUARE_E "}", "not valid JSON"},
    {"four_coordinates", "{\"vertices_coords\": [[0,0],[1,0,0,0],[1,1],[0,1]], " SQUARE_E "}", "vertices_coords[1]: has 4 coordinates"},
    {"dangling_vertex_index", "{" SQUARE_V ", \"edges_vertices\": [[0,1],[1,2],[2,9],[3,0]]}", "edges_vertices[2][1]: vertex index 9 out of range"},
    {"negative_index", "{" SQUARE_V ", \"edges_vertices\": [[0,1],[1,-2],[2,3],[3,0]]}", "edges_vertices[1][1]: index -2 is negative"},
    {"edge_not_a_pair", "{" SQUARE_V ", \"edges_vertices\": [[0,1],[1,2,3],[2,3],[3,0]]}", "edges_vertices[1]: must be a pair"},
    {"self_loop_edge", "{" SQUARE_V ", \"edges_vertices\": [[0,1],[1,2],[2,2],[2,3],[3,0]]}", "edges_vertices[2]: edge joins vertex 2 to itself"},
    {"duplicate_edge", "{" SQUARE_V ", \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[0,2],[2,0]]}", "edges_vertices[5]: duplicate of edge 4"},
    {"zero_length_edge", "{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1],[1,1]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[2,4]]}",
     "edges_vertices[4]: zero-length edge"},
    {"unknown_assignment", "{" SQUARE_V ", " SQUARE_E ", \"edges_assignment\": [\"B\",\"B\",\"B\",\"B\",\"X\"]}",
     "edges_assignment[4]: unknown assignment \"X\""},
    {"assignment_not_string", "{" SQUARE_V ", " SQUARE_E ", \"edges_assignment\": [\"B\",\"B\",\"B\",\"B\",1]}", "edges_assignment[4]: must be a one-letter string"},
    {"assignment_length", "{" SQUARE_V ", " SQUARE_E ", \"edges_assignment\": [\"B\",\"B\"]}", "edges_assignment: has 2 entries but there are 5 edges"},
    {"fold_angle_out_of_range", "{" SQUARE_V ", " SQUARE_E ", " SQUARE_A ", \"edges_foldAngle\": [0,0,0,0,270]}", "edges_foldAngle[4]: fold angle"},
    {"fold_angle_string", "{" SQUARE_V ", " SQUARE_E ", " SQUARE_A ", \"edges_foldAngle\": [0,0,0,0,\"90\"]}", "edges_foldAngle[4]: must be a number"},
    {"face_too_small", "{" SQUARE_V ", " SQUARE_E ", \"faces_vertices\": [[0,1],[0,2,3]]}", "faces_vertices[0]: a face needs at least 3 vertices"},
    {"face_index_out_of_range", "{" SQUARE_V ", " SQUARE_E ", \"faces_vertices\": [[0,1,2],[0,2,7]]}", "faces_vertices[1][2]: vertex index 7 out of range"},
    {"face_not_closed_loop", "{" SQUARE_V ", \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0]], \"faces_vertices\": [[0,1,2],[0,2,3]]}",
     "faces_vertices[0]: side 2-0 is not an edge"},
    {"face_repeats_vertex", "{" SQUARE_V ", " SQUARE_E ", \"faces_vertices\": [[0,1,2,1],[0,2,3]]}", "faces_vertices[0]: face visits a vertex twice"},
    {"faces_inconsistently_oriented", "{" SQUARE_V ", " SQUARE_E ", \"faces_vertices\": [[0,1,2],[0,3,2]]}", "faces_vertices[1]: face is oriented opposite"},
    {"non_manifold_edge",
     "{\"vertices_coords\": [[0,0,0],[1,0,0],[0.5,1,0],[0.5,-1,0],[0.5,0,1]], \"edges_vertices\": [[0,1],[1,2],[2,0],[1,3],[3,0],[1,4],[4,0]],"
     " \"faces_vertices\": [[0,1,2],[1,0,3],[0,1,4]]}",
     "is shared by more than two faces (non-manifold)"},
    {"overlapping_faces_crossing_edges",
     "{\"vertices_coords\": [[0,0],[2,0],[2,2],[0,2],[1,1],[3,1],[3,3],[1,3]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[4,5],[5,6],[6,7],[7,4]],"
     " \"faces_vertices\": [[0,1,2,3],[4,5,6,7]]}",
     "crosses edge"},
    {"overlapping_faces_same_region", "{" SQUARE_V ", \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0]], \"faces_vertices\": [[0,1,2,3],[0,1,2,3]]}",
     "same direction"},
    {"vertex_on_edge", "{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1],[0.5,0.5]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[0,2],[1,4]]}",
     "lies on this edge"},
    {"dangling_crease", "{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1],[0.5,0.4]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[0,4]]}",
     "dangling edge"},
    {"edge_on_no_face", "{\"vertices_coords\": [[0,0],[1,0],[1,1],[0,1],[3,3],[4,4]], \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[0,2],[4,5]],"
                        " \"faces_vertices\": [[0,1,2],[0,2,3]]}",
     "edges_vertices[5]: edge lies on no face"},
    {"file_frames_not_array", "{" SQUARE_V ", " SQUARE_E ", \"file_frames\": {}}", "file_frames: must be an array"},
    {"non_planar_without_faces", "{\"vertices_coords\": [[0,0,0],[1,0,0],[1,1,0.3],[0,1,0]], " SQUARE_E "}", "vertices do not lie in one plane"},
};

class BadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadInput, LibraryThrowsInputErrorNamingThePlace) {
  const BadCase& c = GetParam();
  try {
    parse_fold(c.text, "bad.fold");
    FAIL() << c.name << ": accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad.fold"), std::string::npos) << msg;
    EXPECT_NE(msg.find(c.expected), std::string::npos) << c.name << ": got \"" << msg << "\"";
  }
}

TEST_P(BadInput, CliExitsTwoWithOneLine) {
  const BadCase& c = GetParam();
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_bad_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / (std::string(c.name) + ".fold");
  std::ofstream(path) << c.text;
  const auto r = test::run_command(test::cli() + " info " + path.string());
  EXPECT_EQ(r.status, 2) << c.name << " stderr: " << r.err;
  EXPECT_NE(r.err.find(path.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Table, BadInput, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(BadInputCli, MissingFileAndBadFlagsExitTwo) {
  auto r = test::run_command(test::cli() + " info /nonexistent/x.fold");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent/x.fold: cannot open file"), std::string::npos) << r.err;
  r = test::run_command(test::cli() + " info");
  EXPECT_EQ(r.status, 2);
  r = test::run_command(test::cli() + " no-such-command");
  EXPECT_EQ(r.status, 2);
}

}}  // namespace
}  // namespace rigidfold
