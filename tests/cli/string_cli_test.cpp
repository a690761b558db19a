// `rigidfold string forward|design`: outputs, verification by the general solver, and
// exit 2 with the file and JSON path on bad input, leaving no output file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "kernel/pattern/fold_io.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

std::string data(const std::string& name) { return std::string(RIGIDFOLD_SOURCE_DIR) + "/data/strings/" + name; }

fs::path temp_dir() {
  const fs::path d = fs::temp_directory_path() / ("rigidfold_string_cli_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::string write_file(const std::string& name, const std::string& text) {
  const fs::path p = temp_dir() / name;
  std::ofstream(p) << text;
  return p.string();
}

TEST(StringCli, ForwardWritesTheFoldedFoldAndNamesTheDrivenCrease) {
  const std::string out = (temp_dir() / "forward.fold").string();
  const auto r = test::run_command(test::cli() + " string forward " + data("forward_spec.json") + " --theta 30 --json --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["driven_crease"]["edge"].get<int>(), 0);
  EXPECT_DOUBLE_EQ(j["driven_crease"]["fold_angle_deg"].get<double>(), 60.0);
  ASSERT_EQ(j["vertices"].size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_DOUBLE_EQ(j["vertices"][i]["theta_deg"].get<double>(), i % 2 ? -30.0 : 30.0);
  EXPECT_LE(j["shared_crease_mismatch_deg"].get<double>(), 1e-12);
  EXPECT_LE(j["placement_mismatch"].get<double>(), 1e-12);
  // The folded frame puts the spine vertices (ids 0..N+1) where the closed form says.
  const auto doc = nlohmann::json::parse(read_text_file(out));
  const auto& frame = doc["file_frames"][0];
  EXPECT_EQ(frame["frame_classes"][0], "foldedForm");
  for (std::size_t k = 0; k < 8; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(frame["vertices_coords"][k][c].get<double>(), j["spine"][k][c].get<double>(), 1e-12);
  // Text mode states the driven crease too.
  const auto t = test::run_command(test::cli() + " string forward " + data("forward_spec.json") + " --theta 30");
  EXPECT_NE(t.out.find("driven crease: edge 0"), std::string::npos);
}

TEST(StringCli, IndependentModeReportsTheSharedCreaseMismatch) {
  const auto r = test::run_command(test::cli() + " string forward " + data("independent_spec.json") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mode"], "independent");
  EXPECT_NEAR(j["shared_crease_mismatch_deg"].get<double>(), 100.0, 1e-9);  // 2 * 25 - (-2 * 25)
}

TEST(StringCli, DesignDeflectionsVerifiedByTheGeneralSolver) {
  const std::string out = (temp_dir() / "defl.fold").string(), svg = (temp_dir() / "defl.svg").string();
  const auto r = test::run_command(test::cli() + " string design " + data("target_deflections.json") + " --json --out " + out +
                                   " --svg " + svg);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& v : j["vertices"]) {
    EXPECT_TRUE(v["feasible"].get<bool>());
    EXPECT_LE(std::fabs(v["phi_residual_deg"].get<double>()), 1e-10);
    EXPECT_LE(std::fabs(v["psi_residual_deg"].get<double>()), 1e-10);
  }
  EXPECT_TRUE(j["verification"]["converged"].get<bool>());
  EXPECT_LE(j["verification"]["max_angle_difference_rad"].get<double>(), 1e-10);
  EXPECT_NO_THROW(read_fold(out));
  EXPECT_NE(read_text_file(svg).find("<svg"), std::string::npos);
}

TEST(StringCli, DesignTrajectoriesWithCeres) {
  const std::string out = (temp_dir() / "traj.fold").string();
  const auto r = test::run_command(test::cli() + " string design " + data("target_trajectories.json") + " --json --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["method"].get<std::string>().find("Ceres"), std::string::npos);
  EXPECT_EQ(j["vertices"].size(), 2u);
  EXPECT_TRUE(j["verification"]["converged"].get<bool>());
}

TEST(StringCli, DesignReachableHelixReproducesTheTarget) {
  const std::string out = (temp_dir() / "helix.fold").string();
  const auto r = test::run_command(test::cli() + " string design " + data("target_helix.json") + " --json --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["closed_form"]["exact"].get<bool>());
  EXPECT_EQ(j["string"]["alpha1_deg"].size(), 100u);
  EXPECT_TRUE(j["verification"]["converged"].get<bool>());
  EXPECT_LE(j["verification"]["max_target_error_per_segment"].get<double>(), 1e-9);
}

TEST(StringCli, DesignUnreachableHelixReportsBestFitAndBindingBounds) {
  const std::string out = (temp_dir() / "unreach.fold").string();
  const auto r = test::run_command(test::cli() + " string design " + data("target_helix_unreachable.json") + " --json --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["reachable"].get<bool>());
  EXPECT_FALSE(j["binding_bounds"].empty());
  EXPECT_GT(j["max_error"].get<double>(), 1e-3);
  // The verification compares the folded output with the target: same error as reported.
  EXPECT_NEAR(j["verification"]["max_target_error"].get<double>(), j["max_error"].get<double>(), 1e-9);
  EXPECT_TRUE(fs::exists(out));
}

TEST(StringCli, BadInputExitsTwoNamingFileAndPathWithoutOutput) {
  const std::string out = (temp_dir() / "never.fold").string();
  fs::remove(out);
  struct Case {
    std::string name, text, expect;
  };
  const std::vector<Case> cases{
      {"malformed.json", "{\"kind\": \"deflections\", ", "not valid JSON"},
      {"target.json",
       R"({"kind": "deflections", "theta_deg": 30, "segment_length": 1,
           "vertices": [{"phi_deg": 30, "psi_deg": 0}, {"phi_deg": -30, "psi_deg": 0}, {"phi_deg": 30, "psi_deg": 0},
                        {"phi_deg": -30, "psi_deg": 0, "alpha1_deg": 1}, {"phi_deg": "x", "psi_deg": 0}]})",
       "target.json: /vertices/4/phi_deg: must be a number"},
      {"missing.json", R"({"kind": "deflections", "theta_deg": 30, "vertices": [{"phi_deg": 30}], "segment_length": 1})",
       "missing.json: /vertices/0/psi_deg: missing"},
      {"range.json", R"({"kind": "curve", "helix": {"radius": 1, "rise": 1, "step_deg": 500, "count": 10}})",
       "range.json: /helix/step_deg: must be in (-360, 360)"},
      {"nan.json", R"({"kind": "deflections", "theta_deg": NaN, "vertices": [], "segment_length": 1})", "not valid JSON"},
      {"kind.json", R"({"kind": "spaghetti"})", "kind.json: /kind: must be one of"},
  };
  for (const auto& c : cases) {
    const std::string path = write_file(c.name, c.text);
    const auto r = test::run_command(test::cli() + " string design " + path + " --out " + out);
    EXPECT_EQ(r.status, 2) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << c.name << ": " << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.name;
  }
  // Forward: alpha out of range and theta beyond the vertex limit.
  const std::string spec = write_file("spec.json", R"({"vertices": [{"alpha1_deg": 30, "alpha2_deg": 60},
      {"alpha1_deg": 40, "alpha2_deg": 50}, {"alpha1_deg": 40, "alpha2_deg": 50}, {"alpha1_deg": 95, "alpha2_deg": 50}],
      "segment_length": 1})");
  auto r = test::run_command(test::cli() + " string forward " + spec + " --theta 20 --out " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("spec.json: /vertices/3/alpha1_deg: must be in [1e-300, 90 - 1e-12]"), std::string::npos) << r.err;
  const std::string ok = write_file("ok.json", R"({"vertices": [{"alpha1_deg": 30, "alpha2_deg": 60}], "segment_length": 1})");
  r = test::run_command(test::cli() + " string forward " + ok + " --theta 60 --out " + out);  // limit 54.7 deg
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--theta"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // An unreachable per-vertex target is an input error at that vertex.
  const std::string unreach = write_file("unreach.json", R"({"kind": "deflections", "theta_deg": 30, "segment_length": 1,
      "vertices": [{"phi_deg": 30, "psi_deg": 0}, {"phi_deg": 30, "psi_deg": 0}]})");
  r = test::run_command(test::cli() + " string design " + unreach + " --out " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unreach.json: /vertices/1: unreachable"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}}  // namespace
}  // namespace rigidfold
