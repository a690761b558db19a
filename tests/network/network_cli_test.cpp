// rigidfold network: JSON output of the seed-003 examples, and bad input -> exit 2.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::string data(const std::string& name) { return std::string(RIGIDFOLD_SOURCE_DIR) + "/data/network/" + name; }

TEST(NetworkCli, Fig27TraceJson) {
  const auto r = test::run_command(test::cli() + " network " + data("fig2-7_rotation.json") + " --json --trace 6");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mobility"]["dof"], 1);
  EXPECT_EQ(j["mobility"]["dof_input_held"], 0);
  EXPECT_LE(j["configuration"]["residual_rad"].get<double>(), 1e-12);
  ASSERT_TRUE(j["trace"]["complete"].get<bool>());
  ASSERT_EQ(j["trace"]["points"].size(), 7u);
  for (const auto& p : j["trace"]["points"]) {
    EXPECT_LE(p["residual_rad"].get<double>(), 1e-12);
    EXPECT_EQ(p["dof"], 1);
    EXPECT_EQ(p["outputs_deg"].size(), 3u);
  }
  EXPECT_NEAR(j["trace"]["points"][6]["input_deg"].get<double>(), 90.0, 1e-12);
}

TEST(NetworkCli, PerturbedEq234NotMobile) {
  const auto r = test::run_command(test::cli() + " network " + data("eq2-34_perturbed.json") + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["configuration"]["closed_at_input_start"].get<bool>());
  EXPECT_GT(j["configuration"]["least_residual_rad"].get<double>(), 1e-4);
  EXPECT_NE(j["verdict"].get<std::string>().find("not mobile"), std::string::npos);
  EXPECT_EQ(j["flat_vertices_2_33"].size(), 4u);
}

TEST(NetworkCli, TextOutput) {
  const auto r = test::run_command(test::cli() + " network " + data("eq2-34.json") + " --trace 3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("mobility: DOF 1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("verdict: mobile"), std::string::npos);
}

TEST(NetworkCli, FlatTriangleIsSingularNotMobile) {
  const std::string path = ::testing::TempDir() + "rigidfold_flat_triangle.json";
  {
    std::ofstream f(path);
    f << R"({"linkages": [{"twists_deg": [120, 120, 120], "joints": ["a", "b", "c"]}], "input": {"joint": "a", "start_deg": 0}})";
  }
  const auto r = test::run_command(test::cli() + " network " + path + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mobility"]["dof"], 1);
  EXPECT_EQ(j["mobility"]["input_moves_1e-3_rad"], 0);
  EXPECT_EQ(j["verdict"].get<std::string>().rfind("singular", 0), 0u) << j["verdict"];
  std::remove(path.c_str());
}

TEST(NetworkCli, BadInputExitsTwoNamingThePlace) {
  const std::string path = ::testing::TempDir() + "rigidfold_bad_network.json";
  {
    std::ofstream f(path);
    f << R"({"linkages": [{"twists_deg": [10, 20, "x"], "joints": ["a", "b", "c"]}]})";
  }
  auto r = test::run_command(test::cli() + " network " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("linkages[0].twists_deg[2]"), std::string::npos) << r.err;
  r = test::run_command(test::cli() + " network " + data("fig2-7_rotation.json") + " --trace -1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--trace"), std::string::npos) << r.err;
  r = test::run_command(test::cli() + " network /nonexistent/n.json");
  EXPECT_EQ(r.status, 2);
  std::remove(path.c_str());
}

}}  // namespace
}  // namespace rigidfold
