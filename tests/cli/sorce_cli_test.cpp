// `rigidfold sorce` (app/command_sorce.cpp): SORCE joints on the bundled 4 x 4 Miura-ori
// traced to the flat-folded state (its exact multiplier family; with --general the general
// solver): every folding crease gets a joint whose checks are within the bounds the JSON
// states, and on the exact path every crease stacks at t = 1 with no slab interference; --out writes one closed, outward STL
// per panel (each directed edge once and its reverse once) whose volumes add up to the
// assembled panels' at --at (a rigid placement keeps volume), a multi-frame FOLD that reads
// back, the pose table and the drawings; --optimize reports its search; bad input exits 2
// naming the flag, file or JSON pointer and writes nothing.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "kernel/pattern/fold_io.hpp"
#include "tests/support/run_command.hpp"
#include "tests/support/stl_mesh.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

const std::string kSource = std::string(RIGIDFOLD_SOURCE_DIR) + "/";
const std::string kMiura = kSource + "data/bundled/miura_4x4_alpha60.fold";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_sorce_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SorceCli, MiuraJointsPassTheirChecks) {
  const auto r = test::run_command(test::cli() + " sorce " + kMiura + " --thickness 0.05 --drive 4 --to=-180 --steps 30 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  int folding = 0;
  for (const auto& c : j["creases"]) {
    if (!c["folds"].get<bool>()) continue;
    ++folding;
    EXPECT_NEAR(c["arc_length"][0].get<double>(), c["arc_length"][1].get<double>(), 1e-10) << c["edge"];  // rolling without slip
  }
  EXPECT_EQ(folding, 24);
  for (const auto& [name, bound] : j["check_bounds"].items()) EXPECT_LE(j["checks"][name].get<double>(), bound.get<double>()) << name;
  EXPECT_EQ(j["path"]["model"], "multiplier-propagation");
  EXPECT_NEAR(j["path"]["final_drive_deg"].get<double>(), -180.0, 1e-12);
  EXPECT_TRUE(j["checks"]["flat_folded_end"].get<bool>());
  EXPECT_TRUE(j["checks"]["all_stack"].get<bool>());
  EXPECT_TRUE(j["checks"]["slab_interference"].empty());
  EXPECT_TRUE(j.contains("provenance"));
}

// --out on a 2 x 3 Miura-ori (the solids' swept clearances take minutes on the 4 x 4 under
// AddressSanitizer, and exercise nothing the smaller pattern does not).
TEST(SorceCli, OutWritesClosedPanelsFramesPosesAndDrawings) {
  const fs::path pattern = scratch("m23_out.fold");
  ASSERT_EQ(test::run_command(test::cli() + " generate miura --rows 2 --cols 3 --out " + pattern.string()).status, 0);
  const fs::path out = scratch("miura");
  fs::remove_all(out);
  const auto r = test::run_command(test::cli() + " sorce " + pattern.string() + " --thickness 0.05 --to=-180 --steps 30 --at 0.5 --json --out " +
                                   out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_EQ(j, nlohmann::ordered_json::parse(slurp(out / "sorce.json")));  // the file is what was printed
  EXPECT_FALSE(j.contains("stl_note")) << j["stl_note"];
  EXPECT_TRUE(j["checks"]["slab_interference"].empty());
  const int faces = 6;

  // One closed, outward STL per panel; together they fill what the assembly at t = 0.5 fills.
  double panels_volume = 0.0;
  ASSERT_EQ(j["out"]["panels"].size(), std::size_t(faces));
  for (const auto& f : j["out"]["panels"]) {
    const auto tris = testing::parse_stl(slurp(f.get<std::string>()));
    EXPECT_EQ(testing::open_or_misoriented_edges(tris), 0) << f;
    const double v = testing::enclosed_volume(tris);
    EXPECT_GT(v, 0.0) << f;
    panels_volume += v;
  }
  const auto assembled = testing::parse_stl(slurp(out / "panels_at.stl"));
  EXPECT_NEAR(testing::enclosed_volume(assembled), panels_volume, 1e-5 * panels_volume);

  // The frames read back as FOLD: the panels on their own, 11 frames (t = 0, 0.1, ..., 1).
  const CreasePattern frames = read_fold((out / "frames.fold").string());
  EXPECT_EQ(frames.num_faces(), faces);
  ASSERT_TRUE(frames.extra.contains("file_frames"));
  EXPECT_EQ(frames.extra["file_frames"].size(), 11u);
  EXPECT_EQ(frames.extra["file_frames"][5]["rigidfold:sorce_t"].get<double>(), 0.5);
  // Pose table: a header and one row per (t, face).
  const std::string csv = slurp(out / "poses.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 11 * faces);
  // Every folding crease's profiles are drawn, named by its edge.
  const std::string dxf = slurp(out / "profiles.dxf"), svg = slurp(out / "profiles.svg");
  for (const auto& c : j["creases"]) {
    if (!c["folds"].get<bool>()) continue;
    const std::string e = std::to_string(c["edge"].get<int>());
    EXPECT_NE(dxf.find("E" + e + "_LEFT"), std::string::npos) << e;
    EXPECT_NE(svg.find(">E" + e + "<"), std::string::npos) << e;
  }
  fs::remove_all(out);
  fs::remove(pattern);
}

// --general: the same joints on the general solver's path pass the same bounds.
TEST(SorceCli, GeneralSolverPathPassesTheChecks) {
  const auto r = test::run_command(test::cli() + " sorce " + kMiura + " --thickness 0.05 --drive 4 --to=-180 --steps 30 --general --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  EXPECT_NE(j["path"]["model"], "multiplier-propagation");
  for (const auto& [name, bound] : j["check_bounds"].items()) EXPECT_LE(j["checks"][name].get<double>(), bound.get<double>()) << name;
}

// --circular: vertex A's fold 2 (edge 1) rolls on arcs of radius T/2 (convexity 2/T).
TEST(SorceCli, CircularCreaseHasConvexityTwoOverThickness) {
  const auto r = test::run_command(test::cli() + " sorce " + kSource + "data/sorce/vertex_a.fold --thickness 0.1 --drive 1 --to 180 --circular 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  for (const auto& c : j["creases"]) {
    if (c["edge"] != 1) continue;
    for (const char* side : {"convexity_left", "convexity_right"})
      for (int k = 0; k < 2; ++k) EXPECT_NEAR(c[side][k].get<double>(), 20.0, 2e-8) << side;
  }
}

// --parameter: vertex A on the half-tangent (seed eq 35) and arc-length parameters passes the
// same checks, the JSON names the parameter, and the path's length in fold-angle space does not
// depend on the parameter.
TEST(SorceCli, PathParametersPassTheChecks) {
  double length = 0.0;
  for (const std::string name : {"drive", "arc-length", "half-tangent"}) {
    const auto r = test::run_command(test::cli() + " sorce " + kSource + "data/sorce/vertex_a.fold --thickness 0.1 --drive 1 --to 180 --parameter " + name + " --json");
    ASSERT_EQ(r.status, 0) << name << "\n" << r.err;
    const auto j = nlohmann::ordered_json::parse(r.out);
    std::string expected = name;
    std::replace(expected.begin(), expected.end(), '-', '_');
    EXPECT_EQ(j["path"]["parameter"], expected);
    for (const auto& [check, bound] : j["check_bounds"].items())
      EXPECT_LE(j["checks"][check].get<double>(), bound.get<double>()) << name << " " << check;
    const double l = j["path"]["arc_length_deg"].get<double>();
    if (length == 0.0) length = l;
    EXPECT_NEAR(l, length, 1e-9 * length) << name;
  }
}

TEST(SorceCli, OptimizeReportsItsSearch) {
  const fs::path pattern = scratch("m23.fold");
  ASSERT_EQ(test::run_command(test::cli() + " generate miura --rows 2 --cols 3 --out " + pattern.string()).status, 0);
  // A small budget: the search stops at it and says how far it went.
  const auto r = test::run_command(test::cli() + " sorce " + pattern.string() + " --thickness 0.05 --to=-180 --optimize --max-evaluations 12 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::ordered_json::parse(r.out);
  const auto& o = j["optimization"];
  EXPECT_EQ(o["algorithm"], "LN_COBYLA");
  EXPECT_GT(o["evaluations"].get<int>(), 1);
  EXPECT_LE(o["evaluations"].get<int>(), 12);
  EXPECT_EQ(o["coefficients"].size(), 3 * o["faces"].size());
  fs::remove(pattern);
}

// --split on the bird's-foot vertex's collinear folds (eq 61's shape, d = 0.04 t^2): the
// split creases' profiles change (arc length), the others do not, and the vertex still closes
// at the knots with the split translations included.
TEST(SorceCli, SplitCollinearFoldsOfTheBirdsFootVertex) {
  const std::string vertex_b = kSource + "data/sorce/vertex_b.fold --thickness 0.1 --drive 1 --to 180 --json";
  const auto plain = test::run_command(test::cli() + " sorce " + vertex_b);
  const auto split = test::run_command(test::cli() + " sorce " + vertex_b + " --split 0:quadratic:0.04 --split 2:quadratic:0.04");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(split.status, 0) << split.err;
  const nlohmann::json a = nlohmann::json::parse(plain.out), b = nlohmann::json::parse(split.out);
  EXPECT_LE(b["checks"]["closure_knots"].get<double>(), 1e-12);
  for (std::size_t k = 0; k < b["creases"].size(); ++k) {
    const int edge = b["creases"][k]["edge"].get<int>();
    const double la = a["creases"][k]["arc_length"][0].get<double>(), lb = b["creases"][k]["arc_length"][0].get<double>();
    if (edge == 0 || edge == 2)
      EXPECT_GT(std::abs(lb - la), 1e-3) << "edge " << edge;
    else
      EXPECT_NEAR(lb, la, 1e-12) << "edge " << edge;
  }
}

TEST(SorceCli, BadInputExitsTwoNamingThePlaceAndWritesNothing) {
  const fs::path out = scratch("never");
  fs::remove_all(out);
  auto spec = [](const std::string& name, const std::string& text) {
    const fs::path p = scratch(name);
    std::ofstream(p) << text;
    return p.string();
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {kMiura + " --thickness 0", "--thickness"},
      {kMiura + " --thickness nan", "--thickness"},
      {kMiura + " --thickness 0.05 --at 0.5", "--at"},
      {kMiura + " --thickness 0.05 --at 2 --out " + out.string(), "--at"},
      {kMiura + " --thickness 0.05 --epsilon 0.1", "--optimize"},
      {kMiura + " --thickness 0.05 --max-evaluations 5", "--optimize"},
      {kMiura + " --thickness 0.05 --optimize --max-evaluations 0", "--max-evaluations"},
      {kMiura + " --thickness 0.05 --drive 999", "--drive"},
      {kMiura + " --thickness 0.05 --steps 3", "--steps"},
      {kMiura + " --thickness 0.05 --to 0", "--to"},
      {kMiura + " --thickness 0.05 --parameter arclength", "--parameter"},
      {kMiura + " --thickness 0.05 --offsets " + spec("a.json", "{\"end_offset\": []}") + " --out " + out.string(), "a.json: /end_offset"},
      {kMiura + " --thickness 0.05 --offsets " + spec("b.json", "{\"end_offsets\": [1, 2]}") + " --out " + out.string(), "b.json: /end_offsets"},
      {kMiura + " --thickness 0.05 --offsets " + spec("c.json", "{\"coefficients\": [[1, \"x\"]]}"), "c.json: /coefficients"},
      {kMiura + " --thickness 0.05 --offsets " + spec("d.json", "[1,"), "d.json"},
      {kMiura + " --thickness 0.05 --offsets " + scratch("missing.json").string(), "missing.json"},
      {kSource + "data/sorce/vertex_a.fold --thickness 0.1 --offsets " + spec("e.json", "{\"end_offsets\": [1e301, 0, 0, 0]}"), "e.json: /end_offsets/0"},
      {kSource + "data/sorce/vertex_a.fold --thickness 0.1 --offsets " + spec("f.json", "{\"coefficients\": [[], [101], [], []]}"), "f.json: /coefficients/1/0"},
      {kMiura + " --thickness 0.05 --out " + kMiura, "--out"},
      {kMiura + " --thickness 0.05 --circular 0", "--circular [0]"},
      {kMiura + " --thickness 0.05 --circular x", "--circular"},
      {kSource + "data/bundled/miura_12x12_folded.fold --thickness 0.05", "miura_12x12_folded.fold"},
      {kSource + "data/sorce/vertex_b.fold --thickness 0.1 --split 9:linear:0.1", "--split 9:linear:0.1"},
      {kSource + "data/sorce/vertex_b.fold --thickness 0.1 --split 0:cubic:1", "--split 0:cubic:1"},
      {kSource + "data/sorce/vertex_b.fold --thickness 0.1 --split 0:linear:1e7", "--split 0:linear:1e7"},
      {kSource + "data/sorce/vertex_b.fold --thickness 0.1 --split x --out " + out.string(), "--split x"},
  };
  for (const auto& [args, place] : cases) {
    const auto r = test::run_command(test::cli() + " sorce " + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(place), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(out.parent_path());
}

}}  // namespace
}  // namespace rigidfold
