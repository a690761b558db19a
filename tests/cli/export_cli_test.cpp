// `rigidfold export P --svg OUT.svg [--dxf OUT.dxf]` (and `fold --stl`, `import X.opx`): exit 0
// with an SVG that `rigidfold import` reads back with the same counts; exit 2 with one line
// naming the place for a missing pattern, an output that is the input, and a tube (no flat
// crease pattern).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::string bundled(const std::string& name) { return std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/" + name; }

class ExportCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("rigidfold_export_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string file(const std::string& name) { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(ExportCli, ExportThenImportGivesTheSameCounts) {
  for (const char* name : {"miura_4x4_alpha60.fold", "square_twist_30_type2m.fold", "miura_12x12_folded.fold", "waterbomb_base.fold"}) {
    SCOPED_TRACE(name);
    const std::string svg = file(std::string(name) + ".svg"), back = file(std::string(name) + ".back.fold");
    const auto ex = test::run_command(test::cli() + " export " + bundled(name) + " --svg " + svg + " --json");
    ASSERT_EQ(ex.status, 0) << ex.err;
    const auto je = nlohmann::json::parse(ex.out);
    EXPECT_EQ(je["developed_from_3d"], false);
    const auto im = test::run_command(test::cli() + " import " + svg + " --out " + back + " --json");
    ASSERT_EQ(im.status, 0) << im.err;
    const auto ji = nlohmann::json::parse(im.out);
    const auto info = test::run_command(test::cli() + " info " + bundled(name) + " --json");
    ASSERT_EQ(info.status, 0) << info.err;
    const auto jf = nlohmann::json::parse(info.out);
    for (const char* key : {"vertices", "edges", "faces"}) {
      EXPECT_EQ(ji[key], je[key]) << key;
      EXPECT_EQ(ji[key], jf[key]) << key;
    }
    EXPECT_EQ(ji["edges_by_assignment"], je["edges_by_assignment"]);
    EXPECT_EQ(ji["svg"]["merged_points"], 0);
    EXPECT_EQ(ji["svg"]["crossings_split"], 0);
    // An SVG exported again from the SVG is the same text.
    const std::string again = file(std::string(name) + ".again.svg");
    const auto ex2 = test::run_command(test::cli() + " export " + svg + " --svg " + again);
    ASSERT_EQ(ex2.status, 0) << ex2.err;
    EXPECT_EQ(std::filesystem::file_size(again), std::filesystem::file_size(svg));
  }
}

TEST_F(ExportCli, BadInputExitsTwoNamingThePlace) {
  const std::string missing = file("missing.fold");
  const auto r = test::run_command(test::cli() + " export " + missing + " --svg " + file("m.svg"));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(file("m.svg")));

  const std::string svg = file("w.svg");
  ASSERT_EQ(test::run_command(test::cli() + " export " + bundled("waterbomb_base.fold") + " --svg " + svg).status, 0);
  const auto before = std::filesystem::file_size(svg);
  const auto same = test::run_command(test::cli() + " export " + svg + " --svg " + svg);
  EXPECT_EQ(same.status, 2) << same.err;
  EXPECT_NE(same.err.find("--svg"), std::string::npos) << same.err;
  EXPECT_EQ(std::filesystem::file_size(svg), before);

  const auto tube = test::run_command(test::cli() + " export " + bundled("miura_tube_6_alpha60.fold") + " --svg " + file("t.svg"));
  EXPECT_EQ(tube.status, 2) << tube.err;
  EXPECT_NE(tube.err.find("miura_tube_6_alpha60.fold: the sheet has 1 hole"), std::string::npos) << tube.err;
  EXPECT_FALSE(std::filesystem::exists(file("t.svg")));
}

TEST_F(ExportCli, DxfBesideTheSvgOrAlone) {
  const std::string svg = file("m.svg"), dxf = file("m.dxf");
  const auto r = test::run_command(test::cli() + " export " + bundled("miura_4x4_alpha60.fold") + " --svg " + svg + " --dxf " + dxf);
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(dxf);
  std::string code, value;
  int lines = 0;
  bool r12 = false;
  while (std::getline(in, code) && std::getline(in, value)) {
    lines += code == "0" && value == "LINE";
    r12 = r12 || value == "AC1009";
  }
  EXPECT_EQ(lines, 40);  // the pattern's edges
  EXPECT_TRUE(r12);
  EXPECT_TRUE(std::filesystem::exists(svg));
  const auto none = test::run_command(test::cli() + " export " + bundled("miura_4x4_alpha60.fold"));
  EXPECT_EQ(none.status, 2) << none.err;
  EXPECT_NE(none.err.find("--svg: give --svg OUT.svg and/or --dxf OUT.dxf"), std::string::npos) << none.err;
  const auto clash = test::run_command(test::cli() + " export " + bundled("miura_4x4_alpha60.fold") + " --svg " + svg + " --dxf " + svg);
  EXPECT_EQ(clash.status, 2) << clash.err;
}

// `rigidfold import X.opx` dispatches on the extension (kernel/pattern/opx_reader.hpp).
TEST_F(ExportCli, ImportReadsAnOripaOpx) {
  const std::string out = file("u.fold");
  const auto r = test::run_command(test::cli() + " import " + std::string(RIGIDFOLD_SOURCE_DIR) + "/tests/data/opx/miura_unit.opx --out " +
                                   out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"], 9);
  EXPECT_EQ(j["edges"], 12);
  EXPECT_EQ(j["faces"], 4);
  EXPECT_EQ(j["interior_vertices"], 1);
  EXPECT_TRUE(std::filesystem::exists(out));
  const std::string bad = file("bad.opx");
  std::ofstream(bad) << "<java><object class=\"oripa.DataSet\"><void property=\"lines\">\n"
                        "<array class=\"oripa.OriLineProxy\" length=\"1\"><void index=\"0\">\n"
                        "<object class=\"oripa.OriLineProxy\"><void property=\"type\"><int>9</int></void></object>"
                        "</void></array></void></object></java>\n";
  const auto b = test::run_command(test::cli() + " import " + bad + " --out " + file("bad.fold"));
  EXPECT_EQ(b.status, 2) << b.err;
  EXPECT_NE(b.err.find(bad + ": lines[0] (line 3): type: unknown line type 9"), std::string::npos) << b.err;
  EXPECT_FALSE(std::filesystem::exists(file("bad.fold")));
}

// info, check and trace read an .opx directly (kernel/pattern/read_pattern.hpp), as they read an
// SVG: the same verdict as on the FOLD that `import` writes.
TEST_F(ExportCli, CheckReadsAnOripaOpxDirectly) {
  const std::string opx = std::string(RIGIDFOLD_SOURCE_DIR) + "/tests/data/opx/miura_unit.opx", fold = file("m.fold");
  ASSERT_EQ(test::run_command(test::cli() + " import " + opx + " --out " + fold).status, 0);
  const auto direct = test::run_command(test::cli() + " check " + opx + " --json");
  const auto imported = test::run_command(test::cli() + " check " + fold + " --json");
  ASSERT_EQ(direct.status, 0) << direct.err;
  ASSERT_EQ(imported.status, 0) << imported.err;
  const auto a = nlohmann::json::parse(direct.out), b = nlohmann::json::parse(imported.out);
  EXPECT_EQ(a["file"], opx);
  // The file's letters MMMV put the odd crease where its sectors do not allow: a proof of no motion.
  EXPECT_EQ(a["verdict_class"], "not foldable (proof)");
  for (const char* key : {"verdict_class", "dof", "model", "reason", "obstruction"}) EXPECT_EQ(a[key], b[key]) << key;
}

TEST_F(ExportCli, FoldWritesAnStlWithTheOtherOutputs) {
  const std::string angles = file("a.json"), out = file("f.fold"), stl = file("f.stl");
  std::ofstream(angles) << "{}";
  const auto r = test::run_command(test::cli() + " fold " + bundled("miura_4x4_alpha60.fold") + " --angles " + angles + " --out " + out +
                                   " --stl " + stl);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(std::filesystem::file_size(stl), 84u + 50u * 32u);  // 16 quads, 2 triangles each
  const auto clash = test::run_command(test::cli() + " fold " + bundled("miura_4x4_alpha60.fold") + " --angles " + angles + " --out " +
                                       out + " --stl " + out);
  EXPECT_EQ(clash.status, 2) << clash.err;
  EXPECT_NE(clash.err.find("--stl"), std::string::npos) << clash.err;
}

}}  // namespace
}  // namespace rigidfold
