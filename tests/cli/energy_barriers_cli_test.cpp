// `rigidfold energy --barriers` on the bundled waterbomb base with the bundled rest state
// (theta0 = 60 deg): between the two stable states that keep their letters, the
// minimum-energy path's top is the flat state (a cusp of the energy, not a saddle), and its
// barriers both ways equal `rigidfold waterbomb --n 4 --theta0-deg 60`'s symmetric-path
// barriers to 1e-9 relative. Without the flag the JSON has no "barriers" key. Every barrier
// printed passed its checks; the others say "not found" with a reason.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

const std::string kSource = std::string(RIGIDFOLD_SOURCE_DIR) + "/";
const std::string kBase = kSource + "data/bundled/waterbomb_base.fold";
const std::string kRest = kSource + "data/energy/waterbomb_base_rest60.json";

TEST(EnergyBarriersCli, WaterbombBarrierIsTheFlatCuspOfTheWaterbombCommand) {
  const auto plain = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --starts 2 --json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("barriers"));

  const auto general = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --starts 2 --barriers --json");
  ASSERT_EQ(general.status, 0) << general.err;
  const auto closed = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --json");
  ASSERT_EQ(closed.status, 0) << closed.err;
  const auto g = nlohmann::json::parse(general.out);
  const auto c = nlohmann::json::parse(closed.out);
  ASSERT_EQ(c["barriers"].size(), 2u);
  const double from_rest = c["barriers"][0]["symmetric_path_barrier"].get<double>();
  const double from_second = c["barriers"][1]["symmetric_path_barrier"].get<double>();

  // The two physical states (letters kept, no interference): the rest state and the second one.
  std::vector<int> physical;
  for (std::size_t i = 0; i < g["stable_states"].size(); ++i)
    if (g["stable_states"][i]["keeps_letters"].get<bool>() && !g["stable_states"][i]["facet_interference"].get<bool>())
      physical.push_back(static_cast<int>(i));
  ASSERT_EQ(physical.size(), 2u);
  const std::size_t n = g["stable_states"].size();
  ASSERT_EQ(g["barriers"].size(), n * (n - 1) / 2);  // every pair (n <= 6)
  bool seen = false;
  for (const auto& b : g["barriers"]) {
    if (b["found"].get<bool>()) {
      EXPECT_TRUE(b["barrier_from_first"].is_number());
      EXPECT_EQ(b["message"], "");
      EXPECT_FALSE(b["path"].empty());
    } else {
      EXPECT_TRUE(b["barrier_from_first"].is_null());
      EXPECT_NE(b["message"].get<std::string>(), "");
    }
    if (b["states"][0].get<int>() != physical[0] || b["states"][1].get<int>() != physical[1]) continue;
    seen = true;
    ASSERT_TRUE(b["found"].get<bool>()) << b["message"];
    EXPECT_EQ(b["top"], "singular point (flat state, cusp)");
    EXPECT_NEAR(b["barrier_from_first"].get<double>(), from_rest, 1e-9 * from_rest);
    EXPECT_NEAR(b["barrier_from_second"].get<double>(), from_second, 1e-9 * from_second);
    for (const auto& a : b["saddle"]["fold_angles_deg"]) {
      if (!a.is_null()) {
        EXPECT_EQ(a.get<double>(), 0.0);
      }
    }
  }
  EXPECT_TRUE(seen);

  const auto text = test::run_command(test::cli() + " energy " + kBase + " --rest " + kRest + " --starts 2 --barriers");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("barrier state 1 <-> state 2:"), std::string::npos) << text.out;
}

}}  // namespace
}  // namespace rigidfold
