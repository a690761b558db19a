// `rigidfold vertex s4r` and `rigidfold vertex miura`: JSON shape, full-precision numbers,
// values against the library, and exit 2 on bad flags.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "kernel/math/angle_units.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(VertexCli, S4RJsonBranchesCloseTheLoop) {
  const auto r = test::run_command(test::cli() + " vertex s4r --twists 50,110,100,95 --input 35 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["feasible"].get<bool>());
  ASSERT_EQ(j["branches"].size(), 2u);
  const std::vector<double> sectors{to_radians(50), to_radians(110), to_radians(100), to_radians(95)};
  for (const auto& b : j["branches"]) {
    const auto deg = b["angles_deg"].get<std::vector<double>>();
    ASSERT_EQ(deg.size(), 4u);
    EXPECT_DOUBLE_EQ(deg[0], 35.0);
    std::vector<double> rho;
    for (double d : deg) rho.push_back(to_radians(d));
    // Numbers are printed with full precision: the parsed angles still close to 1e-12.
    EXPECT_LT(vertex_closure_residual(sectors, rho).norm(), 1e-12);
  }
}

TEST(VertexCli, S4RReportsInfeasibleInputOutsideTheMotionLimits) {
  // Twists 90, 30, 90, 40 (not developable): |theta1| is bounded below, so 1 deg is infeasible.
  const auto r = test::run_command(test::cli() + " vertex s4r --twists 90,30,90,40 --input 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["feasible"].get<bool>());
  EXPECT_TRUE(j["branches"].empty());
  const double lo = j["input_range_deg"]["min_abs"].get<double>();
  const double hi = j["input_range_deg"]["max_abs"].get<double>();
  EXPECT_GT(lo, 1.0);
  EXPECT_LT(hi, 180.0);
  // Inside the range both branches exist.
  const auto in = nlohmann::json::parse(test::run_command(test::cli() + " vertex s4r --twists 90,30,90,40 --input 90 --json").out);
  EXPECT_EQ(in["branches"].size(), 2u);
}

TEST(VertexCli, S4RBadFlagsExitTwo) {
  EXPECT_EQ(test::run_command(test::cli() + " vertex s4r --twists 60,120,120 --input 40").status, 2);
  EXPECT_EQ(test::run_command(test::cli() + " vertex s4r --twists 60,120,120,60 --input 400").status, 2);
  EXPECT_EQ(test::run_command(test::cli() + " vertex s4r --twists 60,a,120,60 --input 4").status, 2);
  EXPECT_EQ(test::run_command(test::cli() + " vertex s4r --twists 60,120,120,60").status, 2);
}

TEST(VertexCli, MiuraJsonMatchesTheLibrary) {
  for (const char* theta : {"40", "-12.5", "1e-7"}) {
    const auto r = test::run_command(test::cli() + " vertex miura --alpha1 30 --alpha2 60 --theta " + theta + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const MiuraVertexState st = miura_vertex(to_radians(30), to_radians(60), to_radians(std::stod(theta)));
    // Full-precision output: the parsed degrees are the library's values times 180/pi.
    EXPECT_DOUBLE_EQ(j["phi_deg"].get<double>(), to_degrees(st.phi));
    EXPECT_DOUBLE_EQ(j["psi_deg"].get<double>(), to_degrees(st.psi));
    EXPECT_DOUBLE_EQ(j["theta_limit_deg"].get<double>(), to_degrees(miura_theta_limit(to_radians(30), to_radians(60))));
    ASSERT_EQ(j["fold_angles_deg"].size(), 4u);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(j["fold_angles_deg"][i]["crease"].get<std::string>(), std::string(kMiuraCreaseNames[i]));
      EXPECT_DOUBLE_EQ(j["fold_angles_deg"][i]["fold_angle_deg"].get<double>(), to_degrees(st.fold_angles[i]));
    }
    EXPECT_LT(j["closure_residual_rad"].get<double>(), 1e-12);
  }
  // Eq. (40) at 30/60 deg: 90 - acos(1/3)/2 = 54.7356... deg; the printed limit is accepted.
  const auto lim = nlohmann::json::parse(test::run_command(test::cli() + " vertex miura --alpha1 60 --alpha2 30 --theta 0 --json").out);
  EXPECT_NEAR(lim["theta_limit_deg"].get<double>(), 54.735610317245346, 1e-12);
  char flag[64];
  std::snprintf(flag, sizeof flag, "%.17g", lim["theta_limit_deg"].get<double>());
  EXPECT_EQ(test::run_command(test::cli() + " vertex miura --alpha1 60 --alpha2 30 --theta " + flag).status, 0);
}

TEST(VertexCli, MiuraTextOutput) {
  const auto r = test::run_command(test::cli() + " vertex miura --alpha1 45 --alpha2 45 --theta 30");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("phi = "), std::string::npos);
  EXPECT_NE(r.out.find("psi = 0 deg"), std::string::npos);  // symmetric vertex: exactly 0
  for (auto name : kMiuraCreaseNames) EXPECT_NE(r.out.find(std::string(name)), std::string::npos);
}

TEST(VertexCli, MiuraBadFlagsExitTwoNamingTheFlag) {
  const std::string base = test::cli() + " vertex miura ";
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--alpha1 0 --alpha2 40 --theta 10", "--alpha1"},     {"--alpha1 90 --alpha2 40 --theta 10", "--alpha1"},
      {"--alpha1 30 --alpha2 -5 --theta 10", "--alpha2"},    {"--alpha1 nan --alpha2 40 --theta 10", "--alpha1"},
      {"--alpha1 30 --alpha2 60 --theta 55", "--theta"},     {"--alpha1 30 --alpha2 60 --theta -55", "--theta"},
      {"--alpha1 30 --alpha2 60 --theta inf", "--theta"},    {"--alpha1 30 --alpha2 60 --theta abc", "--theta"},
      {"--alpha1 30 --alpha2 60", "--theta"},
  };
  for (const auto& [args, flag] : cases) {
    const auto r = test::run_command(base + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(r.out.empty()) << args;
    EXPECT_NE(r.err.find(flag), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

}}  // namespace
}  // namespace rigidfold
