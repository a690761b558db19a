// ORIPA .opx crease patterns (kernel/pattern/opx_reader.hpp): the two hand-written files in
// tests/data/opx read with their counts, letters and coordinates (y flipped: ORIPA draws y
// down), properties left out by XMLEncoder read as 0, auxiliary lines ignored; bad files
// raise InputError naming the file, the line's array index and its line in the file.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/opx_reader.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace {

std::string data(const std::string& name) { return std::string(RIGIDFOLD_SOURCE_DIR) + "/tests/data/opx/" + name; }

std::map<char, int> letters(const CreasePattern& p) {
  std::map<char, int> m;
  for (Assignment a : p.assignments) ++m[assignment_letter(a)];
  return m;
}

std::set<std::pair<double, double>> points(const CreasePattern& p) {
  std::set<std::pair<double, double>> s;
  for (const auto& v : p.vertices) s.insert({v.x(), v.y()});
  return s;
}

TEST(OpxReader, SquareWithOneValleyDiagonal) {
  OpxImportSummary summary;
  const CreasePattern p = read_opx(data("square_valley.opx"), {}, &summary);
  EXPECT_EQ(summary.lines, 6);
  EXPECT_EQ(summary.lines_by_type[0], 1);  // the auxiliary line
  EXPECT_EQ(summary.lines_by_type[1], 4);
  EXPECT_EQ(summary.lines_by_type[3], 1);
  EXPECT_EQ(p.num_vertices(), 4);
  EXPECT_EQ(p.num_edges(), 5);
  EXPECT_EQ(p.num_faces(), 2);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 4}, {'V', 1}}));
  for (int e = 0; e < p.num_edges(); ++e) EXPECT_FALSE(p.fold_angles[e].has_value()) << "ORIPA has no fold angles";
  // The valley runs from ORIPA (-200, -200) to (200, 200), i.e. FOLD (-200, 200) to (200, -200).
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.assignments[e] != Assignment::Valley) continue;
    const auto a = p.vertices[p.edges[e][0]], b = p.vertices[p.edges[e][1]];
    EXPECT_EQ(a.x() + b.x(), 0.0);
    EXPECT_EQ(a.x() * a.y(), -40000.0);  // on y = -x
  }
  bool warned = false;
  for (const auto& w : p.warnings) warned = warned || w.find("1 auxiliary lines (type 0) ignored") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(OpxReader, MiuraUnitWithLeftOutZeros) {
  const CreasePattern p = read_opx(data("miura_unit.opx"));
  EXPECT_EQ(p.num_vertices(), 9);
  EXPECT_EQ(p.num_edges(), 12);
  EXPECT_EQ(p.num_faces(), 4);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 8}, {'M', 3}, {'V', 1}}));
  // x0 = 0 etc. are left out of the file; ORIPA y = -50 is FOLD y = 50.
  EXPECT_EQ(points(p), (std::set<std::pair<double, double>>{
                           {-200, -200}, {200, -200}, {200, 200}, {-200, 200}, {0, -200}, {0, 200}, {-200, 50}, {200, 50}, {0, 0}}));
  const Topology t = build_topology(p, "miura_unit.opx");
  ASSERT_EQ(t.interior_vertices.size(), 1u);
  EXPECT_EQ(p.vertices[t.interior_vertices[0]], Eigen::Vector3d(0, 0, 0));
}

std::string opx_with_line(const std::string& object_body, const std::string& array_extra = "") {
  return "<?xml version=\"1.0\"?>\n<java class=\"java.beans.XMLDecoder\">\n <object class=\"oripa.DataSet\">\n  <void property=\"lines\">\n"
         "   <array class=\"oripa.OriLineProxy\" length=\"1\">\n    <void index=\"0\">\n     <object class=\"oripa.OriLineProxy\">\n" +
         object_body + "     </object>\n    </void>\n" + array_extra + "   </array>\n  </void>\n </object>\n</java>\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_opx(text, "bad.opx");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(OpxReader, BadInputNamesThePlace) {
  EXPECT_EQ(error_of(opx_with_line("      <void property=\"type\"><int>7</int></void>\n")),
            "bad.opx: lines[0] (line 7): type: unknown line type 7 (0 aux, 1 cut, 2 mountain, 3 valley, 4 cut)");
  EXPECT_EQ(error_of(opx_with_line("      <void property=\"type\"><int>2</int></void>\n      <void property=\"x0\"><double>1e999</double></void>\n")),
            "bad.opx: lines[0] (line 7): x0: '1e999' is not a finite number");
  EXPECT_EQ(error_of(opx_with_line("      <void property=\"y1\"><double>abc</double></void>\n")),
            "bad.opx: lines[0] (line 7): y1: 'abc' is not a finite number");
  EXPECT_EQ(error_of(opx_with_line("      <void property=\"x0\"><double>1</double></void>\n      <void property=\"x0\"><double>2</double></void>\n")),
            "bad.opx: lines[0] (line 7): x0: given twice");
  EXPECT_EQ(error_of(opx_with_line("", "    <void index=\"3\">\n")), "bad.opx: line 10: lines: index 3 outside the array of length 1");
  EXPECT_EQ(error_of("<svg xmlns=\"http://www.w3.org/2000/svg\"/>"), "bad.opx: root element is <svg>, not <java>: not an ORIPA .opx");
  EXPECT_EQ(error_of("<java><object class=\"other.Thing\"/></java>"), "bad.opx: no <object class=\"oripa.DataSet\"> in <java>: not an ORIPA .opx");
  EXPECT_EQ(error_of("<?xml version=\"1.0\"?>\n<!DOCTYPE java [<!ENTITY a \"aaaa\">]>\n<java>&a;</java>"),
            "bad.opx: line 2: a document type with an internal subset (entity declarations) is refused");
  EXPECT_EQ(error_of("<java><object class=\"oripa.DataSet\"><void property=\"lines\"><array class=\"oripa.OriLineProxy\" length=\"0\"/></void></object></java>"),
            "bad.opx: no crease lines: 0 lines, none of type cut, mountain, valley or model cut");
  EXPECT_NE(error_of("<java><object").find("bad.opx: line 1, column"), std::string::npos);
  // A line of zero length is dropped by the arrangement; one crossing nothing dangles: both
  // leave no face, and the message names the .opx, not an SVG element.
  const std::string lone = error_of(opx_with_line(
      "      <void property=\"type\"><int>2</int></void>\n      <void property=\"x1\"><double>10.0</double></void>\n"));
  EXPECT_EQ(lone.rfind("bad.opx: ", 0), 0u) << lone;
  EXPECT_EQ(lone.find("<line>"), std::string::npos) << lone;
}

}  // namespace
}  // namespace rigidfold
