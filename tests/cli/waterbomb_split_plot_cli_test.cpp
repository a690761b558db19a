// `rigidfold waterbomb --split-deg B` (the split-fold base) and `--plot DIR` (CSV, JSON and
// PNG of the energy and force curves): JSON equal to the library's doubles, exit 2 naming the
// flag on bad input, nothing written by a failed command, and clashing outputs refused.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "design/waterbomb/split_fold_bistability.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

fs::path scratch(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_wbsplit_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(WaterbombSplitCli, JsonMatchesTheLibrary) {
  const auto r = test::run_command(test::cli() + " waterbomb --n 4 --split-deg 5 --theta0-deg 60 --k-ratio 1.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["split_deg"].get<double>(), 5.0);
  const auto lib = waterbomb::split_fold_bistability(4, to_radians(5.0), to_radians(60.0), 1.5, 1.0);
  ASSERT_EQ(j["equilibria"].size(), lib.equilibria.size());
  int stable = 0;
  for (std::size_t i = 0; i < lib.equilibria.size(); ++i) {
    const auto& e = j["equilibria"][i];
    EXPECT_EQ(e["theta_deg"].get<double>(), to_degrees(lib.equilibria[i].path.theta));
    EXPECT_EQ(e["energy"].get<double>(), lib.equilibria[i].path.energy);
    EXPECT_EQ(e["gamma_v_deg"].get<double>(), to_degrees(lib.equilibria[i].path.angles.gamma_v));
    if (e["stable"].get<bool>()) ++stable;
  }
  EXPECT_EQ(stable, 2);
  // The switching force: the general model's, as the library gives it.
  const auto sw = waterbomb::split_fold_switching_force(4, to_radians(5.0), to_radians(60.0), 1.5, 1.0);
  EXPECT_EQ(j["switching_force"]["force"].get<double>(), sw.force);
  EXPECT_GT(sw.force, 0.0);
  ASSERT_EQ(j["barriers"].size(), 2u);
}

TEST(WaterbombSplitCli, BadInputExitsTwoNamingTheFlag) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--n 4 --split-deg 45 --theta0-deg 60", "--split-deg"},
      {"--n 4 --split-deg 0 --theta0-deg 60", "--split-deg"},
      {"--n 4 --split-deg -3 --theta0-deg 60", "--split-deg"},
      {"--n 4 --split-deg nan --theta0-deg 60", "--split-deg"},
      {"--n 4 --split-deg inf --theta0-deg 60", "--split-deg"},
      {"--n 4 --split-deg x --theta0-deg 60", "--split-deg"},
      {"--n 2 --split-deg 5 --theta0-deg 60", "--n"},
      {"--n 4 --split-deg 20 --theta0-deg 5", "--theta0-deg"},      // below theta* = 10.16 deg
      {"--n 4 --split-deg 5 --theta0-deg 137", "--theta0-deg"},     // above theta_max = 136.53 deg
      {"--n 4 --split-deg 5 --theta0-deg 100 --target-switching-force 1", "--target-switching-force"},
      {"--n 4 --split-deg 5 --theta0-deg 60 --target-switching-force -1", "--target-switching-force"},
      {"--n 4 --split-deg 5 --theta0-deg 60 --k-m -1 --k-v 1", "--k-m"},
      {"--n 4 --split-deg 5 --theta0-deg 60 --samples 11", "--samples"},
  };
  for (const auto& [flags, name] : cases) {
    const auto r = test::run_command(test::cli() + " waterbomb " + flags);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_NE(r.err.find(name), std::string::npos) << flags << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << flags;
  }
  // The range is named in the message.
  const auto r = test::run_command(test::cli() + " waterbomb --n 6 --split-deg 31 --theta0-deg 60");
  EXPECT_NE(r.err.find("(0, 30)"), std::string::npos) << r.err;
}

// --plot: two files, the figure's data; the CSV is the library's curve digit for digit, the
// JSON the --json document. No PNG: the binary starts no plotter (the main job draws the
// figure with python/plot_waterbomb.py). The plain base as well.
TEST(WaterbombSplitCli, PlotWritesCsvAndJson) {
  const fs::path dir = scratch("plot");
  for (const std::string& split : {std::string(" --split-deg 5"), std::string()}) {
    const fs::path out = dir / (split.empty() ? "plain" : "split");
    const std::string flags = " waterbomb --n 4" + split + " --theta0-deg 60";
    const auto r = test::run_command(test::cli() + flags + " --samples 31 --plot " + out.string());
    ASSERT_EQ(r.status, 0) << r.err;
    std::set<std::string> written;
    for (const auto& e : fs::directory_iterator(out)) written.insert(e.path().filename().string());
    EXPECT_EQ(written, (std::set<std::string>{"waterbomb.csv", "waterbomb.json"}));
    // With a curve the document also says how the curve crossed flat ("flat_crossing", plain base).
    const auto json = test::run_command(test::cli() + flags + " --samples 31 --curve " + (dir / "json_run.csv").string() + " --json");
    ASSERT_EQ(json.status, 0);
    auto strip = [](nlohmann::json j) {
      j.erase("provenance");
      return j;
    };
    EXPECT_EQ(strip(nlohmann::json::parse(read(out / "waterbomb.json"))), strip(nlohmann::json::parse(json.out)));
    const fs::path csv = dir / (split.empty() ? "plain.csv" : "split.csv");
    ASSERT_EQ(test::run_command(test::cli() + flags + " --samples 31 --curve " + csv.string()).status, 0);
    EXPECT_EQ(read(csv), read(out / "waterbomb.csv"));
    if (!split.empty()) {
      const auto lib = waterbomb::split_fold_curve(4, to_radians(5.0), to_radians(60.0), 1.0, 1.0, 31);
      std::istringstream lines(read(csv));
      std::string line;
      std::getline(lines, line);
      for (const auto& s : lib.samples) {
        ASSERT_TRUE(std::getline(lines, line));
        EXPECT_EQ(std::stod(line.substr(0, line.find(','))), to_degrees(s.theta));
      }
    }
  }
  fs::remove_all(dir);
}

// --target-switching-force on a split fold: the designed k_m, fed back, switches at the target.
TEST(WaterbombSplitCli, DesignedStiffnessSwitchesAtTheTarget) {
  const auto r = test::run_command(test::cli() + " waterbomb --n 4 --split-deg 5 --theta0-deg 60 --target-switching-force 8 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const double k_m = nlohmann::json::parse(r.out)["design"]["k_m"].get<double>();
  char km[64];
  std::snprintf(km, sizeof km, "%.17g", k_m);
  const auto f = test::run_command(test::cli() + " waterbomb --n 4 --split-deg 5 --theta0-deg 60 --k-m " + km + " --k-v 1 --json");
  ASSERT_EQ(f.status, 0) << f.err;
  EXPECT_NEAR(nlohmann::json::parse(f.out)["switching_force"]["force"].get<double>(), 8.0, 1e-9 * 8);
  // Below what k_m = 0 gives: exit 3.
  const auto low = test::run_command(test::cli() + " waterbomb --n 4 --split-deg 5 --theta0-deg 60 --target-switching-force 0.01");
  EXPECT_EQ(low.status, 3) << low.err;
  EXPECT_TRUE(low.out.empty());
}

// A failed command writes nothing into DIR; an output on an input or on another output is refused.
TEST(WaterbombSplitCli, FailedOrClashingPlotWritesNothing) {
  const fs::path dir = scratch("fail");
  const fs::path out = dir / "plot";
  auto r = test::run_command(test::cli() + " waterbomb --n 4 --split-deg 45 --theta0-deg 60 --plot " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(out / "waterbomb.png"));
  EXPECT_FALSE(fs::exists(out / "waterbomb.csv"));
  r = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --plot " + out.string() + " --curve " +
                        (out / "waterbomb.csv").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "waterbomb.png"));
  // An empty directory name.
  r = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --plot ''");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
  // A file where the directory should be.
  std::ofstream(dir / "file") << "x";
  r = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --plot " + (dir / "file").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
  EXPECT_EQ(read(dir / "file"), "x");
  fs::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
