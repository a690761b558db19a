// `rigidfold energy ... --stiffness SPEC.json`: a spec that repeats the letters' stiffness gives
// the --k-m/--k-v result digit for digit; equal stiffness of any size leaves the states in place
// and scales the energies; bad specs exit 2 naming the file and the JSON path.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;
const std::string kSource = std::string(RIGIDFOLD_SOURCE_DIR) + "/";
const std::string kBase = kSource + "data/bundled/waterbomb_base.fold";
const std::string kRest = kSource + "data/energy/waterbomb_base_rest60.json";
const std::string kSpec = kSource + "data/energy/waterbomb_base_stiffness.json";  // M 2, V 1

nlohmann::json run_json(const std::string& flags) {
  const auto r = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --starts 6 --json " + flags);
  EXPECT_EQ(r.status, 0) << flags << ": " << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

TEST(EnergyStiffnessCli, SpecEqualsLetterFlags) {
  const auto spec = run_json("--stiffness " + kSpec);
  const auto flags = run_json("--k-m 2 --k-v 1");
  ASSERT_FALSE(spec.is_null());
  ASSERT_FALSE(flags.is_null());
  EXPECT_EQ(spec["stable_states"], flags["stable_states"]);
  ASSERT_TRUE(spec["stiffness"].contains("per_edge"));
  const auto letters = nlohmann::json::parse(std::ifstream(kBase))["edges_assignment"];
  for (std::size_t e = 0; e < letters.size(); ++e)
    EXPECT_EQ(spec["stiffness"]["per_edge"][e].get<double>(), letters[e] == "M" ? 2.0 : letters[e] == "V" ? 1.0 : 0.0) << e;
}

TEST(EnergyStiffnessCli, EqualStiffnessScalesTheEnergyOnly) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_energy_k_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "k5.json") << "{\"default\": 5}";
  const auto five = run_json("--stiffness " + (dir / "k5.json").string());
  const auto one = run_json("");
  ASSERT_EQ(five["stable_states"].size(), one["stable_states"].size());
  ASSERT_GE(one["stable_states"].size(), 2u);
  for (std::size_t i = 0; i < one["stable_states"].size(); ++i) {
    const auto& a = one["stable_states"][i];
    const auto& b = five["stable_states"][i];
    EXPECT_NEAR(b["energy"].get<double>(), 5 * a["energy"].get<double>(), 1e-9 * std::max(1.0, b["energy"].get<double>()));
    for (std::size_t e = 0; e < a["fold_angles_deg"].size(); ++e) {
      if (!a["fold_angles_deg"][e].is_null()) {
        EXPECT_NEAR(b["fold_angles_deg"][e].get<double>(), a["fold_angles_deg"][e].get<double>(), 1e-7) << i << " " << e;
      }
    }
  }
  fs::remove_all(dir);
}

TEST(EnergyStiffnessCli, BadSpecExitsTwoNamingTheJsonPath) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_energy_kbad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::vector<std::pair<std::string, std::string>> specs = {
      {"{\"edges\": {\"99\": 1}}", "edges.\"99\""},
      {"{\"valley\": -1}", "valley"},
      {"{\"material\": {\"youngs_modulus\": 1}}", "material.thickness"},
      {"{\"default\": 1, \"default\": 2}", "default"},
      {"{\"default\": ", "k.json"},
  };
  for (const auto& [text, place] : specs) {
    const std::string path = (dir / "k.json").string();
    std::ofstream(path) << text;
    const auto r = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --stiffness " + path);
    EXPECT_EQ(r.status, 2) << text;
    EXPECT_NE(r.err.find(path), std::string::npos) << text << ": " << r.err;
    EXPECT_NE(r.err.find(place), std::string::npos) << text << ": " << r.err;
    EXPECT_TRUE(r.out.empty());
  }
  for (const std::string& flags : {"--stiffness " + kSpec + " --k-m 2", "--stiffness " + (dir / "missing.json").string()}) {
    const auto r = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " " + flags);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_NE(r.err.find(flags.find("--k-m") != std::string::npos ? "--stiffness" : "missing.json"), std::string::npos) << r.err;
  }
  fs::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
