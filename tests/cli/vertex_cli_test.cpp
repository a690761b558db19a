// `rigidfold vertex s4r`: JSON shape, full-precision numbers, branches that close the loop,
// and exit 2 on bad flags.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "kernel/vertex/vertex_closure.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace {

TEST(VertexCli, S4RJsonBranchesCloseTheLoop) {
  const auto r = test::run_command(test::cli() + " vertex s4r --twists 50,110,100,95 --input 35 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["feasible"].get<bool>());
  ASSERT_EQ(j["branches"].size(), 2u);
  const double k = std::numbers::pi / 180;
  const std::vector<double> sectors{50 * k, 110 * k, 100 * k, 95 * k};
  for (const auto& b : j["branches"]) {
    const auto deg = b["angles_deg"].get<std::vector<double>>();
    ASSERT_EQ(deg.size(), 4u);
    EXPECT_DOUBLE_EQ(deg[0], 35.0);
    std::vector<double> rho;
    for (double d : deg) rho.push_back(d * k);
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

}  // namespace
}  // namespace rigidfold
