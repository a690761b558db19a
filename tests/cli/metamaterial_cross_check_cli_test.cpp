// `rigidfold metamaterial --unit square-twist --cross-check`: the traced tessellation's
// differences from the closed forms in the JSON (each <= the stated tolerance), its height
// maximum equal to the table's, the sign change of nu_HL there; bad flags exit 2 naming the
// flag and write nothing.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

TEST(MetamaterialCrossCheckCli, JsonReportsDifferencesAndHeightMaximum) {
  const auto r = test::run_command(test::cli() + " metamaterial --unit square-twist --alpha-deg 135 --b 1.2 --c 0.9 --cross-check --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("cross_check"));
  const auto& cc = j["cross_check"];
  const double tol = cc["tolerance"].get<double>();
  EXPECT_EQ(tol, 1e-9);
  for (const char* k : {"max_phi_difference_rad", "max_dimension_difference", "max_derivative_difference",
                        "max_ratio_difference", "max_stationary_theta_difference_rad", "max_stationary_height_difference"}) {
    EXPECT_GE(cc[k].get<double>(), 0.0) << k;
    EXPECT_LE(cc[k].get<double>(), tol) << k;
  }
  EXPECT_LE(cc["max_closure_residual"].get<double>(), 1e-12);
  EXPECT_TRUE(cc["nu_SL_negative"].get<bool>());
  // The traced height maximum is the table's (closed form) one.
  EXPECT_NEAR(cc["height_maximum"]["theta_deg_traced"].get<double>(), j["height_maximum"]["fold_deg"].get<double>(),
              to_degrees(1e-9));
  EXPECT_NEAR(cc["height_maximum"]["height_traced"].get<double>(), j["height_maximum"]["height"].get<double>(), 1e-9);
  ASSERT_EQ(cc["stationary_points"].size(), static_cast<std::size_t>(j["height_stationary_points"].get<int>()));
  for (const auto& q : cc["stationary_points"]) {
    const bool max = q["kind"] == "maximum";
    EXPECT_GT((max ? q["nu_HL_before"] : q["nu_HL_after"]).get<double>(), 0.0);
    EXPECT_LT((max ? q["nu_HL_after"] : q["nu_HL_before"]).get<double>(), 0.0);
  }
  // The nu_HL sign change of the table lies at the traced maximum.
  bool found = false;
  for (const auto& c : j["sign_changes"])
    if (c["ratio"] == "nu_HL" &&
        std::fabs(c["fold_deg"].get<double>() - cc["height_maximum"]["theta_deg_traced"].get<double>()) <= to_degrees(1e-9))
      found = true;
  EXPECT_TRUE(found) << r.out.substr(0, 2000);
  // Without the flag there is no cross_check.
  const auto plain = test::run_command(test::cli() + " metamaterial --unit square-twist --alpha-deg 135 --json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("cross_check"));
}

TEST(MetamaterialCrossCheckCli, TextReport) {
  const auto r = test::run_command(test::cli() + " metamaterial --unit square-twist --cross-check --cross-check-steps 60");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cross-check (3x3 T1 tessellation, general solver, 60 steps"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("H maximum at theta"), std::string::npos) << r.out;
}

TEST(MetamaterialCrossCheckCli, BadFlagsExit2NamingTheFlag) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_metamaterial_cc_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string plot = " --plot " + dir.string();
  const std::pair<const char*, const char*> cases[] = {
      {"--unit element1 --cross-check", "--cross-check"},
      {"--unit element3 --cross-check-steps 20", "--cross-check-steps"},
      {"--unit square-twist --cross-check-steps 20", "--cross-check-steps"},
      {"--unit square-twist --cross-check --cross-check-steps 5", "--cross-check-steps"},
      {"--unit square-twist --cross-check --cross-check-steps 100000", "--cross-check-steps"},
      // alpha 150: the sheet needs b, c > -cos(150 deg) = 0.866 (the table alone only 0.683).
      {"--unit square-twist --cross-check --b 0.8", "--b"},
      {"--unit square-twist --cross-check --c 0.7", "--c"},
  };
  for (const auto& [args, flag] : cases) {
    const auto r = test::run_command(test::cli() + " metamaterial " + args + plot);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(dir)) << args;
  }
  // The table alone accepts b = 0.8 at alpha 150.
  const auto ok = test::run_command(test::cli() + " metamaterial --unit square-twist --b 0.8 --json");
  EXPECT_EQ(ok.status, 0) << ok.err;
}

}}  // namespace
}  // namespace rigidfold
