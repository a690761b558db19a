// Provenance: every JSON document a command prints or writes names the
// rigidfold version and commit and the command line it came from.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "data/generators/miura.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_provenance_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// "rigidfold 0.1.0 (commit abc)" -> {"0.1.0", "abc"}
std::pair<std::string, std::string> version_and_commit() {
  const auto r = test::run_command(test::cli() + " --version");
  EXPECT_EQ(r.status, 0);
  const std::string text = r.out.substr(0, r.out.find('\n'));
  const auto space = text.find(' '), open = text.find(" (commit "), close = text.rfind(')');
  EXPECT_NE(open, std::string::npos) << text;
  if (open == std::string::npos || close == std::string::npos) return {};
  return {text.substr(space + 1, open - space - 1), text.substr(open + 9, close - open - 9)};
}

TEST(ProvenanceCli, CheckJsonNamesVersionCommandAndOptions) {
  const auto dir = fresh_directory("check");
  generators::MiuraParams m;
  m.rows = 2;
  m.cols = 3;
  const std::string path = (dir / "miura.fold").string();
  write_fold(generators::miura_ori(m), path);
  const auto r = test::run_command(test::cli() + " check " + path + " --ignore-assignment --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("provenance"));
  const auto& p = j["provenance"];
  const auto [version, commit] = version_and_commit();
  EXPECT_FALSE(version.empty());
  EXPECT_EQ(p["rigidfold_version"], version);
  EXPECT_EQ(p["rigidfold_commit"], commit);
  EXPECT_EQ(p["command"], "check");
  EXPECT_EQ(p["arguments"], nlohmann::json({"check", path, "--ignore-assignment", "--json"}));
  EXPECT_EQ(p["options"], nlohmann::json({{"pattern", path}, {"--ignore-assignment", true}, {"--json", true}}));
  std::filesystem::remove_all(dir);
}

TEST(ProvenanceCli, NestedSubcommandAndRepeatedValues) {
  const auto r = test::run_command(test::cli() + " vertex s4r --twists 60,70,120,110 --input 30 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto p = nlohmann::json::parse(r.out)["provenance"];
  EXPECT_EQ(p["command"], "vertex s4r");
  EXPECT_EQ(p["arguments"], nlohmann::json({"vertex", "s4r", "--twists", "60,70,120,110", "--input", "30", "--json"}));
  EXPECT_EQ(p["options"]["--input"], "30");
  EXPECT_EQ(p["options"]["--json"], true);
  EXPECT_TRUE(p["options"].contains("--twists"));
}

TEST(ProvenanceCli, ReportJsonFileCarriesIt) {
  const auto dir = fresh_directory("report");
  std::filesystem::create_directories(dir / "in");
  generators::MiuraParams m;
  m.rows = 2;
  m.cols = 2;
  write_fold(generators::miura_ori(m), (dir / "in" / "miura.fold").string());
  const auto r = test::run_command(test::cli() + " report " + (dir / "in").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(dir / "out" / "report.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["provenance"]["command"], "report");
  EXPECT_EQ(j["provenance"]["options"]["--out"], (dir / "out").string());
  std::filesystem::remove_all(dir);
}

}}  // namespace
}  // namespace rigidfold
