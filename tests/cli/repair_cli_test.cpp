// `rigidfold repair` as a user runs it: a jittered Miura-ori repaired, the written pattern
// checked again by `rigidfold check` from its file; no file written and exit 3 when the
// least move exceeds --max-move; exit 2 naming the flag on a bad vertex index.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct RepairDir {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rigidfold_repair_" + std::to_string(::getpid()));
  RepairDir() {
    std::filesystem::create_directories(dir);
    const auto r = test::run_command(test::cli() + " generate miura --rows 5 --cols 6 --perturb 0.04 --seed 9 --out " + path("jittered.fold"));
    EXPECT_EQ(r.status, 0) << r.err;
  }
  ~RepairDir() { std::filesystem::remove_all(dir); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

TEST(RepairCli, RepairsAJitteredMiuraThatCheckThenCallsFoldable) {
  RepairDir d;
  const auto r = test::run_command(test::cli() + " repair " + d.path("jittered.fold") + " --out " + d.path("repaired.fold") + " --json");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"termination", "succeeded", "before", "after", "modes", "constraints", "violation", "move", "costliest", "stationarity"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["termination"], "repaired");
  EXPECT_EQ(j["before"]["rigidly_foldable"], false);
  EXPECT_EQ(j["after"]["verdict_class"], "foldable");
  EXPECT_GT(j["move"]["rms"].get<double>(), 0.0);
  EXPECT_LE(j["violation"]["kawasaki_after"].get<double>(), 1e-13);
  const auto c = test::run_command(test::cli() + " check " + d.path("repaired.fold") + " --json");
  ASSERT_EQ(c.status, 0) << c.err;
  const auto checked = nlohmann::json::parse(c.out);
  EXPECT_EQ(checked["verdict_class"], "foldable");
  EXPECT_EQ(checked["model"], "multiplier-propagation");
  EXPECT_LE(checked["certificate_mismatch"].get<double>(), 1e-12);
}

TEST(RepairCli, WritesNothingAndExits3WhenTheMoveExceedsTheBound) {
  RepairDir d;
  const auto r = test::run_command(test::cli() + " repair " + d.path("jittered.fold") + " --out " + d.path("repaired.fold") + " --max-move 1e-5");
  EXPECT_EQ(r.status, 3) << r.err << r.out;
  EXPECT_NE(r.out.find("no repair within max move"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(d.path("repaired.fold")));
}

TEST(RepairCli, BadVertexIndexIsExit2NamingTheFlag) {
  RepairDir d;
  const auto r = test::run_command(test::cli() + " repair " + d.path("jittered.fold") + " --out " + d.path("repaired.fold") + " --fix 3,9999");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("--fix"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("9999"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(d.path("repaired.fold")));
}

// Origami Simulator's square twists: their loop gain in the letters' modes is far from 1 (e^2.2
// and e^5.3); the least move that closes it collapses the twist until creases cross, so no file
// is written and the violation left at the last valid pattern along the move is reported.
TEST(RepairCli, OrigamiSimulatorsSquareTwistsGetTheViolationLeftNotARepair) {
  RepairDir d;
  for (const char* name : {"singlesquaretwist.svg", "squaretwistManyAngles.svg"}) {
    const std::string svg = std::string(RIGIDFOLD_CORPUS_DIR) + "/origami-simulator/" + name;
    const auto r = test::run_command(test::cli() + " repair " + svg + " --out " + d.path("twist.fold") + " --json");
    EXPECT_EQ(r.status, 3) << name << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["termination"], "no valid pattern") << name;
    EXPECT_TRUE(j["out"].is_null());
    EXPECT_GT(j["violation"]["loop_gain_before"].get<double>(), 2.0) << name;
    EXPECT_LT(j["violation"]["loop_gain_after"].get<double>(), 1e-3) << name;
    EXPECT_NE(j["message"].get<std::string>().find("last valid pattern"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(d.path("twist.fold")));
  }
}

TEST(RepairCli, AddCreasesWritesTheSeedsDiagonalForTheType2Twist) {
  RepairDir d;
  const std::string twist = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/square_twist_30_type2.fold";
  const auto r = test::run_command(test::cli() + " repair " + twist + " --add-creases --max-added 1 --out " + d.path("added.fold") + " --json");
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["termination"], "creases added");
  ASSERT_FALSE(j["found"].empty());
  EXPECT_EQ(j["found"][0]["verdict_class"], "foldable");
  const auto c = test::run_command(test::cli() + " check " + d.path("added.fold") + " --json");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["verdict_class"], "foldable");
  EXPECT_EQ(test::run_command(test::cli() + " repair " + twist + " --add-creases --max-move 1 --out " + d.path("x.fold")).status, 2);
}

TEST(RepairCli, ToleranceStudyOfTheBundledMiura) {
  const std::string miura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_12x12_folded.fold";
  const auto r = test::run_command(test::cli() + " check " + miura + " --tolerance-study 1e-3 --samples 3 --seed 2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out)["tolerance_study"];
  for (const char* key : {"sigma", "distribution", "seed", "samples", "foldable", "fraction", "interval_95", "verdicts", "loops", "repairs"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["samples"], 3);
  EXPECT_EQ(j["fraction"], 0.0);
  EXPECT_EQ(test::run_command(test::cli() + " check " + miura + " --samples 3").status, 2);
  EXPECT_EQ(test::run_command(test::cli() + " check " + miura + " --tolerance-study 0").status, 2);
}

}}  // namespace
}  // namespace rigidfold
