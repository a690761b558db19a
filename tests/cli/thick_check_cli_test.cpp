// `rigidfold check` and `rigidfold trace` on a thick FOLD (see
// kernel/thick/thick_check.hpp): the file `rigidfold thick --out` writes is answered with the
// thick model - Bennett heights on the bundled 4 x 4 Miura-ori are mobile with DOF 1 and the
// trace lands on the `thick` command's own trace; valley-side hinges are rigid (DOF 0 at flat);
// bad extension data exits 2 naming its JSON path; trace refuses --out for a thick FOLD, and
// both refuse --ignore-assignment, --general and --tolerance there.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

namespace fs = std::filesystem;

const std::string kMiura = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_4x4_alpha60.fold";

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rigidfold_thick_check_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// The thick FOLD of the bundled Miura with the given hinges (written once per placement).
std::string thick_fold(const std::string& hinges, nlohmann::ordered_json* thick_report = nullptr) {
  const std::string path = scratch("miura_" + hinges + ".fold").string();
  const auto r = test::run_command(test::cli() + " thick " + kMiura + " --thickness 0.05 --hinges " + hinges + " --json --out " + path);
  EXPECT_EQ(r.status, 0) << r.err;
  if (thick_report) *thick_report = nlohmann::ordered_json::parse(r.out);
  return path;
}

nlohmann::ordered_json run_json(const std::string& args) {
  const auto r = test::run_command(test::cli() + " " + args + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return nlohmann::ordered_json::parse(r.out);
}

TEST(ThickCheckCli, BennettMiuraIsMobileAndTracedOnTheThickCommandsMotion) {
  nlohmann::ordered_json thick;
  const std::string path = thick_fold("bennett", &thick);
  const auto c = run_json("check " + path);
  EXPECT_EQ(c["model"], "thick");
  EXPECT_EQ(c["verdict"], "mobile");
  // The headline in the shared vocabulary: "foldable" only when no hinge ends against its letter.
  EXPECT_EQ(c["verdict_class"], c["trace"]["letter_disagreements_at_end"].get<int>() == 0 ? "foldable" : "undecided");
  EXPECT_EQ(c["flat_state"]["dof"].get<int>(), 1);
  EXPECT_EQ(c["thick_vertices"].get<int>(), 9);  // the 3 x 3 interior vertices
  EXPECT_EQ(c["trace"]["dof_max"].get<int>(), 1);
  EXPECT_LE(c["trace"]["max_residual"].get<double>(), 1e-10);
  std::ifstream in(path);
  const auto doc = nlohmann::ordered_json::parse(in);
  double thickest = 0.0;
  for (const auto& t : doc["rigidfold:thickness"]) thickest = std::max(thickest, t.get<double>());
  EXPECT_EQ(c["thickness_max"].get<double>(), thickest);

  // `trace` with the thick command's driving crease and angles lands where `thick` traced
  // (its trace follows the zero-thickness motion; this one is continuation on the sheet alone).
  const auto& steps = thick["trace"]["steps"];
  ASSERT_GE(steps.size(), 2u);
  const int drive = thick["trace"]["driving_crease"].get<int>();
  const double to = steps.back()["drive_deg"].get<double>();
  const auto t = run_json("trace " + path + " --drive " + std::to_string(drive) + " --to " + std::to_string(to) + " --steps " +
                          std::to_string(steps.size()));
  EXPECT_EQ(t["model"], "thick");
  ASSERT_EQ(t["trace"]["steps"].size(), steps.size());
  double worst = 0.0;
  std::size_t compared = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const auto& mine = t["trace"]["steps"][k];
    EXPECT_EQ(mine["dof"].get<int>(), 1);
    EXPECT_LE(mine["residual"].get<double>(), 1e-10);
    // --to was printed with 6 decimals: compare where both are at the same driving angle.
    if (std::abs(mine["drive_deg"].get<double>() - steps[k]["drive_deg"].get<double>()) > 1e-12) continue;
    ++compared;
    ASSERT_EQ(mine["fold_angles_deg"].size(), steps[k]["fold_angles_deg"].size());
    for (std::size_t e = 0; e < steps[k]["fold_angles_deg"].size(); ++e)
      worst = std::max(worst, std::abs(mine["fold_angles_deg"][e].get<double>() - steps[k]["fold_angles_deg"][e].get<double>()));
  }
  EXPECT_EQ(compared, steps.size());
  EXPECT_LE(worst, 1e-8);  // degrees
}

TEST(ThickCheckCli, ValleySideHingesAreRigid) {
  const auto c = run_json("check " + thick_fold("valley"));
  EXPECT_EQ(c["model"], "thick");
  EXPECT_EQ(c["verdict"], "rigid");
  EXPECT_EQ(c["verdict_class"], "not foldable (proof)");
  EXPECT_EQ(c["flat_state"]["dof"].get<int>(), 0);
  EXPECT_GT(c["flat_state"]["smallest_kept_singular_value"].get<double>(), 1e3 * c["flat_state"]["rank_cut"].get<double>());
  // A zero-thickness FOLD is still the zero-thickness model.
  EXPECT_NE(run_json("check " + kMiura)["model"], "thick");
}

TEST(ThickCheckCli, BadExtensionExitsTwoNamingTheJsonPath) {
  const std::string good = thick_fold("bennett");
  std::ifstream in(good);
  const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(in);
  struct Case {
    const char* key;
    int index;
    nlohmann::ordered_json value;
    const char* place;
  };
  const Case cases[] = {{"rigidfold:thickness", 2, -1.0, "rigidfold:thickness[2]"},
                        {"rigidfold:thickness", 0, "thick", "rigidfold:thickness[0]"},
                        {"rigidfold:hinge_heights", 3, 7.5, "rigidfold:hinge_heights[3]"},
                        {"rigidfold:hinge_heights", 1, "high", "rigidfold:hinge_heights[1]"}};
  for (const Case& c : cases) {
    nlohmann::ordered_json bad = doc;
    bad[c.key][c.index] = c.value;
    const std::string path = scratch("bad.fold").string();
    std::ofstream(path) << bad.dump();
    for (const char* command : {"check", "trace"}) {
      const auto r = test::run_command(test::cli() + " " + command + " " + path);
      EXPECT_EQ(r.status, 2) << command << " " << c.place << ": " << r.out;
      EXPECT_NE(r.err.find(c.place), std::string::npos) << command << ": " << r.err;
    }
  }
  nlohmann::ordered_json missing = doc;
  missing.erase("rigidfold:thickness");
  const std::string path = scratch("missing.fold").string();
  std::ofstream(path) << missing.dump();
  const auto r = test::run_command(test::cli() + " check " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("rigidfold:thickness"), std::string::npos) << r.err;

  const std::string out = scratch("frames.fold").string();
  const auto t = test::run_command(test::cli() + " trace " + good + " --out " + out);
  EXPECT_EQ(t.status, 2);
  EXPECT_NE(t.err.find("--out"), std::string::npos) << t.err;
  EXPECT_FALSE(fs::exists(out));
  const auto d = test::run_command(test::cli() + " trace " + good + " --drive 100000");
  EXPECT_EQ(d.status, 2);
  EXPECT_NE(d.err.find("--drive"), std::string::npos) << d.err;
}

// Flags with no meaning for the thick model are refused, not silently ignored: the thick
// model always runs the general SE(3) solver, reports the letters its motion keeps, and
// judges its numbers as written.
TEST(ThickCheckCli, FlagsTheThickModelCannotHonourExitTwo) {
  const std::string good = thick_fold("bennett");
  for (const char* command : {"check", "trace"})
    for (const char* flag : {"--ignore-assignment", "--general", "--tolerance 1e-6", "--tolerance auto"}) {
      const auto r = test::run_command(test::cli() + " " + command + " " + good + " " + flag);
      EXPECT_EQ(r.status, 2) << command << " " << flag << ": " << r.out;
      const std::string name = std::string(flag).substr(0, std::string(flag).find(' '));
      EXPECT_NE(r.err.find(name), std::string::npos) << command << " " << flag << ": " << r.err;
      EXPECT_TRUE(r.out.empty()) << command << " " << flag << ": " << r.out;
    }
  const auto plain = test::run_command(test::cli() + " check " + good);
  EXPECT_EQ(plain.status, 0) << plain.err;
}

}}  // namespace
}  // namespace rigidfold
