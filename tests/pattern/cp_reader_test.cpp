// .cp crease patterns (kernel/pattern/cp_reader.hpp) and the format dispatch by content
// (kernel/pattern/read_pattern.hpp). The .cp twins of two ORIPA files (tests/data/oripa,
// converted by us as ORIPA's ExporterCP writes them) read to exactly the vertices, edges,
// letters and faces of their .opx; Rabbit Ear's own square-fish.cp reads as its .opx;
// Oriedita's birdbase.cp reads with its counts, locally flat-foldable. Synthetic files check
// the format (separators, line ends, Java's numbers, auxiliary types 0 and 4) and bad input
// names the file and the line; a line drawn twice merges by the later line (strict_lines
// refuses). read_pattern chooses the reader by the content: a renamed .opx or .cp reads;
// garbage names the four formats; its overload takes the line readers' options.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "kernel/pattern/cp_reader.hpp"
#include "kernel/pattern/flat_foldability.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/opx_reader.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::string oripa(const std::string& name) { return std::string(RIGIDFOLD_SOURCE_DIR) + "/tests/data/oripa/" + name; }

std::map<char, int> letters(const CreasePattern& p) {
  std::map<char, int> m;
  for (Assignment a : p.assignments) ++m[assignment_letter(a)];
  return m;
}

std::string error_of(const std::string& text) {
  try {
    parse_cp(text, "bad.cp");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// Our twins: the crease lines of the .opx in its order with its numbers, aux lines left out,
// so the same SVG goes through the same arrangement: everything equal, bit for bit.
TEST(CpReader, TwinsReadExactlyAsTheirOpx) {
  for (const char* name : {"miura-ori", "degree-4"}) {
    SCOPED_TRACE(name);
    OpxImportSummary so;
    CpImportSummary sc;
    const CreasePattern o = read_opx(oripa(std::string(name) + ".opx"), {}, &so);
    const CreasePattern c = read_cp(oripa(std::string(name) + ".cp"), {}, &sc);
    EXPECT_EQ(sc.lines, so.lines);
    for (int t = 0; t < 5; ++t) EXPECT_EQ(sc.lines_by_type[t], so.lines_by_type[t]) << t;
    EXPECT_EQ(c.vertices, o.vertices);
    EXPECT_EQ(c.edges, o.edges);
    EXPECT_EQ(c.assignments, o.assignments);
    EXPECT_EQ(c.faces, o.faces);
    EXPECT_EQ(c.fold_angles, o.fold_angles);
    EXPECT_EQ(sc.arrangement.merged_points, so.arrangement.merged_points);
    EXPECT_EQ(sc.arrangement.touches, so.arrangement.touches);
  }
}

// Pieces as (ends, letter), ends rounded to 1e-9 and ordered: the same pattern whatever the
// order of the lines in the file.
std::set<std::tuple<double, double, double, double, char>> pieces(const CreasePattern& p) {
  auto r = [](double x) { return std::round(x * 1e9) / 1e9 + 0.0; };
  std::set<std::tuple<double, double, double, double, char>> s;
  for (int e = 0; e < p.num_edges(); ++e) {
    auto a = std::pair(r(p.vertices[p.edges[e][0]].x()), r(p.vertices[p.edges[e][0]].y()));
    auto b = std::pair(r(p.vertices[p.edges[e][1]].x()), r(p.vertices[p.edges[e][1]].y()));
    if (b < a) std::swap(a, b);
    s.insert({a.first, a.second, b.first, b.second, assignment_letter(p.assignments[e])});
  }
  return s;
}

// Rabbit Ear's square fish as .opx and as .cp (its own files, lines in another order):
// the .cp has no auxiliary lines; the same pattern, in the same axes.
TEST(CpReader, RabbitEarSquareFishAsItsOpx) {
  CpImportSummary s;
  const CreasePattern c = read_cp(oripa("square-fish.cp"), {}, &s);
  const CreasePattern o = read_opx(oripa("square-fish.opx"));
  EXPECT_EQ(s.lines, 24);
  EXPECT_EQ(s.lines_by_type[1], 12);
  EXPECT_EQ(s.lines_by_type[2], 4);
  EXPECT_EQ(s.lines_by_type[3], 8);
  EXPECT_EQ(c.num_vertices(), 13);
  EXPECT_EQ(c.num_edges(), 22);
  EXPECT_EQ(c.num_faces(), 10);
  EXPECT_EQ(letters(c), (std::map<char, int>{{'B', 10}, {'M', 4}, {'V', 8}}));
  EXPECT_EQ(pieces(c), pieces(o));
}

// Oriedita's bird base: Java's numbers with E-14 noise and -0.0, merged into 13 vertices.
TEST(CpReader, OrieditaBirdBase) {
  CpImportSummary s;
  const CreasePattern p = read_cp(oripa("birdbase.cp"), {}, &s);
  EXPECT_EQ(s.lines, 26);
  EXPECT_EQ(p.num_vertices(), 13);
  EXPECT_EQ(p.num_edges(), 26);
  EXPECT_EQ(p.num_faces(), 14);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 8}, {'M', 12}, {'V', 6}}));
  EXPECT_EQ(p.extra["file_creator"], "rigidfold import (.cp)");
  const Topology t = build_topology(p, "birdbase.cp");
  const auto verdicts = flat_foldability(p, t, 1e-9);
  ASSERT_EQ(verdicts.size(), 5u);
  for (const auto& r : verdicts) {
    EXPECT_TRUE(r.kawasaki) << r.vertex;
    EXPECT_EQ(r.maekawa, true) << r.vertex;
  }
}

TEST(CpReader, FormatDetails) {
  // Tabs and runs of blanks, CRLF, a lone CR, blank lines, a byte order mark, Java's number
  // forms, a '+' sign; 0 and 4 are auxiliary lines, ignored with a warning.
  const std::string text =
      "\xEF\xBB\xBF"
      "1 -200.0 -200.0 200.0 -200.0\r\n"
      "1\t200.0\t-200.0   200.0 200.0\r\n"
      "\r\n"
      "1 200.0 200.0 -200.0 200.0\r"
      "1 -200.0 200.0 -200.0 -2.0E2\n"
      "  3 -200.0 -200.0 +200.0 2.0E+2  \n"
      "0 -200.0 0.0 200.0 0.0\n"
      "4 0.0 -200.0 -0.0 200.0\n";
  CpImportSummary s;
  const CreasePattern p = parse_cp(text, "ok.cp", {}, &s);
  EXPECT_EQ(s.lines, 7);
  EXPECT_EQ(s.lines_by_type[0], 1);
  EXPECT_EQ(s.lines_by_type[4], 1);
  EXPECT_EQ(p.num_vertices(), 4);
  EXPECT_EQ(p.num_edges(), 5);
  EXPECT_EQ(p.num_faces(), 2);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 4}, {'V', 1}}));
  // ORIPA's y points down: the valley from (-200, -200) to (200, 200) runs on FOLD y = -x.
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.assignments[e] != Assignment::Valley) continue;
    for (int k : p.edges[e]) EXPECT_EQ(p.vertices[k].x(), -p.vertices[k].y());
  }
  bool warned = false;
  for (const auto& w : p.warnings) warned = warned || w == "ok.cp: 2 auxiliary lines (type 0 or 4) ignored: they are no creases";
  EXPECT_TRUE(warned);
  EXPECT_TRUE(looks_like_cp(text));
  EXPECT_TRUE(is_cp_path("A.CP"));
  EXPECT_FALSE(is_cp_path("a.cpp"));
}

TEST(CpReader, BadInputNamesTheLine) {
  const std::string square = "1 0 0 1 0\n1 1 0 1 1\n1 1 1 0 1\n1 0 1 0 0\n";
  EXPECT_EQ(error_of(square + "2 0 0 1\n"), "bad.cp: line 5: 4 fields where 5 (type x1 y1 x2 y2) were expected");
  EXPECT_EQ(error_of(square + "2 0 0 1 1 7\n"), "bad.cp: line 5: 6 fields where 5 (type x1 y1 x2 y2) were expected");
  EXPECT_EQ(error_of("\n" + square + "M 0 0 1 1\n"), "bad.cp: line 6: type: 'M' is not an integer");
  EXPECT_EQ(error_of(square + "2.0 0 0 1 1\n"), "bad.cp: line 5: type: '2.0' is not an integer");
  EXPECT_EQ(error_of(square + "7 0 0 1 1\n"), "bad.cp: line 5: type: unknown line type 7 (1 cut, 2 mountain, 3 valley; 0 and 4 auxiliary)");
  EXPECT_EQ(error_of(square + "2 0 0 abc 1\n"), "bad.cp: line 5: x2: 'abc' is not a finite number");
  EXPECT_EQ(error_of(square + "2 0 NaN 1 1\n"), "bad.cp: line 5: y1: 'NaN' is not a finite number");
  EXPECT_EQ(error_of(square + "2 0 0 1 1e999\n"), "bad.cp: line 5: y2: '1e999' is not a finite number");
  EXPECT_EQ(error_of("2 0 0 1 " + std::string(100, '9') + "x\n"),
            "bad.cp: line 1: y2: '9999999999999999999999999999999999999999...' is not a finite number");
  EXPECT_EQ(error_of(" \n\n"), "bad.cp: no lines: not a .cp crease pattern (lines \"type x1 y1 x2 y2\")");
  EXPECT_EQ(error_of("0 0 0 1 1\n4 0 1 1 0\n"), "bad.cp: no crease lines: 2 lines, none of type 1 (cut), 2 (mountain) or 3 (valley)");
  // The arrangement's messages name .cp lines, not SVG elements (strict_lines: a crease drawn
  // twice in two letters is refused).
  SvgReadOptions strict;
  strict.strict_lines = true;
  try {
    parse_cp(square + "2 0 0 1 1\n3 1 1 0 0\n", "bad.cp", strict);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "bad.cp: line 5 and line 6: draw the same crease from (1, 1) to (0, 0) as mountain and valley");
  }
  const std::string lone = error_of("2 0 0 1 1\n");
  EXPECT_EQ(lone.rfind("bad.cp: ", 0), 0u) << lone;
  EXPECT_EQ(lone.find("<line>"), std::string::npos) << lone;
}

// A line drawn twice (svg_reader.hpp, "Lines drawn twice"): the later letter wins, in either
// order, with a warning naming both .cp lines; the same letter twice is one edge, warned; a
// crease over the outline leaves it. read_pattern reads the same, with the same warnings.
TEST(CpReader, DuplicatedLinesMergeByTheLaterLine) {
  const std::string square = "1 0 0 1 0\n1 1 0 1 1\n1 1 1 0 1\n1 0 1 0 0\n";
  CpImportSummary s;
  const CreasePattern mv = parse_cp(square + "2 0 0 1 1\n3 1 1 0 0\n", "dup.cp", {}, &s);
  EXPECT_EQ(letters(mv), (std::map<char, int>{{'B', 4}, {'V', 1}}));
  EXPECT_EQ(mv.num_faces(), 2);
  EXPECT_EQ(s.arrangement.overwritten_edges, 1);
  const std::string warning =
      "dup.cp: line 5 and line 6 draw the same crease from (1, 1) to (0, 0) as mountain and valley: kept valley (the later line, as "
      "ORIPA's editor does)";
  EXPECT_EQ(std::count(mv.warnings.begin(), mv.warnings.end(), warning), 1) << ::testing::PrintToString(mv.warnings);
  ASSERT_EQ(s.arrangement.merged_lines.size(), 1u);
  EXPECT_EQ(s.arrangement.merged_lines[0].first, "line 5");
  EXPECT_EQ(s.arrangement.merged_lines[0].second, "line 6");
  EXPECT_EQ(s.arrangement.merged_lines[0].kept_letter, Assignment::Valley);
  const CreasePattern vm = parse_cp(square + "3 1 1 0 0\n2 0 0 1 1\n", "dup.cp");
  EXPECT_EQ(letters(vm), (std::map<char, int>{{'B', 4}, {'M', 1}}));
  // The same letter twice (and blank lines between): one edge, warned, counted.
  const CreasePattern same = parse_cp(square + "3 0 0 1 1\n\n3 0 0 1 1\n", "dup.cp", {}, &s);
  EXPECT_EQ(letters(same), (std::map<char, int>{{'B', 4}, {'V', 1}}));
  EXPECT_EQ(s.arrangement.duplicate_edges, 1);
  EXPECT_EQ(std::count(same.warnings.begin(), same.warnings.end(),
                       "dup.cp: line 5 and line 7 draw the same crease from (0, 0) to (1, 1), both as valley: merged into one edge"),
            1)
      << ::testing::PrintToString(same.warnings);
  // A mountain along the outline: the outline stays.
  const CreasePattern edge = parse_cp(square + "3 0 0 1 1\n2 0 0 1 0\n", "dup.cp", {}, &s);
  EXPECT_EQ(letters(edge), (std::map<char, int>{{'B', 4}, {'V', 1}}));
  ASSERT_EQ(s.arrangement.merged_lines.size(), 1u);
  EXPECT_EQ(s.arrangement.merged_lines[0].rule, MergedLines::Rule::Outline);
  EXPECT_EQ(s.arrangement.merged_lines[0].first, "line 1");
}

// ---- read_pattern: the format by the content ----

class ReadPatternByContent : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("rigidfold_cp_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string copy_as(const std::string& from, const std::string& name) {
    const auto to = dir_ / name;
    std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
    return to.string();
  }
  std::string write(const std::string& name, const std::string& text) {
    const auto to = dir_ / name;
    std::ofstream(to, std::ios::binary) << text;
    return to.string();
  }
  static std::string error_of_path(const std::string& path) {
    try {
      read_pattern(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
  std::filesystem::path dir_;
};

TEST_F(ReadPatternByContent, DetectsEachFormat) {
  EXPECT_EQ(detect_pattern_format(" {\"vertices_coords\": []}"), PatternFormat::Fold);
  EXPECT_EQ(detect_pattern_format("\xEF\xBB\xBF[1]"), PatternFormat::Fold);
  EXPECT_EQ(detect_pattern_format("<?xml version=\"1.0\"?>\n<java version=\"1.7.0_40\">"), PatternFormat::Opx);
  EXPECT_EQ(detect_pattern_format("<!-- Generator -->\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"x.dtd\">\n<svg>"),
            PatternFormat::Svg);
  EXPECT_EQ(detect_pattern_format("<!DOCTYPE s [<!ENTITY a \"<java>\">]><svg:svg xmlns:svg=\"x\">"), PatternFormat::Svg);
  EXPECT_EQ(detect_pattern_format("\n\n1 -200.0 -200.0 200.0 -2.0E2\n"), PatternFormat::Cp);
  EXPECT_EQ(detect_pattern_format("<html><svg>"), PatternFormat::Unknown);
  EXPECT_EQ(detect_pattern_format("1 2 3 4\n"), PatternFormat::Unknown);
  EXPECT_EQ(detect_pattern_format("  \n"), PatternFormat::Unknown);
  EXPECT_EQ(pattern_format_of_path("dir.v2/x.OPX"), PatternFormat::Opx);
  EXPECT_EQ(pattern_format_of_path("dir.cp/x"), PatternFormat::Unknown);
}

TEST_F(ReadPatternByContent, RenamedFilesRead) {
  const CreasePattern opx = read_opx(oripa("miura-ori.opx"));
  const CreasePattern as_txt = read_pattern(copy_as(oripa("miura-ori.opx"), "miura.txt"));
  EXPECT_EQ(as_txt.vertices, opx.vertices);
  EXPECT_EQ(as_txt.edges, opx.edges);
  EXPECT_EQ(as_txt.assignments, opx.assignments);
  const CreasePattern none = read_pattern(copy_as(oripa("miura-ori.cp"), "miura"));
  EXPECT_EQ(none.edges, opx.edges);
  EXPECT_EQ(read_pattern(oripa("miura-ori.cp")).edges, opx.edges);
  // Content against a known extension: the content wins, and the warnings say so.
  const std::string wrong = copy_as(oripa("square-fish.opx"), "fish.svg");
  const CreasePattern fish = read_pattern(wrong);
  EXPECT_EQ(fish.num_edges(), 22);
  bool warned = false;
  for (const auto& w : fish.warnings) warned = warned || w == wrong + ": read as ORIPA .opx by its content, though its extension says SVG";
  EXPECT_TRUE(warned);
}

TEST_F(ReadPatternByContent, LineReadersOptionsAndSummary) {
  // A .cp under another name, with a line drawn twice: the rule, its warning and the summary
  // as parse_cp gives them; strict_lines refuses.
  const std::string text = "1 0 0 1 0\n1 1 0 1 1\n1 1 1 0 1\n1 0 1 0 0\n2 0 0 1 1\n3 1 1 0 0\n";
  const std::string path = write("dup.txt", text);
  SvgImportSummary s;
  PatternFormat format = PatternFormat::Unknown;
  const CreasePattern p = read_pattern(path, {}, &s, &format);
  EXPECT_EQ(format, PatternFormat::Cp);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 4}, {'V', 1}}));
  ASSERT_EQ(s.merged_lines.size(), 1u);
  EXPECT_EQ(s.merged_lines[0].first, "line 5");
  EXPECT_EQ(s.elements, 6);
  EXPECT_EQ(s.drawn_elements, 6);
  EXPECT_EQ(read_pattern(path).warnings, p.warnings);
  SvgReadOptions strict;
  strict.strict_lines = true;
  try {
    read_pattern(path, strict);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": line 5 and line 6: draw the same crease from (1, 1) to (0, 0) as mountain and valley");
  }
  EXPECT_EQ(pattern_format_to_read(text, "x.fold"), PatternFormat::Cp);
  EXPECT_EQ(pattern_format_to_read("  ", "x.fold"), PatternFormat::Fold);
  EXPECT_EQ(pattern_format_to_read("junk", "x.svg"), PatternFormat::Svg);
}

TEST_F(ReadPatternByContent, GarbageNamesTheFormats) {
  const std::string txt = write("junk.txt", "hello world\nsecond line\n");
  EXPECT_EQ(error_of_path(txt), txt + ": not a FOLD, SVG, ORIPA .opx or .cp file (it begins \"hello world\")");
  const std::string fold = write("junk.fold", "PK\x03\x04 a zip archive, not JSON at all");
  EXPECT_EQ(error_of_path(fold), fold + ": not a FOLD, SVG, ORIPA .opx or .cp file (it begins \"PK?? a zip archive, not ...\")");
  // A file named .cp, .opx or .svg whose content is none of the formats: its reader says what is wrong.
  const std::string cp = write("bad.cp", "2 0 0 1\n");
  EXPECT_EQ(error_of_path(cp), cp + ": line 1: 4 fields where 5 (type x1 y1 x2 y2) were expected");
  const std::string opx = write("bad.opx", "<html/>");
  EXPECT_EQ(error_of_path(opx), opx + ": root element is <html>, not <java>: not an ORIPA .opx");
  // Empty: FOLD's message, as before.
  EXPECT_EQ(error_of_path(write("empty.fold", "")), (dir_ / "empty.fold").string() + ": file is empty");
}

}}  // namespace
}  // namespace rigidfold
