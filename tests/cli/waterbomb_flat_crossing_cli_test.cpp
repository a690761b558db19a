// `rigidfold waterbomb --curve --json`: the "flat_crossing" report names the tangent-cone
// branch the general model continued along past the flat state, the same as the library's.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "design/waterbomb/waterbomb_curve.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombFlatCrossingCli, JsonReportsTheLetterKeepingBranch) {
  const auto dir = std::filesystem::temp_directory_path() / ("rf_wb_flat_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string csv = (dir / "curve.csv").string();
  const auto r = test::run_command(test::cli() + " waterbomb --n 6 --theta0-deg 50 --curve " + csv + " --samples 11 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("flat_crossing"));
  const auto& fc = j["flat_crossing"];
  const auto lib = waterbomb::waterbomb_curve(6, to_radians(50.0), 1.0, 1.0, 11).flat_crossing;
  EXPECT_EQ(fc["cone_lines"].get<int>(), lib.cone_lines);
  EXPECT_GT(fc["branches_below_supports"].get<int>(), 1);  // the mirror is there too
  EXPECT_EQ(fc["letter_keeping_below_supports"].get<int>(), 1);
  const int taken = fc["taken"].get<int>();
  EXPECT_EQ(taken, lib.taken);
  ASSERT_EQ(fc["branches"].size(), lib.branches.size());
  EXPECT_TRUE(fc["branches"][taken]["keeps_letters"].get<bool>());
  EXPECT_TRUE(fc["branches"][taken]["below_supports"].get<bool>());
  EXPECT_LT(fc["branches"][taken]["height_rate"].get<double>(), 0.0);
  for (std::size_t i = 0; i < fc["branches"].size(); ++i)
    if (static_cast<int>(i) != taken && fc["branches"][i]["below_supports"].get<bool>()) {
      EXPECT_FALSE(fc["branches"][i]["keeps_letters"].get<bool>());
    }
  // Without --curve there is no crossing to report.
  const auto plain = test::run_command(test::cli() + " waterbomb --n 6 --theta0-deg 50 --json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("flat_crossing"));
  std::filesystem::remove_all(dir);
}

TEST(WaterbombFlatCrossingCli, TextNamesTheBranch) {
  const auto dir = std::filesystem::temp_directory_path() / ("rf_wb_flat_t_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto r = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --curve " + (dir / "c.csv").string() + " --samples 7");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("flat crossing: tangent cone of the symmetric closure system has 2 lines"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 keeping the M/V letters"), std::string::npos) << r.out;
  std::filesystem::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
