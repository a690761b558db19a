// bundled_examples(), the committed files in data/bundled/, and `rigidfold generate`.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "data/generators/bundled_examples.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "tests/data/generator_test_utils.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold::test {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(GeneratorBundle, NamesAndContents) {
  const auto examples = generators::bundled_examples();
  std::set<std::string> names;
  for (const auto& [name, p] : examples) {
    names.insert(name);
    EXPECT_FALSE(p.extra.value("file_title", std::string()).empty()) << name;
    EXPECT_FALSE(p.extra.value("frame_title", std::string()).empty()) << name;
    EXPECT_GT(p.num_faces(), 0) << name;
    EXPECT_TRUE(p.warnings.empty()) << name << ": " << (p.warnings.empty() ? "" : p.warnings[0]);
  }
  EXPECT_EQ(names, (std::set<std::string>{"miura_4x4_alpha60", "miura_12x12_folded", "miura_3x3_perturbed", "miura_tube_6_alpha60", "square_twist_30_type1",
                                          "square_twist_30_type2", "square_twist_30_type3", "square_twist_30_type4",
                                          "square_twist_30_type1m", "square_twist_30_type2m", "waterbomb_base",
                                          "corrugated_p_rigid", "corrugated_q_rigid"}));
}

// The committed data/bundled/*.fold must be what the generators produce now.
TEST(GeneratorBundle, CommittedFilesAreUpToDate) {
  const std::filesystem::path dir = std::filesystem::path(RIGIDFOLD_SOURCE_DIR) / "data" / "bundled";
  for (const auto& [name, p] : generators::bundled_examples()) {
    const auto path = dir / (name + ".fold");
    ASSERT_TRUE(std::filesystem::exists(path)) << path << " missing: run rigidfold generate bundle --out-dir data/bundled";
    const CreasePattern stored = read_fold(path.string());
    ASSERT_EQ(stored.num_vertices(), p.num_vertices()) << name << " is stale: regenerate data/bundled";
    for (int v = 0; v < p.num_vertices(); ++v)  // tolerance: libm may differ in the last bit elsewhere
      EXPECT_LE((stored.vertices[v] - p.vertices[v]).norm(), 1e-12) << name << " vertex " << v << " is stale";
    EXPECT_EQ(stored.edges, p.edges) << name;
    EXPECT_EQ(stored.assignments, p.assignments) << name;
    EXPECT_EQ(stored.num_faces(), p.num_faces()) << name;
    EXPECT_EQ(stored.extra.value("file_title", std::string()), p.extra.value("file_title", std::string())) << name;
    EXPECT_EQ(stored.extra.value("frame_title", std::string()), p.extra.value("frame_title", std::string())) << name;
    EXPECT_EQ(stored.extra["rigidfold:generator"], p.extra["rigidfold:generator"]) << name;
  }
}

TEST(GeneratorCli, WritesEveryKindAndBundle) {
  const auto dir = std::filesystem::temp_directory_path() / ("rigidfold_generate_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string out = (dir / "x.fold").string();
  for (const std::string args :
       {"miura --rows 2 --cols 3 --alpha-deg 50 --a 2 --b 1", "miura --perturb 0.05 --seed 3", "miura --fold-deg 40",
        "square-twist --twist-deg 20 --type 4", "square-twist --type 2M",
        "square-twist --assignment MMMMMVMVMVMVV --diagonal BD", "waterbomb --n 6 --corners V",
        "corrugated-p --alpha-deg 120 --beta-deg 80", "corrugated-q --odd 3434",
        "corrugated-p --assignment 'MVVM MV VV VM MM'", "miura-tube --rows 3 --fold-deg 70",
        "square-twist-tessellation --rows 2 --cols 3 --layout type3-rows"}) {
    const auto r = run_command(cli() + " generate " + args + " --out " + out);
    EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
    EXPECT_NO_THROW(read_fold(out)) << args;
  }
  const CreasePattern folded = [&] {
    run_command(cli() + " generate miura --rows 2 --cols 2 --fold-deg 40 --out " + out);
    return read_fold(out);
  }();
  // The interior creases of a 2x2 Miura carry their angle; B/F/J edges are written as 0
  // (FOLD 1.2 numbers, no null).
  int creases_with_angle = 0;
  for (int e = 0; e < folded.num_edges(); ++e) {
    const bool crease = folded.assignments[e] == Assignment::Mountain || folded.assignments[e] == Assignment::Valley;
    if (crease) {
      creases_with_angle += folded.fold_angles[e].has_value() && *folded.fold_angles[e] != 0.0;
    } else if (folded.fold_angles[e]) {
      EXPECT_EQ(*folded.fold_angles[e], 0.0) << "edge " << e;
    }
  }
  EXPECT_EQ(creases_with_angle, 4);

  const auto bundle = run_command(cli() + " generate bundle --out-dir " + (dir / "bundle").string());
  EXPECT_EQ(bundle.status, 0) << bundle.err;
  for (const auto& [name, p] : generators::bundled_examples())
    EXPECT_TRUE(std::filesystem::exists(dir / "bundle" / (name + ".fold"))) << name;
  std::filesystem::remove_all(dir);
}

TEST(GeneratorCli, BadFlagsNameTheFlagAndExitTwo) {
  const auto out = (std::filesystem::temp_directory_path() / ("rigidfold_bad_" + std::to_string(::getpid()) + ".fold")).string();
  const std::vector<std::pair<std::string, std::string>> cases{
      {"miura --alpha-deg 95", "--alpha-deg"},
      {"miura --rows 0", "--rows"},
      {"miura --perturb 9", "--perturb"},
      {"miura --twist-deg 30", "--twist-deg"},
      {"miura --seed -1 --perturb 0.01", "--seed"},
      {"miura --alpha-deg 0", "--alpha-deg"},
      {"square-twist --type 1 --assignment MMMMMMMMMMMM", "--type"},
      {"square-twist --type 7", "--type"},
      {"square-twist --twist-deg 90", "--twist-deg"},
      {"square-twist --assignment MMX", "--assignment"},
      {"waterbomb --n 2", "--n"},
      {"corrugated-p --beta-deg 10", "--beta-deg"},
      {"corrugated-q --odd 3444", "--odd"},
      {"miura-tube --fold-deg 180", "--fold-deg"},
      {"miura-tube --cols 3", "--cols"},
      {"square-twist-tessellation --layout spiral", "--layout"},
      {"square-twist-tessellation --spacing 1", "--spacing"},
      {"origami", "KIND"},
  };
  for (const auto& [args, flag] : cases) {
    const auto r = run_command(cli() + " generate " + args + " --out " + out);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(flag), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args << " left a file";
  }
  const auto missing = run_command(cli() + " generate miura");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--out"), std::string::npos);
}

}}  // namespace
}  // namespace rigidfold::test
