// `rigidfold metamaterial`: JSON that agrees with the library's independent height maximum,
// --plot writing its three files, bad flags exiting 2 naming the flag, and refused outputs
// writing nothing.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "design/metamaterial/corrugated_elements.hpp"
#include "design/metamaterial/square_twist_unit.hpp"
#include "kernel/math/angle_units.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("rigidfold_metamaterial_cli_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(MetamaterialCli, SquareTwistJsonHeightMaximumAndNuHLSignChange) {
  const auto r = test::run_command(test::cli() + " metamaterial --unit square-twist --alpha-deg 135 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  metamaterial::SquareTwistUnitParams p;
  p.alpha = to_radians(135.0);
  const auto m = metamaterial::square_twist_height_maximum(p);
  EXPECT_NEAR(to_radians(j["height_maximum"]["fold_deg"].get<double>()), m.theta, 1e-9);
  EXPECT_NEAR(j["height_maximum"]["height"].get<double>(), m.height, 1e-12);
  int hl = 0;
  for (const auto& c : j["sign_changes"]) {
    EXPECT_EQ(c["ratio"], "nu_HL");  // nu_SL < 0 throughout
    EXPECT_NEAR(to_radians(c["fold_deg"].get<double>()), m.theta, 1e-9);
    EXPECT_TRUE(c["negative_after"].get<bool>());
    ++hl;
  }
  EXPECT_EQ(hl, 1);
  ASSERT_EQ(j["rows"].size(), 181u);
  // Each row is the closed form at its fold angle (full precision).
  const auto& row = j["rows"][40];
  const auto s = metamaterial::square_twist_unit(p, to_radians(row["fold_deg"].get<double>()));
  EXPECT_NEAR(row["H"].get<double>(), s.H, 1e-15);
  EXPECT_NEAR(row["nu_HL"].get<double>(), s.nu_HL, 1e-12 * std::fabs(s.nu_HL));
  EXPECT_LE(j["checks"]["max_constraint_residual"].get<double>(), 1e-12);
}

TEST(MetamaterialCli, DefaultTextSummary) {
  const auto r = test::run_command(test::cli() + " metamaterial --unit element1");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("height maximum"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nu_out changes sign"), std::string::npos) << r.out;
  const auto h = test::run_command(test::cli() + " metamaterial --help");
  EXPECT_NE(h.out.find("default 150"), std::string::npos);
}

TEST(MetamaterialCli, PlotWritesCsvAndSvgs) {
  const fs::path d = scratch("plot");
  const auto r = test::run_command(test::cli() + " metamaterial --unit element3 --samples 50 --json --plot " + d.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::string csv = read(d / "metamaterial.csv");
  std::size_t lines = 0;
  for (char ch : csv) lines += ch == '\n';
  EXPECT_EQ(lines, 51u);
  EXPECT_EQ(csv.rfind("fold_deg,second_angle_deg,W,L,H,", 0), 0u);
  // The CSV's first data row is the JSON's first row.
  const std::string first = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(std::strtod(first.c_str(), nullptr), j["rows"][0]["fold_deg"].get<double>());
  for (const char* f : {"dimensions.svg", "poisson.svg"}) {
    const std::string svg = read(d / f);
    EXPECT_NE(svg.find("<svg"), std::string::npos) << f;
    EXPECT_NE(svg.find("<polyline"), std::string::npos) << f;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << f;
  }
  fs::remove_all(d);
}

TEST(MetamaterialCli, BadFlagsExitTwoNamingTheFlagAndWriteNothing) {
  const fs::path d = scratch("bad");
  const std::string plot = " --plot " + d.string();
  const std::pair<const char*, const char*> cases[] = {
      {"--unit foo", "--unit"},
      {"--unit P", "--unit"},
      {"--unit square-twist --alpha-deg 80", "--alpha-deg"},
      {"--unit square-twist --alpha-deg 180", "--alpha-deg"},
      {"--unit square-twist --alpha-deg nan", "--alpha-deg"},
      {"--unit square-twist --beta-deg 30", "--beta-deg"},
      {"--unit square-twist --a 0", "--a"},
      {"--unit square-twist --b 0.1", "--b"},
      {"--unit square-twist --c -1", "--c"},
      {"--unit element1 --a 2", "--a"},
      {"--unit element2 --l 0", "--l"},
      {"--unit element2 --beta-deg inf", "--beta-deg"},
      {"--unit element3 --alpha-deg 60 --beta-deg 120", "--beta-deg"},
      {"--unit element1 --samples 2", "--samples"},
      {"--unit element1 --samples 100001", "--samples"},
  };
  for (const auto& [args, flag] : cases) {
    const auto r = test::run_command(test::cli() + " metamaterial " + args + plot);
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(flag), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(fs::exists(d)) << args;
  }
}

TEST(MetamaterialCli, RefusesDeviceAndFileAsPlotDirectory) {
  // The command reads no input file; its outputs are refused where DIR is a device or a file.
  auto r = test::run_command(test::cli() + " metamaterial --unit square-twist --plot /dev/null");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
  const fs::path f = scratch("file");
  { std::ofstream(f) << "keep"; }
  r = test::run_command(test::cli() + " metamaterial --unit square-twist --plot " + f.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
  EXPECT_EQ(read(f), "keep");
  fs::remove(f);
  // An existing directory whose output name is taken by a directory: refused, nothing written.
  const fs::path d = scratch("taken");
  fs::create_directories(d / "poisson.svg");
  r = test::run_command(test::cli() + " metamaterial --unit square-twist --plot " + d.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_FALSE(fs::exists(d / "metamaterial.csv"));
  EXPECT_FALSE(fs::exists(d / "dimensions.svg"));
  fs::remove_all(d);
}

}}  // namespace
}  // namespace rigidfold
