// `rigidfold waterbomb --sweep-n ...`: the CSV table is the library's, --plot writes the same
// table and a PNG, --json has one row per combination, and bad lists exit 2 naming the flag.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "design/waterbomb/waterbomb_sweep.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

TEST(WaterbombSweepCli, TableIsTheLibrarysAndPlotWritesIt) {
  const std::string flags = " waterbomb --sweep-n 3..5 --sweep-split-deg 0,4,60 --sweep-k-ratio 1,2 --theta0-deg 55";
  const auto r = test::run_command(test::cli() + flags);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto lib = waterbomb::waterbomb_sweep({{3, 4, 5}, {0.0, 4.0, 60.0}, {1.0, 2.0}, 55.0});
  EXPECT_EQ(r.out, waterbomb::sweep_csv(lib));
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_wbsweep_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto p = test::run_command(test::cli() + flags + " --plot " + dir.string());
  ASSERT_EQ(p.status, 0) << p.err;
  std::ifstream in(dir / "sweep.csv");
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), r.out);
  // The data only: the binary starts no plotter (python/plot_waterbomb.py --sweep draws it).
  std::vector<std::string> written;
  for (const auto& e : fs::directory_iterator(dir)) written.push_back(e.path().filename().string());
  EXPECT_EQ(written, std::vector<std::string>{"sweep.csv"});
  const auto j = test::run_command(test::cli() + flags + " --json");
  ASSERT_EQ(j.status, 0) << j.err;
  EXPECT_EQ(nlohmann::json::parse(j.out)["rows"].size(), lib.size());
  fs::remove_all(dir);
}

TEST(WaterbombSweepCli, BadListsExitTwoNamingTheFlag) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--sweep-n 2..5 --theta0-deg 60", "--sweep-n"},
      {"--sweep-n 3..x --theta0-deg 60", "--sweep-n"},
      {"--sweep-n 5..3 --theta0-deg 60", "--sweep-n"},
      {"--sweep-n 3.5 --theta0-deg 60", "--sweep-n"},
      {"--sweep-n 3,,4 --theta0-deg 60", "--sweep-n"},
      {"--sweep-n 3..500 --theta0-deg 60", "--sweep-n"},
      {"--sweep-n 3..36 --sweep-split-deg 0,1 --theta0-deg 60", "--sweep-n"},  // over the work budget
      {"--sweep-n 4 --sweep-split-deg 1,nan --theta0-deg 60", "--sweep-split-deg"},
      {"--sweep-n 4 --sweep-split-deg -1 --theta0-deg 60", "--sweep-split-deg"},
      {"--sweep-n 4 --sweep-k-ratio -1 --theta0-deg 60", "--sweep-k-ratio"},
      {"--sweep-n 4 --sweep-k-ratio 1e999 --theta0-deg 60", "--sweep-k-ratio"},
      {"--sweep-n 4", "--theta0-deg"},
      {"--sweep-n 4 --theta0-deg 95", "--theta0-deg"},
      {"--sweep-n 4 --n 4 --theta0-deg 60", "--sweep-n"},
      {"--sweep-n 4 --theta0-deg 60 --curve c.csv", "--sweep-n"},
      {"--sweep-split-deg 5 --n 4 --theta0-deg 60", "--sweep-split-deg"},
      {"--theta0-deg 60", "--n"},
  };
  for (const auto& [flags, name] : cases) {
    const auto r = test::run_command(test::cli() + " waterbomb " + flags);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_NE(r.err.find(name), std::string::npos) << flags << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << flags;
  }
}

}}  // namespace
}  // namespace rigidfold
