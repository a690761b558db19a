// `rigidfold assignments`: seed 003's unit P from the bundled file (10 classes, 4 rigid, each
// listed with its verdict), the blocking vertex of a pattern off Kawasaki, exit 2 naming the
// flag or the file on bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

const std::string kBundled = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/";

TEST(AssignmentsCli, UnitPHasTenClassesFourRigid) {
  const auto r = test::run_command(test::cli() + " assignments " + kBundled + "corrugated_p_rigid.fold --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["complete"].get<bool>());
  EXPECT_EQ(j["assignments"].get<long>(), 32);
  EXPECT_EQ(j["classes"].get<long>(), 10);
  EXPECT_EQ(j["foldable_classes"].get<long>(), 4);
  ASSERT_EQ(j["listed"].size(), 10u);
  long orbits = 0, rigid = 0;
  for (const auto& c : j["listed"]) {
    EXPECT_EQ(c["letters"].get<std::string>().size(), j["creases"].size());
    orbits += c["orbit_size"].get<long>();
    rigid += c["verdict"].get<std::string>() == "foldable";
  }
  EXPECT_EQ(orbits, 32);
  EXPECT_EQ(rigid, 4);
  const auto text = test::run_command(test::cli() + " assignments " + kBundled + "corrugated_p_rigid.fold --list 3");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("in 10 classes"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("7 more classes"), std::string::npos) << text.out;
}

// A search stopped by --max-assignments knows no class count: null, never a number that
// reads as the answer (it printed 0 classes for a 4x4 square-twist tessellation).
TEST(AssignmentsCli, StoppedSearchGivesNoClassCount) {
  const auto r = test::run_command(test::cli() + " assignments " + kBundled + "corrugated_p_rigid.fold --json --max-assignments 5");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["complete"].get<bool>());
  EXPECT_EQ(j["assignments"].get<long>(), 5);
  EXPECT_TRUE(j["classes"].is_null());
  EXPECT_LE(j["classes_reached"].get<long>(), 5);
  const auto text = test::run_command(test::cli() + " assignments " + kBundled + "corrugated_p_rigid.fold --max-assignments 5");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("class count unknown"), std::string::npos) << text.out;
}

TEST(AssignmentsCli, NamesTheVertexOffKawasaki) {
  const auto r = test::run_command(test::cli() + " assignments " + kBundled + "miura_3x3_perturbed.fold --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["assignments"].get<long>(), 0);
  EXPECT_NE(j["no_assignment_because"]["reason"].get<std::string>().find("Kawasaki"), std::string::npos);
}

TEST(AssignmentsCli, BadInputExitsTwoNamingThePlace) {
  const std::string p = kBundled + "corrugated_p_rigid.fold";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {p + " --list -1", "--list"},
      {p + " --list 100001", "--list"},
      {p + " --max-assignments 0", "--max-assignments"},
      {p + " --max-verdicts -3", "--max-verdicts"},
      {p + " --max-verdicts x", "--max-verdicts"},
      {kBundled + "no_such_file.fold", "no_such_file.fold"},
      {kBundled + "miura_tube_6_alpha60.fold", "miura_tube_6_alpha60.fold: vertices_coords["},  // 3D: not flat
  };
  for (const auto& [args, place] : cases) {
    const auto r = test::run_command(test::cli() + " assignments " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(place), std::string::npos) << args << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

}}  // namespace
}  // namespace rigidfold
