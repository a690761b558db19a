// `rigidfold waterbomb --target-second-state-deg T2`: the designed rest angle, fed back with
// --theta0-deg, puts a stable state at T2; bad input exits 2 naming the flag.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "design/waterbomb/waterbomb_rest_design.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombRestDesignCli, DesignedRestAngleReachesTheTargetForward) {
  const auto r = test::run_command(test::cli() + " waterbomb --n 4 --target-second-state-deg 104 --k-ratio 1.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double theta0_deg = j["design"]["theta0_deg"].get<double>();
  EXPECT_EQ(theta0_deg, to_degrees(waterbomb::rest_angle_for_state2(4, to_radians(104.0), 1.5, 1.0).theta0));
  EXPECT_LE(j["design"]["second_state_gap_rad"].get<double>(), 1e-9);
  // Fed back as an ordinary rest angle (round-trip text), the analysis finds state 2 at 104 deg.
  char t0[64];
  std::snprintf(t0, sizeof t0, "%.17g", theta0_deg);
  const auto f = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg " + t0 + " --k-ratio 1.5 --json");
  ASSERT_EQ(f.status, 0) << f.err;
  const auto forward = nlohmann::json::parse(f.out);
  double gap = INFINITY;
  for (const auto& e : forward["equilibria"])
    if (e["stable"].get<bool>()) gap = std::min(gap, std::fabs(to_radians(e["theta_deg"].get<double>() - 104.0)));
  EXPECT_LE(gap, 1e-9);
}

TEST(WaterbombRestDesignCli, BadInputExitsTwoNamingTheFlag) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--n 4", "--theta0-deg"},
      {"--n 4 --target-second-state-deg 100 --theta0-deg 60", "--target-second-state-deg"},
      {"--n 4 --target-second-state-deg 90", "--target-second-state-deg"},
      {"--n 4 --target-second-state-deg 135", "--target-second-state-deg"},
      {"--n 4 --target-second-state-deg nan", "--target-second-state-deg"},
      {"--n 4 --target-second-state-deg -inf", "--target-second-state-deg"},
      {"--n 4 --target-second-state-deg 100 --split-deg 5", "--target-second-state-deg"},
      {"--n 4 --target-second-state-deg 100 --target-switching-force 1", "--target-second-state-deg"},
      {"--n 4 --target-second-state-deg 100 --k-m -1 --k-v 1", "--k-m"},
  };
  for (const auto& [flags, name] : cases) {
    const auto r = test::run_command(test::cli() + " waterbomb " + flags);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_NE(r.err.find(name), std::string::npos) << flags << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << flags;
  }
  // No rest angle reaches it: exit 3, nothing printed.
  const auto r = test::run_command(test::cli() + " waterbomb --n 4 --target-second-state-deg 134 --k-m 0 --k-v 1");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_TRUE(r.out.empty());
}

}}  // namespace
}  // namespace rigidfold

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombRestDesignCli, RestAngleForASwitchingForce) {
  const auto r = test::run_command(test::cli() + " waterbomb --n 5 --target-switching-force 12 --design theta0 --k-ratio 2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["switching_force"]["force"].get<double>(), 12.0, 1e-9 * 12);
  EXPECT_EQ(j["theta0_deg"].get<double>(), j["design"]["theta0_deg"].get<double>());
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--n 5 --target-switching-force 12 --design theta0 --theta0-deg 50", "--design"},
      {"--n 5 --target-switching-force 12 --design k_v --theta0-deg 50", "--design"},
      {"--n 5 --design theta0 --theta0-deg 50", "--design"},
      {"--n 5 --target-switching-force -3 --design theta0", "--target-switching-force"},
      {"--n 5 --target-switching-force 12 --design theta0 --split-deg 3", "--split-deg"},
  };
  for (const auto& [flags, name] : cases) {
    const auto bad = test::run_command(test::cli() + " waterbomb " + flags);
    EXPECT_EQ(bad.status, 2) << flags;
    EXPECT_NE(bad.err.find(name), std::string::npos) << flags << ": " << bad.err;
  }
  // Above what theta0 = 0 gives: exit 3, nothing printed.
  const auto high = test::run_command(test::cli() + " waterbomb --n 5 --target-switching-force 1e9 --design theta0");
  EXPECT_EQ(high.status, 3) << high.err;
  EXPECT_TRUE(high.out.empty());
}

}}  // namespace
}  // namespace rigidfold
