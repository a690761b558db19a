// `rigidfold thick` (app/command_thick.cpp): the bundled 4 x 4 Miura-ori with Bennett hinge
// heights folds with one DOF along the zero-thickness motion, with hinges on the valley side
// it is rigid (DOF 0, every vertex off the zero-thickness motion), with hinges on the top face
// it folds as at zero thickness; the Type 3 square twist has Bennett heights only against its
// letters (--reverse); the thick sheet and the slabs are written; bad input exits 2
// naming the flag or file; the JSON ends with the provenance.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

const std::string kSource = std::string(RIGIDFOLD_SOURCE_DIR) + "/";
const std::string kMiura = kSource + "data/bundled/miura_4x4_alpha60.fold";

nlohmann::ordered_json run_json(const std::string& args) {
  const auto r = test::run_command(test::cli() + " thick " + args + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::ordered_json::parse(r.out);
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_thick_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// A 2 x 3 Miura-ori (two interior vertices sharing a crease), generated once.
const std::string& small_miura() {
  static const std::string path = [] {
    const std::string p = (fs::temp_directory_path() / ("rigidfold_thick_miura23_" + std::to_string(::getpid()) + ".fold")).string();
    const auto r = test::run_command(test::cli() + " generate miura --rows 2 --cols 3 --out " + p);
    EXPECT_EQ(r.status, 0) << r.err;
    return p;
  }();
  return path;
}

TEST(ThickCli, BennettMiuraFollowsTheZeroThicknessMotionWithOneDof) {
  const auto j = run_json(kMiura + " --thickness 0.05 --hinges bennett");
  EXPECT_EQ(j["hinges"], "bennett");
  EXPECT_EQ(j["flat_state"]["dof"].get<int>(), 1);
  EXPECT_GT(j["flat_state"]["smallest_kept_singular_value"].get<double>(), 1e3 * j["flat_state"]["rank_cut"].get<double>());
  EXPECT_TRUE(j["flat_state"]["locked_vertices"].empty());
  EXPECT_TRUE(j["flat_state"]["off_motion_vertices"].empty());
  EXPECT_EQ(j["flat_state"]["vertices"].size(), 9u);
  const auto& steps = j["trace"]["steps"];
  ASSERT_GE(steps.size(), 5u);
  EXPECT_EQ(steps.size(), j["zero_thickness"]["states"].get<std::size_t>());
  EXPECT_LE(j["trace"]["max_deviation_rad"].get<double>(), 1e-10);
  for (const auto& s : steps) {
    EXPECT_LE(s["residual"].get<double>(), 1e-10);
    EXPECT_LE(s["deviation_rad"].get<double>(), 1e-10);
    EXPECT_EQ(s["dof"].get<int>(), 1);
  }
  EXPECT_GT(std::abs(steps.back()["drive_deg"].get<double>()), 45.0);
  // The provenance closes the document, as for every command.
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(std::prev(j.end()).key(), "provenance");
  EXPECT_EQ(j["provenance"]["command"], "thick");
}

TEST(ThickCli, BennettSquareTwistFoldsAgainstItsLettersOnly) {
  const std::string twist = scratch("twist3.fold").string();
  const auto g = test::run_command(test::cli() + " generate square-twist --type 3 --out " + twist);
  ASSERT_EQ(g.status, 0) << g.err;
  const auto along = test::run_command(test::cli() + " thick " + twist + " --thickness 0.05");
  EXPECT_EQ(along.status, 2);
  EXPECT_NE(along.err.find("--hinges: no Bennett hinge heights"), std::string::npos) << along.err;
  const auto j = run_json(twist + " --thickness 0.05 --reverse");
  EXPECT_EQ(j["zero_thickness"]["direction"], "against the letters");
  EXPECT_EQ(j["flat_state"]["dof"].get<int>(), 1);
  EXPECT_EQ(j["flat_state"]["vertices"].size(), 4u);
  EXPECT_TRUE(j["flat_state"]["off_motion_vertices"].empty());
  ASSERT_GE(j["trace"]["steps"].size(), 5u);
  EXPECT_LE(j["trace"]["max_deviation_rad"].get<double>(), 1e-10);
  EXPECT_LE(j["trace"]["max_residual"].get<double>(), 1e-10);
}

TEST(ThickCli, ValleySideHingesMakeTheMiuraRigid) {
  const auto j = run_json(kMiura + " --thickness 0.05 --hinges valley");
  EXPECT_EQ(j["flat_state"]["dof"].get<int>(), 0);
  EXPECT_GT(j["flat_state"]["smallest_kept_singular_value"].get<double>(), 1e3 * j["flat_state"]["rank_cut"].get<double>());
  EXPECT_EQ(j["flat_state"]["off_motion_vertices"].size(), 9u);
  for (const auto& v : j["flat_state"]["vertices"]) EXPECT_GT(v["off_motion_residual"].get<double>(), 1e-4);
  EXPECT_TRUE(j["trace"]["steps"].empty());
  EXPECT_TRUE(j["trace"].contains("note"));
}

TEST(ThickCli, TopHingesKeepTheZeroThicknessKinematics) {
  const auto j = run_json(kMiura + " --thickness 0.05 --hinges top");
  EXPECT_TRUE(j["flat_state"]["locked_vertices"].empty());
  EXPECT_TRUE(j["flat_state"]["off_motion_vertices"].empty());
  ASSERT_FALSE(j["trace"]["steps"].empty());
  EXPECT_LE(j["trace"]["max_deviation_rad"].get<double>(), 1e-10);
  for (const auto& h : j["hinge_heights"]) EXPECT_EQ(h.get<double>(), 0.05);
}

// Slab interference along the path and stacking at its end (kernel/thick/slab_interference.hpp,
// stacking_order.hpp): hinges on the top face make the slabs interpenetrate across a mountain
// crease at the first folded state; the JSON carries the first pair, its state and crease,
// and the stacking at the end of the path (180 deg).
TEST(ThickCli, ReportsSlabInterferenceAndTheStackingAtTheEnd) {
  const auto input = nlohmann::json::parse(std::ifstream(kMiura));
  const auto top = run_json(kMiura + " --thickness 0.05 --hinges top");
  const auto& in = top["slab_interference"];
  EXPECT_FALSE(in["passed"].get<bool>());
  EXPECT_TRUE(in["states"][0]["pairs"].empty());  // flat: slabs only touch
  ASSERT_TRUE(in.contains("first"));
  EXPECT_EQ(in["first"]["state"].get<int>(), 1);
  EXPECT_EQ(in["first"]["drive_deg"].get<double>(), top["trace"]["steps"][0]["drive_deg"].get<double>());
  ASSERT_FALSE(in["first"]["shared_crease"].is_null());
  const int crease = in["first"]["shared_crease"].get<int>();
  EXPECT_EQ(input["edges_assignment"][crease], "M");
  EXPECT_LT(in["first"]["shared_crease_fold_deg"].get<double>(), 0.0);
  EXPECT_EQ(in["states"].size(), in["states_checked"].get<std::size_t>());
  EXPECT_GT(in["collisions"].get<long long>(), 0);
  EXPECT_TRUE(top["stacking"]["flat_folded"].get<bool>());
  EXPECT_GT(top["stacking"]["letter_disagreements"].get<int>(), 0);

  // Bennett heights as slabs (kernel test: thick_geometry_test.cpp): the first collision is
  // across a crease whose hinge sits on the face away from its fold (a valley's on the bottom,
  // at height 0, or a mountain's on the top), and at 180 deg the zig-zag creases' hinges, steps
  // between their panels, turn each panel onto its neighbour's level.
  const auto bennett = run_json(kMiura + " --thickness 0.05 --hinges bennett");
  const auto& bi = bennett["slab_interference"];
  EXPECT_FALSE(bi["passed"].get<bool>());
  EXPECT_EQ(bi["first"]["state"].get<int>(), 1);
  ASSERT_FALSE(bi["first"]["shared_crease"].is_null());
  double highest = 0;
  for (const auto& h : bennett["hinge_heights"]) highest = std::max(highest, h.get<double>());
  const int first = bi["first"]["shared_crease"].get<int>();
  const double h = bennett["hinge_heights"][first].get<double>();
  const std::string letter = input["edges_assignment"][first];
  EXPECT_TRUE((letter == "V" && std::abs(h) <= 1e-9) || (letter == "M" && std::abs(h - highest) <= 1e-9)) << letter << " " << h;
  EXPECT_FALSE(bennett["trace"]["extension"].empty());
  EXPECT_EQ(std::abs(bennett["stacking"]["at_drive_deg"].get<double>()), 180.0);
  EXPECT_EQ(bennett["stacking"]["end_of"], "extension");
  EXPECT_TRUE(bennett["stacking"]["flat_folded"].get<bool>());
  int level = 0, disagree = 0;
  for (const auto& c : bennett["stacking"]["creases"]) {
    level += c["b_side_of_a"] == "level" ? 1 : 0;
    disagree += c["agrees_with_letter"].get<bool>() ? 0 : 1;
  }
  EXPECT_GT(level, 0);
  EXPECT_EQ(bennett["stacking"]["letter_disagreements"].get<int>(), disagree);
  EXPECT_LT(disagree, static_cast<int>(bennett["stacking"]["creases"].size()));
  EXPECT_EQ(bennett["stacking"]["panels_bottom_to_top"].size(), input["faces_vertices"].size());
  EXPECT_LT(bennett["stacking"]["min_gap"].get<double>(), 0.0);
}

// The sign of the driving crease's fold on the traced motion (its letter's direction).
std::string signed_deg(double magnitude) {
  const auto j = run_json(small_miura() + " --thickness 0.05");
  const double last = j["trace"]["steps"].back()["drive_deg"].get<double>();
  return std::to_string(last > 0 ? magnitude : -magnitude);
}

TEST(ThickCli, WritesTheThickSheetAndTheSlabs) {
  const fs::path fold = scratch("thick.fold"), stl = scratch("slabs.stl");
  const std::string at = signed_deg(40);
  const auto j = run_json(small_miura() + " --thickness 0.05 --out " + fold.string() + " --stl " + stl.string() + " --at=" + at);
  const auto doc = nlohmann::json::parse(std::ifstream(fold));
  const std::size_t faces = doc["faces_vertices"].size(), edges = doc["edges_vertices"].size();
  EXPECT_EQ(faces, 6u);
  ASSERT_EQ(doc["rigidfold:thickness"].size(), faces);
  for (const auto& t : doc["rigidfold:thickness"]) EXPECT_GT(t.get<double>(), 0.0);
  ASSERT_EQ(doc["rigidfold:hinge_heights"].size(), edges);
  const auto input = nlohmann::json::parse(std::ifstream(small_miura()));
  const std::size_t flat_edges = input["edges_vertices"].size();
  for (std::size_t e = 0; e < edges; ++e) EXPECT_EQ(doc["rigidfold:hinge_heights"][e].is_null(), e >= flat_edges) << e;
  for (std::size_t e = 0; e < flat_edges; ++e)
    EXPECT_EQ(doc["rigidfold:hinge_heights"][e].get<double>(), j["hinge_heights"][e].get<double>());
  // Binary STL: 6 parallelogram slabs, each 2 quads (2 triangles) + 4 walls (2 triangles).
  std::ifstream in(stl, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  const std::string s = bytes.str();
  ASSERT_GE(s.size(), 84u);
  std::uint32_t count = 0;
  std::memcpy(&count, s.data() + 80, 4);
  EXPECT_EQ(count, 6u * 12u);
  EXPECT_EQ(s.size(), 84u + 50u * count);
  EXPECT_NE(s.rfind("solid", 0), 0u);  // not mistaken for ASCII STL
  EXPECT_EQ(std::abs(j["stl"]["drive_deg"].get<double>()), 40.0);
  EXPECT_LE(j["stl"]["residual"].get<double>(), 1e-10);
  EXPECT_LE(j["stl"]["relative_mismatch"].get<double>(), 1e-9);
  // The closed slabs enclose volume panels x area x thickness at any fold (divergence theorem).
  double volume = 0;
  for (std::uint32_t k = 0; k < count; ++k) {
    float v[9];
    std::memcpy(v, s.data() + 84 + 50 * k + 12, 36);
    volume += (v[0] * (v[4] * v[8] - v[5] * v[7]) - v[1] * (v[3] * v[8] - v[5] * v[6]) + v[2] * (v[3] * v[7] - v[4] * v[6])) / 6.0;
  }
  // Faces of the sheet are the input's faces in the same order but one (the lead face first),
  // and every panel of the bundled Miura has the same area: volume = area x sum of thicknesses.
  const auto& xy = input["vertices_coords"];
  const auto& f0 = input["faces_vertices"][0];
  double area = 0;
  for (std::size_t i = 0; i < f0.size(); ++i) {
    const auto& a = xy[f0[i].get<int>()];
    const auto& b = xy[f0[(i + 1) % f0.size()].get<int>()];
    area += 0.5 * (a[0].get<double>() * b[1].get<double>() - a[1].get<double>() * b[0].get<double>());
  }
  double expected = 0;
  for (const auto& t : doc["rigidfold:thickness"]) expected += t.get<double>();
  expected *= std::abs(area);
  EXPECT_NEAR(volume, expected, 1e-4 * expected);
  fs::remove_all(fold.parent_path());
}

TEST(ThickCli, BadInputExitsTwoNamingThePlace) {
  const fs::path copy = scratch("miura.fold");
  fs::copy_file(kMiura, copy, fs::copy_options::overwrite_existing);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {kMiura + " --thickness 0", "--thickness"},
      {kMiura + " --thickness -1", "--thickness"},
      {kMiura + " --thickness nan", "--thickness"},
      {kMiura + " --thickness inf", "--thickness"},
      {kMiura + " --thickness 1e6", "--thickness"},
      {kSource + "data/bundled/no_such_pattern.fold --thickness 0.05", "no_such_pattern.fold"},
      {kMiura + " --thickness 0.05 --hinges bogus", "--hinges"},
      {kSource + "data/bundled/miura_tube_6_alpha60.fold --thickness 0.05 --hinges top", "miura_tube_6_alpha60.fold: vertex"},
      {copy.string() + " --thickness 0.05 --out " + copy.string(), "--out"},
      {kMiura + " --thickness 0.05 --stl " + scratch("x.stl").string(), "--at"},
      {small_miura() + " --thickness 0.05 --stl " + scratch("x.stl").string() + " --at=" + signed_deg(120), "--at"},
      {small_miura() + " --thickness 0.05 --stl " + scratch("x.stl").string() + " --at=" + signed_deg(-10), "--at"},
      {kMiura + " --thickness 0.05 --hinges valley --stl " + scratch("x.stl").string() + " --at 10", "--at"},
  };
  for (const auto& [args, place] : cases) {
    const auto r = test::run_command(test::cli() + " thick " + args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(place), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(scratch("x.stl")));
  fs::remove_all(copy.parent_path());
}

}}  // namespace
}  // namespace rigidfold
