// `rigidfold waterbomb`: JSON with round-trip numbers that agree with the library, stable
// states that close their loop, and exit 2 naming the flag on bad input.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_curve.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(WaterbombCli, JsonMatchesLibraryAndCloses) {
  const auto r = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --k-ratio 1.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto lib = waterbomb::waterbomb_bistability(4, to_radians(60.0), 1.5, 1.0);
  ASSERT_EQ(j["equilibria"].size(), lib.equilibria.size());
  int stable = 0;
  for (std::size_t i = 0; i < lib.equilibria.size(); ++i) {
    const auto& e = j["equilibria"][i];
    // Full precision: the printed numbers are the library's doubles.
    EXPECT_EQ(e["theta_deg"].get<double>(), to_degrees(lib.equilibria[i].path.theta));
    EXPECT_EQ(e["energy"].get<double>(), lib.equilibria[i].path.energy);
    const double gm = to_radians(e["gamma_m_deg"].get<double>()), gv = to_radians(e["gamma_v_deg"].get<double>());
    std::vector<double> sectors(8, kPi / 4), rho(8);
    for (int k = 0; k < 8; ++k) rho[k] = k % 2 ? gm : gv;
    EXPECT_LT(vertex_closure_residual(sectors, rho).norm(), 1e-12);
    if (e["stable"].get<bool>()) {
      ++stable;
      EXPECT_GT(e["min_reduced_hessian_eigenvalue"].get<double>(), 0.0);
    }
  }
  EXPECT_EQ(stable, 2);
  // Symmetric-path barriers: the flat cusp's energy above each stable state, both positive.
  ASSERT_EQ(j["barriers"].size(), 2u);
  for (const auto& b : j["barriers"]) EXPECT_GT(b["symmetric_path_barrier"].get<double>(), 0.0);
  EXPECT_GT(j["barriers"][0]["symmetric_path_barrier"].get<double>(), j["barriers"][1]["symmetric_path_barrier"].get<double>());
}

TEST(WaterbombCli, TextNamesStableStates) {
  const auto r = test::run_command(test::cli() + " waterbomb --n 3 --theta0-deg 50 --k-m 2 --k-v 1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("STABLE"), std::string::npos);
  EXPECT_NE(r.out.find("cusp maximum"), std::string::npos);
}

TEST(WaterbombCli, BadInputExitsTwoNamingTheFlag) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--n 2 --theta0-deg 60", "--n"},
      {"--n 4 --theta0-deg 135.5", "--theta0-deg"},
      {"--n 4 --theta0-deg -1", "--theta0-deg"},
      {"--n 4 --theta0-deg nan", "--theta0-deg"},
      {"--n 4 --theta0-deg 60 --k-m -1 --k-v 1", "--k-m"},
      {"--n 4 --theta0-deg 60 --k-m 1 --k-v inf", "--k-v"},
      {"--n 4 --theta0-deg 60 --k-ratio -0.5", "--k-ratio"},
      {"--n 4 --theta0-deg 60 --k-ratio 1 --k-m 1 --k-v 1", "--k-ratio"},
  };
  for (const auto& [flags, name] : cases) {
    const auto r = test::run_command(test::cli() + " waterbomb " + flags);
    EXPECT_EQ(r.status, 2) << flags;
    EXPECT_NE(r.err.find(name), std::string::npos) << flags << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << flags;
  }
}

// --curve: the CSV holds the library's checked samples digit for digit; bad --samples or
// --samples without --curve exit 2 and write nothing.
TEST(WaterbombCli, CurveWritesTheCheckedSamples) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_waterbomb_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string csv = (dir / "curve.csv").string();
  const auto r = test::run_command(test::cli() + " waterbomb --n 5 --theta0-deg 50 --k-ratio 2 --curve " + csv + " --samples 21");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto lib = waterbomb::waterbomb_curve(5, to_radians(50.0), 2.0, 1.0, 21);
  std::ifstream in(csv);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line.rfind("theta_deg,gamma_m_deg,gamma_v_deg,energy,", 0), 0u) << line;
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    ASSERT_LT(rows, lib.samples.size());
    std::stringstream fields(line);
    std::string theta_text, skip, energy_text;
    std::getline(fields, theta_text, ',');
    std::getline(fields, skip, ',');
    std::getline(fields, skip, ',');
    std::getline(fields, energy_text, ',');
    EXPECT_EQ(std::stod(theta_text), to_degrees(lib.samples[rows].theta));
    EXPECT_EQ(std::stod(energy_text), lib.samples[rows].energy);
    ++rows;
  }
  EXPECT_EQ(rows, lib.samples.size());
  for (const std::string& flags : {"--curve " + (dir / "bad.csv").string() + " --samples 2", std::string("--samples 11")}) {
    const auto bad = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 " + flags);
    EXPECT_EQ(bad.status, 2) << flags;
    EXPECT_NE(bad.err.find("--samples"), std::string::npos) << bad.err;
  }
  EXPECT_FALSE(fs::exists(dir / "bad.csv"));
  fs::remove_all(dir);
}

// --target-switching-force: the designed k_m, fed back with --k-m, switches at the target.
TEST(WaterbombCli, DesignedStiffnessSwitchesAtTheTarget) {
  const auto d = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60 --target-switching-force 20 --json");
  ASSERT_EQ(d.status, 0) << d.err;
  const double k_m = nlohmann::json::parse(d.out)["design"]["k_m"].get<double>();
  char flags[96];
  std::snprintf(flags, sizeof flags, " --k-m %.17g --k-v 1 --json", k_m);
  const auto f = test::run_command(test::cli() + " waterbomb --n 4 --theta0-deg 60" + flags);
  ASSERT_EQ(f.status, 0) << f.err;
  EXPECT_NEAR(nlohmann::json::parse(f.out)["switching_force"]["force"].get<double>(), 20.0, 1e-9);
  for (const std::string& bad : {std::string("--theta0-deg 60 --target-switching-force -1"),
                                 std::string("--theta0-deg 100 --target-switching-force 5")}) {
    const auto r = test::run_command(test::cli() + " waterbomb --n 4 " + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--target-switching-force"), std::string::npos) << r.err;
  }
}

}}  // namespace
}  // namespace rigidfold
