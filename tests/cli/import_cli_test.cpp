// `rigidfold import CP.svg --out CP.fold`, and info/check/trace reading .svg directly: the
// written FOLD reads back with the counts the import printed; bad SVGs exit 2 with one line
// naming the file and the element; a .cp with a line drawn twice imports by the later line,
// listed under merged_lines, and --strict-lines refuses it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/run_command.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::string corpus(const std::string& rel) { return std::string(RIGIDFOLD_CORPUS_DIR) + "/" + rel; }

class ImportCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("rigidfold_import_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string file(const std::string& name, const std::string& text = "") {
    const auto p = (dir_ / name).string();
    if (!text.empty()) std::ofstream(p) << text;
    return p;
  }
  std::filesystem::path dir_;
};

TEST_F(ImportCli, WritesAFoldThatReadsBackWithThePrintedCounts) {
  ASSERT_TRUE(std::filesystem::exists(corpus("origami-simulator/waterbombBase.svg")));
  const std::string out = file("wb.fold");
  const auto r = test::run_command(test::cli() + " import " + corpus("origami-simulator/waterbombBase.svg") + " --out " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const CreasePattern p = read_fold(out);
  EXPECT_EQ(j["vertices"], p.num_vertices());
  EXPECT_EQ(j["edges"], p.num_edges());
  EXPECT_EQ(j["faces"], p.num_faces());
  EXPECT_EQ(p.num_vertices(), 9);
  EXPECT_EQ(p.num_faces(), 8);
  EXPECT_EQ(j["euler_characteristic"], 1);
  EXPECT_EQ(j["edges_by_assignment"]["M"], 4);
  EXPECT_EQ(j["edges_by_assignment"]["V"], 4);
  EXPECT_EQ(j["edges_by_assignment"]["B"], 8);
  EXPECT_DOUBLE_EQ(j["svg"]["merge_tolerance_relative"].get<double>(), 1e-4);
  EXPECT_GT(j["svg"]["merge_tolerance"].get<double>(), 0.0);
  EXPECT_EQ(j["svg"]["crossings_split"], 6);  // the six pairs of the four creases cross, all at the centre
  // The tolerance flag is used and reported.
  const auto r2 = test::run_command(test::cli() + " import " + corpus("origami-simulator/waterbombBase.svg") + " --out " + out +
                                    " --merge-tolerance 1e-6 --json");
  ASSERT_EQ(r2.status, 0) << r2.err;
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(r2.out)["svg"]["merge_tolerance_relative"].get<double>(), 1e-6);
}

// Origami Simulator's hypar.svg draws one magenta crease 2.95 px short of its corner: joined
// by default (3 px, Origami Simulator's vertex tolerance), removed as dangling with 0.
TEST_F(ImportCli, LooseLineEndsAreJoinedAndReported) {
  ASSERT_TRUE(std::filesystem::exists(corpus("origami-simulator/hypar.svg")));
  const std::string out = file("hypar.fold");
  const std::string base = test::cli() + " import " + corpus("origami-simulator/hypar.svg") + " --out " + out + " --json";
  const auto r = test::run_command(base);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["svg"]["loose_ends_snapped"], 1);
  EXPECT_DOUBLE_EQ(j["svg"]["loose_end_snap"].get<double>(), 3.0);
  EXPECT_NEAR(j["svg"]["max_snap_distance"].get<double>(), 2.9536, 1e-4);
  EXPECT_EQ(j["edges_by_assignment"]["U"], 96);
  const auto r0 = test::run_command(base + " --snap-loose-ends 0");
  ASSERT_EQ(r0.status, 0) << r0.err;
  const auto j0 = nlohmann::json::parse(r0.out);
  EXPECT_EQ(j0["svg"]["loose_ends_snapped"], 0);
  EXPECT_EQ(j0["edges_by_assignment"]["U"], 95);
  bool dangling = false;
  for (const auto& w : j0["warnings"]) dangling = dangling || w.get<std::string>().find("dangling") != std::string::npos;
  EXPECT_TRUE(dangling);
  const auto bad = test::run_command(base + " --snap-loose-ends -1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--snap-loose-ends"), std::string::npos) << bad.err;
}

TEST_F(ImportCli, InfoCheckAndTraceReadSvgDirectly) {
  const std::string svg = file("cross.svg",
                               "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"10\" height=\"10\" stroke=\"#000\"/>"
                               "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"#00f\"/></svg>");
  const auto info = test::run_command(test::cli() + " info " + svg + " --json");
  ASSERT_EQ(info.status, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out);
  EXPECT_EQ(j["file"], svg);
  const auto check = test::run_command(test::cli() + " check " + svg + " --json");
  ASSERT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(nlohmann::json::parse(check.out)["rigidly_foldable"], true);  // one straight valley folds
  const auto trace = test::run_command(test::cli() + " trace " + svg + " --steps 5 --json");
  EXPECT_EQ(trace.status, 0) << trace.err;
}

TEST_F(ImportCli, BadSvgExitsTwoNamingTheElement) {
  const std::string curve = file("curve.svg",
                                 "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<rect width=\"10\" height=\"10\" stroke=\"#000\"/>\n"
                                 "<path stroke=\"red\" d=\"M0 0 Q 5 5 10 10\"/>\n</svg>");
  for (const std::string& cmd : {" import " + curve + " --out " + file("x.fold"), " info " + curve, " check " + curve, " trace " + curve}) {
    const auto r = test::run_command(test::cli() + cmd);
    EXPECT_EQ(r.status, 2) << cmd << ": " << r.err;
    EXPECT_NE(r.err.find("curve.svg: <path> #1 (line 3) d:"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "x.fold"));
  const auto lol = test::run_command(test::cli() + " import " +
                                     file("lol.svg", "<!DOCTYPE svg [<!ENTITY a \"aaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;\">]><svg>&b;</svg>") +
                                     " --out " + file("y.fold"));
  EXPECT_EQ(lol.status, 2) << lol.err;
  EXPECT_NE(lol.err.find("lol.svg: line 1"), std::string::npos) << lol.err;
  const auto flag = test::run_command(test::cli() + " import " + curve + " --out " + file("z.fold") + " --merge-tolerance 0.5");
  EXPECT_EQ(flag.status, 2) << flag.err;
  EXPECT_NE(flag.err.find("--merge-tolerance"), std::string::npos) << flag.err;
}

// A .cp with one crease drawn twice in two letters (kernel/pattern/svg_reader.hpp, "Lines
// drawn twice"): `import` reads it by its content, keeps the later line's letter, warns
// naming both lines and lists the merge under merged_lines; --strict-lines refuses it with
// the message naming both lines and writes nothing; `info` reads it directly with the same
// warning. A FOLD file is refused: it needs no import.
TEST_F(ImportCli, CpWithALineDrawnTwiceListsTheMerge) {
  const std::string cp = file("dup.cp", "1 0 0 1 0\n1 1 0 1 1\n1 1 1 0 1\n1 0 1 0 0\n2 0 0 1 1\n3 1 1 0 0\n");
  const std::string warning = cp + ": line 5 and line 6 draw the same crease from (1, 1) to (0, 0) as mountain and valley: kept valley "
                                   "(the later line, as ORIPA's editor does)";
  const std::string out = file("dup.fold");
  const auto r = test::run_command(test::cli() + " import " + cp + " --out " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], ".cp");
  EXPECT_EQ(j["svg"]["elements"], 6);
  EXPECT_EQ(j["svg"]["drawn_elements"], 6);
  EXPECT_EQ(j["svg"]["overwritten_edges"], 1);
  EXPECT_EQ(j["svg"]["duplicate_edges"], 0);
  EXPECT_EQ(j["edges_by_assignment"]["V"], 1);
  EXPECT_EQ(j["edges_by_assignment"]["B"], 4);
  EXPECT_FALSE(j["edges_by_assignment"].contains("M"));
  EXPECT_EQ(j["faces"], 2);
  ASSERT_EQ(j["merged_lines"].size(), 1u);
  const auto& m = j["merged_lines"][0];
  EXPECT_EQ(m["lines"][0], "line 5");
  EXPECT_EQ(m["lines"][1], "line 6");
  EXPECT_EQ(m["assignments"][0], "M");
  EXPECT_EQ(m["assignments"][1], "V");
  EXPECT_EQ(m["kept"], "V");
  EXPECT_EQ(m["rule"], "later");
  EXPECT_TRUE(m["kept_fold_angle_deg"].is_null());  // .cp has no fold angles
  EXPECT_DOUBLE_EQ(m["from"][0].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(m["to"][1].get<double>(), 0.0);
  EXPECT_EQ(m["pieces"], 1);
  EXPECT_EQ(std::count(j["warnings"].begin(), j["warnings"].end(), warning), 1) << j["warnings"].dump();
  const CreasePattern p = read_fold(out);
  EXPECT_EQ(p.num_edges(), 5);
  EXPECT_EQ(std::count(p.assignments.begin(), p.assignments.end(), Assignment::Valley), 1);
  // The text report prints the warning.
  const auto text = test::run_command(test::cli() + " import " + cp + " --out " + out);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("  warning: " + warning + "\n"), std::string::npos) << text.out;
  // --strict-lines: refused as before the rule, nothing written.
  const std::string strict_out = file("strict.fold");
  const auto strict = test::run_command(test::cli() + " import " + cp + " --out " + strict_out + " --strict-lines");
  EXPECT_EQ(strict.status, 2) << strict.err;
  EXPECT_NE(strict.err.find(cp + ": line 5 and line 6: draw the same crease from (1, 1) to (0, 0) as mountain and valley"), std::string::npos)
      << strict.err;
  EXPECT_EQ(std::count(strict.err.begin(), strict.err.end(), '\n'), 1) << strict.err;
  EXPECT_FALSE(std::filesystem::exists(strict_out));
  // The same crease twice in one letter: merged, listed, and not refused by --strict-lines.
  const std::string same = file("same.cp", "1 0 0 1 0\n1 1 0 1 1\n1 1 1 0 1\n1 0 1 0 0\n3 0 0 1 1\n3 0 0 1 1\n");
  const auto rs = test::run_command(test::cli() + " import " + same + " --out " + file("same.fold") + " --strict-lines --json");
  ASSERT_EQ(rs.status, 0) << rs.err;
  const auto js = nlohmann::json::parse(rs.out);
  EXPECT_EQ(js["svg"]["duplicate_edges"], 1);
  ASSERT_EQ(js["merged_lines"].size(), 1u);
  EXPECT_EQ(js["merged_lines"][0]["rule"], "same");
  // info reads the .cp directly, with the same warning.
  const auto info = test::run_command(test::cli() + " info " + cp + " --json");
  ASSERT_EQ(info.status, 0) << info.err;
  const auto ji = nlohmann::json::parse(info.out);
  EXPECT_EQ(std::count(ji["warnings"].begin(), ji["warnings"].end(), warning), 1) << ji["warnings"].dump();
  // A FOLD file: refused, naming it.
  const auto fold = test::run_command(test::cli() + " import " + out + " --out " + file("again.fold"));
  EXPECT_EQ(fold.status, 2) << fold.err;
  EXPECT_NE(fold.err.find(out + ": a FOLD file needs no import"), std::string::npos) << fold.err;
  EXPECT_FALSE(std::filesystem::exists(dir_ / "again.fold"));
}

}}  // namespace
}  // namespace rigidfold
