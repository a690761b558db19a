// `rigidfold energy ... --load SPEC.json` on the bundled waterbomb base (rest at theta0 = 60
// deg): the loaded state reached from the rest state has the reaction force of the closed form
// (seed 004 eq. 3.9, design/waterbomb/waterbomb_force.hpp) at that height; bad specs exit 2
// naming the file and the JSON path.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "design/waterbomb/waterbomb_force.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;
const std::string kSource = std::string(RIGIDFOLD_SOURCE_DIR) + "/";
const std::string kBase = kSource + "data/bundled/waterbomb_base.fold";
const std::string kRest = kSource + "data/energy/waterbomb_base_rest60.json";

TEST(EnergyLoadCli, ReactionForceEqualsTheClosedForm) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_energy_load_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const double r = std::cos(kPi / 4);  // the bundled base's valley crease length
  const auto springs = waterbomb::springs_at_rest_theta(4, to_radians(60.0), 1.0, 1.0);
  for (double theta_deg : {40.0, 70.0, 85.0}) {
    const double theta = to_radians(theta_deg);
    const std::string path = (dir / "load.json").string();
    char text[128];
    std::snprintf(text, sizeof text, "{\"vertex\": 0, \"height\": %.17g}", r * std::cos(theta));
    std::ofstream(path) << text;
    const auto run = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --starts 0 --json --load " + path);
    ASSERT_EQ(run.status, 0) << run.err;
    const auto j = nlohmann::json::parse(run.out);
    const double want = waterbomb::waterbomb_force(springs, to_radians(60.0), r, theta).force;
    // The state reached from the rest state is the symmetric one: its force is eq. 3.9's.
    bool found = false;
    for (const auto& s : j["loaded"]["states"])
      found = found || std::fabs(s["force"].get<double>() - want) <= 1e-9 * std::max(1.0, std::fabs(want));
    EXPECT_TRUE(found) << theta_deg << ": want " << want << " in " << j["loaded"].dump();
    EXPECT_EQ(j["loaded"]["supports"], nlohmann::json::parse("[0, 2, 4, 6]"));
  }
  fs::remove_all(dir);
}

// A pattern outside [2^-20, 2^20] is normalised on reading: its load height is a length of the
// file and is normalised with it, and the force (energy per length) comes back in the file's
// units. The base scaled by s, held at s times the height, has the force of the unscaled base
// over s; held at the unscaled height it cannot reach it (no loaded state, or exit 3).
TEST(EnergyLoadCli, LoadHeightScalesWithThePattern) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_energy_load_scale_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  auto fold = nlohmann::json::parse(std::ifstream(kBase));
  const double height = std::cos(kPi / 4) * std::cos(to_radians(70.0));
  auto force_at = [&](const std::string& pattern, double h, int* status) {
    const std::string load = (dir / "load.json").string();
    char text[128];
    std::snprintf(text, sizeof text, "{\"vertex\": 0, \"height\": %.17g}", h);
    std::ofstream(load) << text;
    const auto run = test::run_command(test::cli() + " energy " + pattern + " --rest " + kRest + " --starts 0 --json --load " + load);
    *status = run.status;
    std::vector<double> forces;
    if (run.status == 0) {
      const auto doc = nlohmann::json::parse(run.out);  // held: the loop's range is a part of it
      for (const auto& s : doc["loaded"]["states"]) forces.push_back(s["force"].get<double>());
    }
    return forces;
  };
  int status = -1;
  const auto unscaled = force_at(kBase, height, &status);
  ASSERT_EQ(status, 0);
  ASSERT_FALSE(unscaled.empty());
  for (double scale : {1e-7, 1e-300, 1e300}) {
    auto scaled = fold;
    for (auto& v : scaled["vertices_coords"])
      for (auto& x : v) x = x.get<double>() * scale;
    const std::string path = (dir / "scaled.fold").string();
    std::ofstream(path) << scaled.dump();
    const auto forces = force_at(path, height * scale, &status);
    ASSERT_EQ(status, 0) << scale;
    ASSERT_EQ(forces.size(), unscaled.size()) << scale;
    for (std::size_t i = 0; i < forces.size(); ++i)
      EXPECT_NEAR(forces[i] * scale, unscaled[i], 1e-9 * std::max(1.0, std::fabs(unscaled[i]))) << scale;
    if (scale < 1.0) {
      // The unscaled height is out of reach of the small base: never an equilibrium there.
      const auto unreachable = force_at(path, height, &status);
      EXPECT_TRUE(status == 3 || (status == 0 && unreachable.empty())) << scale << ": status " << status;
    }
  }
  fs::remove_all(dir);
}

TEST(EnergyLoadCli, BadSpecExitsTwoNamingTheJsonPath) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_energy_loadbad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> specs = {
      {R"({"vertex": 3, "height": 1})", "vertex"},
      {R"({"vertex": 0, "force": 2})", "force"},
      {R"({"vertex": 0, "height": 1, "supports": [0, 2, 12]})", "supports[2]"},
      {R"({"vertex": 0, "height": 1e999})", "l.json"},
      {"[", "l.json"},
  };
  for (const auto& [text, place] : specs) {
    const std::string path = (dir / "l.json").string();
    std::ofstream(path) << text;
    const auto r = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --starts 0 --load " + path);
    EXPECT_EQ(r.status, 2) << text;
    EXPECT_NE(r.err.find(path), std::string::npos) << text << ": " << r.err;
    EXPECT_NE(r.err.find(place), std::string::npos) << text << ": " << r.err;
    EXPECT_TRUE(r.out.empty());
  }
  const auto missing = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --load " + (dir / "none.json").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("none.json"), std::string::npos) << missing.err;
  fs::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
