// `rigidfold metamaterial --stacked M`: JSON whose measured stack agrees with the element
// closed forms computed here, and bad flags exiting 2 naming the flag with nothing printed.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "design/metamaterial/corrugated_elements.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(MetamaterialStackedCli, JsonStackAgreesWithElementTwoClosedForm) {
  const auto r = test::run_command(test::cli() +
                                   " metamaterial --stacked 2 --alpha-deg 60 --beta-deg 70 --layers 3 --stacked-steps 8 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["stacked_metamaterial"], 2);
  EXPECT_LE(j["max_dimension_difference"].get<double>(), 1e-9);
  EXPECT_LE(j["max_bond_gap"].get<double>(), 1e-10);
  ASSERT_EQ(j["states"].size(), 8u);
  // Metamaterial 2: two element-2 cells along W and L, three layers of element 2's height.
  const metamaterial::CorrugatedElementParams p{to_radians(60.0), to_radians(70.0), 1.0};
  for (const auto& s : j["states"]) {
    const auto e = metamaterial::corrugated_element(metamaterial::CorrugatedElement::kElement2, p,
                                                    to_radians(s["phi_deg"].get<double>()));
    EXPECT_NEAR(s["W"].get<double>(), 2 * e.W, 1e-9);
    EXPECT_NEAR(s["L"].get<double>(), 2 * e.L, 1e-9);
    EXPECT_NEAR(s["H"].get<double>(), 3 * e.H, 1e-9);
  }
}

TEST(MetamaterialStackedCli, BadFlagsExitTwoNamingTheFlag) {
  const std::pair<const char*, const char*> cases[] = {
      {"--stacked 5", "--stacked"},
      {"--stacked 0", "--stacked"},
      {"--stacked 1 --unit element1", "--unit"},
      {"--stacked 1 --layers 1", "--layers"},
      {"--stacked 1 --layers 17", "--layers"},
      {"--stacked 1 --stacked-steps 7", "--stacked-steps"},
      {"--stacked 1 --samples 10", "--samples"},
      {"--stacked 1 --a 2", "--a"},
      {"--stacked 1 --alpha-deg 180", "--alpha-deg"},
      {"--stacked 2 --beta-deg nan", "--beta-deg"},
      {"--stacked 3 --l -1", "--l"},
      {"--stacked 4 --alpha-deg 60 --beta-deg 120", "--beta-deg"},
      {"--unit element1 --layers 3", "--layers"},
      {"--json", "--unit"},
  };
  for (const auto& [args, flag] : cases) {
    const auto r = test::run_command(test::cli() + " metamaterial " + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

}}  // namespace
}  // namespace rigidfold
