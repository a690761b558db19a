// `rigidfold energy` on the bundled waterbomb base with the bundled rest state (theta0 = 60
// deg): the same two stable states as `rigidfold waterbomb --n 4 --theta0-deg 60`, and exit 2
// naming the place for bad stiffness, a rest state that does not close, or a rest file of
// another pattern.
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

const std::string kSource = std::string(RIGIDFOLD_SOURCE_DIR) + "/";
const std::string kBase = kSource + "data/bundled/waterbomb_base.fold";
const std::string kRest = kSource + "data/energy/waterbomb_base_rest60.json";

TEST(EnergyCli, BundledWaterbombMatchesTheWaterbombCommand) {
  const auto general = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --json");
  ASSERT_EQ(general.status, 0) << general.err;
  const auto closed = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --json");
  ASSERT_EQ(closed.status, 0) << closed.err;
  const auto g = nlohmann::json::parse(general.out);
  const auto c = nlohmann::json::parse(closed.out);
  std::vector<nlohmann::json> stable;
  for (const auto& e : c["equilibria"])
    if (e["stable"].get<bool>()) stable.push_back(e);
  ASSERT_EQ(stable.size(), 2u);
  std::vector<nlohmann::json> physical;
  for (const auto& s : g["stable_states"])
    if (s["keeps_letters"].get<bool>() && !s["facet_interference"].get<bool>()) physical.push_back(s);
  ASSERT_EQ(physical.size(), 2u);
  const auto letters = nlohmann::json::parse(std::ifstream(kBase))["edges_assignment"];
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& s = physical[i];
    EXPECT_NEAR(s["energy"].get<double>(), stable[i]["energy"].get<double>(), 1e-9 * std::max(1.0, stable[i]["energy"].get<double>()));
    for (std::size_t e = 0; e < letters.size(); ++e) {
      const std::string l = letters[e];
      if (l != "M" && l != "V") continue;
      const double want = stable[i][l == "M" ? "gamma_m_deg" : "gamma_v_deg"].get<double>();
      EXPECT_NEAR(s["fold_angles_deg"][e].get<double>(), want, 1e-7) << "state " << i << " edge " << e;  // 1e-7 deg ~ 2e-9 rad
    }
  }
}

TEST(EnergyCli, BadInputExitsTwoNamingThePlace) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_energy_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string open_rest = (dir / "open.json").string();
  std::ofstream(open_rest) << "{\"0\": 30, \"1\": -30}\n";  // two creases folded, the rest flat: no closure
  const std::vector<std::pair<std::string, std::string>> cases = {
      {kBase + " --rest " + kRest + " --k-m -1", "--k-m"},
      {kBase + " --rest " + kRest + " --k-v nan", "--k-v"},
      {kBase + " --rest " + kRest + " --starts 1001", "--starts"},
      {kBase + " --rest " + open_rest, open_rest},
      {kBase + " --rest " + kSource + "data/bundled/miura_4x4_alpha60.fold", "miura_4x4_alpha60.fold"},
      {kBase + " --rest " + kSource + "data/strings/forward_spec.json", "forward_spec.json"},
      {kBase, "--rest"},
  };
  for (const auto& [args, place] : cases) {
    const auto r = test::run_command(test::cli() + " energy " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(place), std::string::npos) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
  fs::remove_all(dir);
}

// A sheet with holes has no flat state to fold from: refused as input (exit 2 naming the file
// and the holes), never an internal error. The bundled Miura tube, and a thick FOLD, each its
// own rest state.
TEST(EnergyCli, SheetsWithHolesAreRefusedAsInput) {
  for (const std::string file : {kSource + "data/bundled/miura_tube_6_alpha60.fold", kSource + "data/thick/diamond_arch_6_a30_thick.fold"}) {
    const auto r = test::run_command(test::cli() + " energy " + file + " --rest " + file);
    EXPECT_EQ(r.status, 2) << file << ": " << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("hole"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }
}

}}  // namespace
}  // namespace rigidfold
