// SVG crease patterns (kernel/pattern/svg_reader.hpp): Origami Simulator's own SVGs
// (tests/data/corpus/origami-simulator) import with their counts, letters and Euler
// characteristic, agreeing with the FOLD versions of the same patterns where the corpus has
// them; synthetic SVGs check each feature (transforms, path commands, colour forms,
// crossings, merging, opacity -> fold angle, lines drawn twice: the later wins, a crease
// leaves the boundary, strict_lines refuses); bad SVGs raise InputError naming the element.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/svg_reader.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::string corpus(const std::string& rel) { return std::string(RIGIDFOLD_CORPUS_DIR) + "/" + rel; }

std::map<char, int> letters(const CreasePattern& p) {
  std::map<char, int> m;
  for (Assignment a : p.assignments) ++m[assignment_letter(a)];
  return m;
}

int euler(const Topology& t) {
  int chi = 0;
  for (const auto& c : t.components) chi += c.euler_characteristic;
  return chi;
}

struct SvgCorpusFile {
  const char* path;
  int vertices, edges, faces, interior, components;
  int b, m, v, f, u;  // edges per letter
};

// Counts as imported with the default merge tolerance; each was checked against the drawing
// (see the comparisons with FOLD versions below for the ones the corpus also has as FOLD).
const SvgCorpusFile kSvgFiles[] = {
    {"origami-simulator/MoosersTrainRigid-Gardner.svg", 467, 950, 484, 340, 1, 127, 397, 426, 0, 0},
    {"origami-simulator/huffmanWaterbomb.svg", 448, 1165, 718, 360, 1, 88, 758, 319, 0, 0},
    {"origami-simulator/hypar.svg", 97, 284, 188, 93, 1, 4, 96, 88, 0, 96},  // one loose end joined
    {"origami-simulator/miura-ori.svg", 182, 337, 156, 132, 1, 50, 137, 150, 0, 0},
    {"origami-simulator/miura_sharpangle.svg", 325, 612, 288, 253, 1, 72, 282, 258, 0, 0},
    {"origami-simulator/reschTriTessellation.svg", 243, 664, 422, 183, 1, 60, 451, 153, 0, 0},
    {"origami-simulator/singlesquaretwist.svg", 16, 24, 9, 4, 1, 12, 4, 8, 0, 0},
    {"origami-simulator/squaretwistManyAngles.svg", 144, 216, 81, 36, 9, 108, 36, 72, 0, 0},
    {"origami-simulator/traditionalCrane.svg", 69, 144, 76, 55, 1, 14, 70, 50, 10, 0},  // two loose ends joined
    {"origami-simulator/waterbombBase.svg", 9, 16, 8, 1, 1, 8, 4, 4, 0, 0},
};

void PrintTo(const SvgCorpusFile& c, std::ostream* os) { *os << c.path; }

class SvgCorpus : public ::testing::TestWithParam<SvgCorpusFile> {
 protected:
  void SetUp() override {
    ASSERT_TRUE(std::filesystem::exists(corpus(GetParam().path))) << "missing from tests/data/corpus";
  }
};

TEST_P(SvgCorpus, ImportsAsDisksWithEveryColourDrawn) {
  const auto& c = GetParam();
  SvgImportSummary s;
  const CreasePattern p = read_svg(corpus(c.path), {}, &s);
  const Topology t = build_topology(p, c.path);
  EXPECT_EQ(p.num_vertices(), c.vertices);
  EXPECT_EQ(p.num_edges(), c.edges);
  EXPECT_EQ(p.num_faces(), c.faces);
  EXPECT_EQ(static_cast<int>(t.interior_vertices.size()), c.interior);
  ASSERT_EQ(static_cast<int>(t.components.size()), c.components);
  for (const auto& comp : t.components) {
    EXPECT_EQ(comp.euler_characteristic, 1) << "each sheet is a disk";
    EXPECT_EQ(comp.boundary_loops, 1);
  }
  EXPECT_EQ(euler(t), c.components);
  EXPECT_EQ(p.num_vertices() - p.num_edges() + p.num_faces(), c.components);
  auto l = letters(p);
  EXPECT_EQ(l['B'], c.b);
  EXPECT_EQ(l['M'], c.m);
  EXPECT_EQ(l['V'], c.v);
  EXPECT_EQ(l['F'], c.f);
  EXPECT_EQ(l['U'], c.u);
  // Every colour the file draws in is present among the edges, and nothing else.
  for (int k = 0; k < 7; ++k) {
    const char letter = assignment_letter(static_cast<Assignment>(k));
    EXPECT_EQ(s.segments_by_letter[k] > 0, l[letter] > 0) << letter;
  }
  // The black lines are exactly the boundary: every B edge has one face, every crease two.
  for (int e = 0; e < p.num_edges(); ++e) {
    const int faces = (t.edge_faces[e][0] >= 0) + (t.edge_faces[e][1] >= 0);
    EXPECT_EQ(faces, p.assignments[e] == Assignment::Boundary ? 1 : 2) << "edge " << e;
  }
  // The tolerance is reported relative to the drawing, and no point moved farther.
  EXPECT_DOUBLE_EQ(s.merge_tolerance_relative, 1e-4);
  EXPECT_NEAR(s.merge_tolerance, 1e-4 * s.pattern_size, 1e-12 * s.pattern_size);
  EXPECT_LE(s.max_merge_distance, s.merge_tolerance);
  EXPECT_EQ(read_pattern(corpus(c.path)).num_edges(), c.edges) << "read_pattern dispatches .svg";
}

INSTANTIATE_TEST_SUITE_P(All, SvgCorpus, ::testing::ValuesIn(kSvgFiles));

TEST(SvgCorpusAgainstFold, SameCountsAsTheFoldVersionsOfThePatterns) {
  ASSERT_TRUE(std::filesystem::exists(corpus("origami-simulator/waterbombBase.svg"))) << "missing from tests/data/corpus";
  // Origami Simulator's waterbomb base and square twist against the FOLD files of the same
  // patterns from two other projects (rigid-origami, the FOLD spec's examples).
  for (auto [svg, fold] : {std::pair{"origami-simulator/waterbombBase.svg", "rigid-origami/waterbombBase.fold"},
                           {"origami-simulator/singlesquaretwist.svg", "fold-spec/squaretwist.fold"}}) {
    const CreasePattern a = read_svg(corpus(svg)), b = read_fold(corpus(fold));
    EXPECT_EQ(a.num_vertices(), b.num_vertices()) << svg;
    EXPECT_EQ(a.num_edges(), b.num_edges()) << svg;
    EXPECT_EQ(a.num_faces(), b.num_faces()) << svg;
    EXPECT_EQ(build_topology(a).interior_vertices.size(), build_topology(b).interior_vertices.size()) << svg;
  }
  // Huffman's waterbomb tessellation: the FOLD is triangulated, the SVG is not, but both
  // have the same 360 interior vertices.
  EXPECT_EQ(build_topology(read_svg(corpus("origami-simulator/huffmanWaterbomb.svg"))).interior_vertices.size(),
            build_topology(read_fold(corpus("rigid-origami/huffmanWaterbomb.fold"))).interior_vertices.size());
}

TEST(SvgCorpusAgainstFold, OpacityIsTheTargetFoldAngle) {
  ASSERT_TRUE(std::filesystem::exists(corpus("origami-simulator/waterbombBase.svg"))) << "missing from tests/data/corpus";
  // waterbombBase.svg: red diagonals at full opacity, blue midlines at opacity 0.5.
  const CreasePattern p = read_svg(corpus("origami-simulator/waterbombBase.svg"));
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.assignments[e] == Assignment::Mountain) {
      EXPECT_DOUBLE_EQ(*p.fold_angles[e], -std::numbers::pi);
    }
    if (p.assignments[e] == Assignment::Valley) {
      EXPECT_DOUBLE_EQ(*p.fold_angles[e], std::numbers::pi / 2);
    }
    if (p.assignments[e] == Assignment::Boundary) {
      EXPECT_FALSE(p.fold_angles[e].has_value());
    }
  }
}

// ---- synthetic SVGs -------------------------------------------------------------------

std::string svg(const std::string& body, const std::string& head = "") {
  return "<?xml version=\"1.0\"?>\n" + head + "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"100\">\n" + body + "\n</svg>\n";
}

const std::string kSquare = "<rect x=\"0\" y=\"0\" width=\"10\" height=\"10\" fill=\"none\" stroke=\"#000\"/>\n";

std::set<std::pair<double, double>> rounded_vertices(const CreasePattern& p) {
  std::set<std::pair<double, double>> s;
  for (const auto& v : p.vertices) s.emplace(std::round(v.x() * 1e6) / 1e6 + 0.0, std::round(v.y() * 1e6) / 1e6 + 0.0);
  return s;
}

TEST(SvgReader, CrossingLinesAreSplitAndFacesBuilt) {
  // Two diagonals drawn end to end across the square, no vertex drawn at the centre.
  SvgImportSummary s;
  const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"10\" stroke=\"red\"/>"
                                                  "<line x1=\"10\" y1=\"0\" x2=\"0\" y2=\"10\" stroke=\"blue\"/>"),
                                    "x.svg", {}, &s);
  EXPECT_EQ(p.num_vertices(), 5);
  EXPECT_EQ(p.num_edges(), 8);
  EXPECT_EQ(p.num_faces(), 4);
  EXPECT_EQ(s.crossings, 1);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 4}, {'M', 2}, {'V', 2}}));
  // SVG's y points down; FOLD's y = -SVG y, so the centre is (5, -5).
  EXPECT_TRUE(rounded_vertices(p).count({5.0, -5.0}));
  const Topology t = build_topology(p);
  ASSERT_EQ(t.interior_vertices.size(), 1u);
  EXPECT_NEAR(t.stars[t.interior_vertices[0]].sector_sum(), 2 * std::numbers::pi, 1e-12);
}

// CreasePattern::position_bounds: each vertex within the box of its drawn points, each grown by
// count x max(0.5 10^-D, 0.5 10^(magnitude - S + 1)) (D: most decimals, S: most significant
// digits of the file's numbers; count: numbers added to make the coordinate).
TEST(SvgReader, PositionBoundsComeFromTheDigitsOfTheNumbers) {
  // D = 3 (2.125), S = 4 (2.125): "10" then reads as 10.00, rounding 0.005.
  const CreasePattern p = parse_svg(svg(kSquare + "<path d=\"M0,2.125 l10,0\" stroke=\"red\"/>"), "b.svg");
  const auto& b = p.position_bounds;
  ASSERT_TRUE(b.covers(p.num_vertices()));
  EXPECT_EQ(b.decimal_places, 3);
  EXPECT_EQ(b.significant_digits, 4);
  auto find = [&](double x, double y) {
    for (int v = 0; v < p.num_vertices(); ++v)
      if (std::abs(p.vertices[v].x() - x) < 1e-12 && std::abs(p.vertices[v].y() - y) < 1e-12) return v;
    return -1;
  };
  // The mountain's right end (10, 2.125): x = 0 + 10 (relative: two numbers, largest 10),
  // y = 2.125 + 0 (two numbers of magnitude 0 or none).
  const int end = find(10, -2.125);
  ASSERT_GE(end, 0);
  EXPECT_NEAR(b.hi[end].x() - 10, 2 * 0.005, 1e-15);
  EXPECT_NEAR(10 - b.lo[end].x(), 2 * 0.005, 1e-15);
  EXPECT_NEAR(b.hi[end].y() + 2.125, 2 * 0.0005, 1e-15);
  // Its left end, absolute: x "0" (0.5 10^-3), y "2.125" (0.5 10^-3).
  const int start = find(0, -2.125);
  ASSERT_GE(start, 0);
  EXPECT_NEAR(b.hi[start].x(), 0.0005, 1e-15);
  EXPECT_NEAR(b.hi[start].y() + 2.125, 0.0005, 1e-15);
  // A crossing: a bounded box around the computed point, wider than its lines' ends' rounding.
  // The square written "10.000": D = 3, S = 5, so every number here is known to 0.0005. (With
  // whole numbers alone, D = 0, the ends' rounding 0.5 is not small against the lines, and the
  // crossing's box is unbounded.)
  const std::string square3 = "<rect x=\"0\" y=\"0\" width=\"10.000\" height=\"10.000\" fill=\"none\" stroke=\"#000\"/>\n";
  const CreasePattern q = parse_svg(svg(square3 + "<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"10\" stroke=\"red\"/>"
                                                  "<line x1=\"10\" y1=\"0\" x2=\"0\" y2=\"10\" stroke=\"blue\"/>"),
                                    "x.svg");
  ASSERT_TRUE(q.position_bounds.covers(q.num_vertices()));
  for (int v = 0; v < q.num_vertices(); ++v) {
    const Eigen::Vector2d lo = q.position_bounds.lo[v], hi = q.position_bounds.hi[v];
    EXPECT_TRUE(std::isfinite(lo.x()) && std::isfinite(hi.y())) << v;
    EXPECT_LE(lo.x(), q.vertices[v].x());
    EXPECT_GE(hi.y(), q.vertices[v].y());
    if (std::abs(q.vertices[v].x() - 5) < 1e-12) {
      // First order: each diagonal shifts by <= 0.0005 sqrt 2, at right angles: twice that sum.
      EXPECT_NEAR(hi.x() - q.vertices[v].x(), 2 * 2 * 0.0005 * std::sqrt(2.0), 1e-12) << "the crossing";
    }
  }
}

TEST(SvgCorpusBounds, EveryVertexLiesInItsBox) {
  for (const char* name : {"miura-ori.svg", "miura_sharpangle.svg", "singlesquaretwist.svg", "hypar.svg", "reschTriTessellation.svg",
                           "huffmanWaterbomb.svg", "traditionalCrane.svg"}) {
    const std::string path = corpus(std::string("origami-simulator/") + name);
    ASSERT_TRUE(std::filesystem::exists(path)) << "missing from tests/data/corpus";
    const CreasePattern p = read_svg(path);
    const auto& b = p.position_bounds;
    ASSERT_TRUE(b.covers(p.num_vertices())) << name;
    EXPECT_GE(b.decimal_places, 1) << name;
    for (int v = 0; v < p.num_vertices(); ++v)
      for (int k = 0; k < 2; ++k) {
        EXPECT_LE(b.lo[v][k], p.vertices[v][k]) << name << " vertex " << v;
        EXPECT_GE(b.hi[v][k], p.vertices[v][k]) << name << " vertex " << v;
        EXPECT_GT(b.hi[v][k] - b.lo[v][k], 0.0) << name << " vertex " << v;
      }
  }
}

TEST(SvgReader, TJunctionsSplitTheLineTheyMeet) {
  // A valley from the left side to the middle of a mountain that crosses the square.
  const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"5\" y1=\"0\" x2=\"5\" y2=\"10\" stroke=\"red\"/>"
                                                  "<line x1=\"0\" y1=\"5\" x2=\"5\" y2=\"5\" stroke=\"blue\"/>"),
                                    "t.svg");
  EXPECT_EQ(p.num_vertices(), 8);  // 4 corners, the 3 ends on the sides, the T
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 7}, {'M', 2}, {'V', 1}}));
  EXPECT_EQ(p.num_faces(), 3);
}

TEST(SvgReader, NearCoincidentEndsMergeWithinTheToleranceOnly) {
  // The crease stops 2e-4 short of the far side (relative to the 14.1 diagonal: 1.4e-5).
  const std::string body = kSquare + "<line x1=\"0\" y1=\"5\" x2=\"9.9998\" y2=\"5.0001\" stroke=\"red\"/>";
  SvgImportSummary s;
  const CreasePattern p = parse_svg(svg(body), "gap.svg", {}, &s);
  EXPECT_EQ(p.num_faces(), 2);
  EXPECT_EQ(letters(p)['M'], 1);
  EXPECT_GT(s.max_merge_distance, 0.0);
  EXPECT_LE(s.max_merge_distance, s.merge_tolerance);
  EXPECT_NEAR(s.pattern_size, std::sqrt(200.0), 1e-12);
  bool reported = false;
  for (const auto& w : p.warnings) reported = reported || w.find("merged") != std::string::npos;
  EXPECT_TRUE(reported);
  // With a tolerance below the gap the crease stops short of the side: the loose end is
  // joined to the side (loose_end_snap.hpp) ...
  SvgReadOptions tight;
  tight.merge_tolerance = 1e-6;
  SvgImportSummary s3;
  const CreasePattern joined = parse_svg(svg(body), "gap.svg", tight, &s3);
  EXPECT_EQ(joined.num_faces(), 2);
  EXPECT_EQ(s3.loose_ends_snapped, 1);
  EXPECT_EQ(s3.loose_ends_onto_lines, 1);
  // ... and without that, it dangles: it is removed and no face splits.
  tight.loose_end_snap = 0;
  SvgImportSummary s2;
  const CreasePattern q = parse_svg(svg(body), "gap.svg", tight, &s2);
  EXPECT_EQ(q.num_faces(), 1);
  EXPECT_EQ(letters(q)['M'], 0);
  EXPECT_EQ(s2.dangling_edges_removed, 1);
  EXPECT_EQ(s2.loose_ends_snapped, 0);
}

TEST(SvgReader, LinesStoppingShortOfAVertexOrLineAreJoinedToIt) {
  // A 400 x 400 square (size 566: snap distance 3, Origami Simulator's vertTol); mountains
  // across it and along a diagonal cross at (200, 200). Two valleys come down from the top
  // side and stop 2.5 short: one of that crossing (a vertex), one of the horizontal mountain
  // at (300, 200) (a line), as Origami Simulator's hypar.svg draws one of its creases.
  const std::string body =
      "<polygon points=\"0,0 400,0 400,400 0,400\" stroke=\"black\" fill=\"none\"/>"
      "<line x1=\"0\" y1=\"200\" x2=\"400\" y2=\"200\" stroke=\"red\"/>"
      "<line x1=\"0\" y1=\"0\" x2=\"400\" y2=\"400\" stroke=\"red\"/>"
      "<line x1=\"200\" y1=\"0\" x2=\"200\" y2=\"197.5\" stroke=\"blue\"/>"
      "<line x1=\"300\" y1=\"0\" x2=\"300\" y2=\"197.5\" stroke=\"blue\"/>";
  SvgImportSummary s;
  const CreasePattern p = parse_svg(svg(body), "short.svg", {}, &s);
  EXPECT_DOUBLE_EQ(s.loose_end_snap, 3.0);
  EXPECT_EQ(s.loose_ends_snapped, 2);
  EXPECT_EQ(s.loose_ends_onto_lines, 1);
  EXPECT_DOUBLE_EQ(s.max_snap_distance, 2.5);
  EXPECT_EQ(s.dangling_edges_removed, 0);
  EXPECT_EQ(p.num_faces(), 6);  // 4 quarters of the mountains, each valley splitting one
  EXPECT_EQ(letters(p)['V'], 2);
  EXPECT_EQ(letters(p)['M'], 5);  // the horizontal split at the crossing and at (300, 200)
  int centre_degree = 0;  // the valley ends exactly at the crossing
  for (const auto& e : p.edges)
    for (int v : e)
      centre_degree += std::abs(p.vertices[v].x() - 200) < 1e-12 && std::abs(p.vertices[v].y() + 200) < 1e-12;
  EXPECT_EQ(centre_degree, 5);
  bool warned = false;
  for (const auto& w : p.warnings) warned = warned || w.find("2 loose line ends joined") != std::string::npos;
  EXPECT_TRUE(warned);
  // Not joined: both valleys dangle and are removed.
  SvgReadOptions no_snap;
  no_snap.loose_end_snap = 0;
  SvgImportSummary s0;
  const CreasePattern q = parse_svg(svg(body), "short.svg", no_snap, &s0);
  EXPECT_EQ(s0.loose_ends_snapped, 0);
  EXPECT_EQ(s0.dangling_edges_removed, 2);
  EXPECT_EQ(q.num_faces(), 4);
  EXPECT_EQ(letters(q)['V'], 0);
  // The snap distance is at most 1e-2 of the pattern: the same drawing scaled down 10x
  // (size 56.6, snap 0.566) leaves the 0.25 gaps joined and a 1 gap alone.
  const std::string scaled = "<g transform=\"scale(0.1)\">" + body + "</g>";
  SvgImportSummary s10;
  (void)parse_svg(svg(scaled), "short.svg", {}, &s10);
  EXPECT_NEAR(s10.loose_end_snap, 0.01 * s10.pattern_size, 1e-12);
  EXPECT_EQ(s10.loose_ends_snapped, 2);
  SvgReadOptions narrow;
  narrow.loose_end_snap = 1.5;  // below the 2.5 gaps (and the 1.77 from (200, 197.5) to the diagonal)
  SvgImportSummary s2;
  (void)parse_svg(svg(body), "short.svg", narrow, &s2);
  EXPECT_EQ(s2.loose_ends_snapped, 0);
  EXPECT_EQ(s2.dangling_edges_removed, 2);
}

TEST(SvgReader, TransformsComposeThroughNestedGroups) {
  // The same square with diagonals drawn plainly at its final place, and through nested
  // groups whose transforms (translate, rotate about a centre, scale, skew, matrix) compose
  // to the identity on it plus a translation of (20, 30).
  const std::string plain =
      "<rect x=\"20\" y=\"30\" width=\"10\" height=\"10\" stroke=\"black\"/>"
      "<line x1=\"20\" y1=\"30\" x2=\"30\" y2=\"40\" stroke=\"red\"/><line x1=\"30\" y1=\"30\" x2=\"20\" y2=\"40\" stroke=\"red\"/>";
  const std::string nested =
      "<g transform=\"translate(20 30) rotate(90, 5, 5)\">"
      "  <g transform=\"scale(2) skewX(45)\">"
      "    <g transform=\"matrix(1 0 0 1 0 0) skewX(-45) scale(0.5)\"><g transform=\"rotate(-90 5 5)\">"
      "      <rect width=\"10\" height=\"10\" stroke=\"black\"/>"
      "      <line x2=\"10\" y2=\"10\" stroke=\"red\"/><line x1=\"10\" y2=\"10\" stroke=\"red\"/>"
      "    </g></g></g></g>";
  const CreasePattern a = parse_svg(svg(plain), "plain.svg"), b = parse_svg(svg(nested), "nested.svg");
  EXPECT_EQ(a.num_vertices(), 5);
  EXPECT_EQ(rounded_vertices(a), rounded_vertices(b));
  EXPECT_EQ(letters(a), letters(b));
  // matrix() alone: a rotation by 90 degrees about the origin maps (10, 0) to (0, 10).
  const CreasePattern c = parse_svg(svg("<g transform=\"matrix(0,1,-1,0,0,0)\">" + kSquare +
                                        "<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"10\" stroke=\"red\"/></g>"),
                                    "m.svg");
  EXPECT_EQ(rounded_vertices(c), (std::set<std::pair<double, double>>{{0, 0}, {0, -10}, {-10, 0}, {-10, -10}}));
}

TEST(SvgReader, EveryPathCommandAbsoluteAndRelative) {
  // One square boundary and its two diagonals, drawn four ways.
  const std::string ways[] = {
      "<path stroke=\"#000\" d=\"M0,0 L10,0 L10,10 L0,10 Z\"/><path stroke=\"#f00\" d=\"M0 0 L10 10 M10 0 L0 10\"/>",
      "<path stroke=\"#000\" d=\"m0 0 h10 v10 h-10 z\"/><path stroke=\"#f00\" d=\"m0,0 l10,10 m0-10 l-10,10\"/>",
      "<path stroke=\"#000\" d=\"M0 0H10V10H0V0\"/><path stroke=\"#f00\" d=\"M0 0 10 10M10 0 0 10\"/>",  // implicit line-tos
      "<polygon stroke=\"#000\" points=\"0,0 10,0 10,10 0,10\"/><polyline stroke=\"#f00\" points=\"0 0 10 10\"/>"
      "<path stroke=\"#f00\" d=\"m10 0 l-5 5 l-5 5\"/>",
  };
  for (const auto& w : ways) {
    const CreasePattern p = parse_svg(svg(w), "p.svg");
    EXPECT_EQ(p.num_vertices(), 5) << w;
    EXPECT_EQ(p.num_faces(), 4) << w;
    EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 4}, {'M', 4}})) << w;
    EXPECT_EQ(rounded_vertices(p), (std::set<std::pair<double, double>>{{0, 0}, {10, 0}, {0, -10}, {10, -10}, {5, -5}})) << w;
  }
}

TEST(SvgReader, ColourInEveryCssForm) {
  const std::pair<std::string, char> forms[] = {
      {"stroke=\"#f00\"", 'M'},
      {"stroke=\"#FF0000\"", 'M'},
      {"stroke=\"rgb(255, 0, 0)\"", 'M'},
      {"stroke=\"rgb(100%,0%,0%)\"", 'M'},
      {"stroke=\"RED\"", 'M'},
      {"style=\"fill:none; stroke: #0000ff\"", 'V'},
      {"stroke=\"red\" style=\"stroke:blue\"", 'V'},  // style wins over the attribute
      {"stroke=\"rgba(0,0,255,0.5)\"", 'V'},
      {"stroke=\"#ff0\"", 'F'},
      {"stroke=\"yellow\"", 'F'},
      {"stroke=\"magenta\"", 'U'},
      {"stroke=\"#f0f\"", 'U'},
      {"stroke=\"lime\"", 'C'},
      {"stroke=\"currentColor\" color=\"#00f\"", 'V'},
  };
  for (const auto& [attr, letter] : forms) {
    const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" " + attr + "/>"), "c.svg");
    if (letter == 'C') {  // a cut along the whole square splits the sheet in two
      EXPECT_EQ(letters(p)['C'], 1) << attr;
      continue;
    }
    EXPECT_EQ(letters(p)[letter], 1) << attr;
    EXPECT_EQ(p.num_faces(), 2) << attr;
  }
  // Inherited from an enclosing group, overridden by the element.
  const CreasePattern g = parse_svg(svg("<g stroke=\"#0000FF\">" + std::string("<rect width=\"10\" height=\"10\" stroke=\"black\"/>") +
                                        "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\"/><g><line x1=\"5\" y1=\"0\" x2=\"5\" y2=\"10\"/></g></g>"),
                                    "g.svg");
  EXPECT_EQ(letters(g), (std::map<char, int>{{'B', 8}, {'V', 4}}));
}

TEST(SvgReader, OtherColoursAndUnstrokedShapesAreIgnoredWithAWarning) {
  const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"#00ffff\"/>"
                                                  "<line x1=\"5\" y1=\"0\" x2=\"5\" y2=\"10\" stroke=\"gray\" stroke-dasharray=\"2 2\"/>"
                                                  "<rect width=\"10\" height=\"10\" fill=\"#eee\"/>"
                                                  "<defs><line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"10\" stroke=\"red\"/></defs>"),
                                    "o.svg");
  EXPECT_EQ(p.num_faces(), 1);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 4}}));
  int colour_warnings = 0;
  for (const auto& w : p.warnings) colour_warnings += w.find("is not a crease colour") != std::string::npos;
  EXPECT_EQ(colour_warnings, 2);
}

TEST(SvgReader, DashesDoNotChangeTheAssignment) {
  const auto solid = parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"#00f\"/>"), "s.svg");
  const auto dashed = parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"#00f\" stroke-dasharray=\"4,2\"/>"), "d.svg");
  EXPECT_EQ(letters(solid), letters(dashed));
  EXPECT_EQ(solid.fold_angles, dashed.fold_angles);
}

TEST(SvgReader, OpacityGivesTheFoldAngleAsOrigamiSimulatorReadsIt) {
  const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"#00f\" opacity=\"0.5\"/>"
                                                  "<g opacity=\"0.5\"><line x1=\"5\" y1=\"0\" x2=\"5\" y2=\"5\" stroke=\"#f00\" stroke-opacity=\"0.5\"/></g>"
                                                  "<line x1=\"5\" y1=\"5\" x2=\"5\" y2=\"10\" stroke=\"#ff0\"/>"),
                                    "a.svg");
  int checked = 0;
  for (int e = 0; e < p.num_edges(); ++e) {
    switch (p.assignments[e]) {
      case Assignment::Valley: EXPECT_DOUBLE_EQ(*p.fold_angles[e], std::numbers::pi / 2); ++checked; break;
      case Assignment::Mountain: EXPECT_DOUBLE_EQ(*p.fold_angles[e], -std::numbers::pi / 4); ++checked; break;
      case Assignment::Flat: EXPECT_DOUBLE_EQ(*p.fold_angles[e], 0.0); ++checked; break;
      default: EXPECT_FALSE(p.fold_angles[e].has_value());
    }
  }
  EXPECT_EQ(checked, 4);  // the valley is split in two by the T-junctions
  // Written to FOLD and read back: the same letters and angles.
  const CreasePattern q = parse_fold(write_fold_string(p), "round.fold");
  EXPECT_EQ(q.fold_angles.size(), p.fold_angles.size());
  for (int e = 0; e < q.num_edges(); ++e) {
    EXPECT_EQ(q.assignments[e], p.assignments[e]);
    if (!p.fold_angles[e]) continue;
    ASSERT_TRUE(q.fold_angles[e].has_value());
    EXPECT_NEAR(*q.fold_angles[e], *p.fold_angles[e], 1e-15);
  }
}

TEST(SvgReader, LinesOvershootingTheBoundaryAreTrimmed) {
  // A mountain from a corner and a valley from another cross 0.4 below the black square;
  // the mountain also starts a little before its corner.
  SvgImportSummary s;
  const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"-0.2\" y1=\"-0.416\" x2=\"5.5\" y2=\"11.44\" stroke=\"red\"/>"
                                                  "<line x1=\"10\" y1=\"0\" x2=\"4.5\" y2=\"11.44\" stroke=\"blue\"/>"),
                                    "over.svg", {}, &s);
  EXPECT_EQ(s.dangling_edges_removed, 3);          // the mountain's head, both tails past the crossing
  EXPECT_EQ(s.faces_outside_boundary_removed, 1);  // the small triangle below the square
  EXPECT_EQ(p.num_faces(), 3);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 6}, {'M', 1}, {'V', 1}}));
  const Topology t = build_topology(p);
  EXPECT_EQ(t.components.size(), 1u);
  for (const auto& v : p.vertices) {
    EXPECT_GE(v.x(), -1e-12);
    EXPECT_LE(v.x(), 10 + 1e-12);
    EXPECT_LE(v.y(), 1e-12);
    EXPECT_GE(v.y(), -10 - 1e-12);
  }
}

// ---- lines drawn twice (svg_reader.hpp, "Lines drawn twice") ------------------------------

std::vector<std::string> merge_warnings(const CreasePattern& p) {
  std::vector<std::string> out;
  for (const auto& w : p.warnings)
    if (w.find("the same crease") != std::string::npos) out.push_back(w);
  return out;
}

TEST(SvgReader, OneSegmentInTwoColoursTakesTheLaterColour) {
  const std::string red = "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\"/>\n";
  const std::string blue = "<line x1=\"10\" y1=\"5\" x2=\"0\" y2=\"5\" stroke=\"blue\"/>\n";
  // kSquare is the <rect> on line 3; the lines follow on lines 4 and 5.
  SvgImportSummary s;
  const CreasePattern rb = parse_svg(svg(kSquare + red + blue), "two.svg", {}, &s);
  EXPECT_EQ(letters(rb), (std::map<char, int>{{'B', 6}, {'V', 1}}));
  EXPECT_EQ(rb.num_faces(), 2);
  EXPECT_EQ(s.overwritten_edges, 1);
  EXPECT_EQ(merge_warnings(rb), (std::vector<std::string>{"two.svg: <line> #1 (line 4) and <line> #2 (line 5) draw the same crease from "
                                                          "(10, 5) to (0, 5) as mountain and valley: kept valley (the later line, as "
                                                          "ORIPA's editor does)"}));
  ASSERT_EQ(s.merged_lines.size(), 1u);
  EXPECT_EQ(s.merged_lines[0].first, "<line> #1 (line 4)");
  EXPECT_EQ(s.merged_lines[0].second, "<line> #2 (line 5)");
  EXPECT_EQ(s.merged_lines[0].kept_letter, Assignment::Valley);
  ASSERT_TRUE(s.merged_lines[0].kept_fold_angle.has_value());
  EXPECT_DOUBLE_EQ(*s.merged_lines[0].kept_fold_angle, std::numbers::pi);
  for (int e = 0; e < rb.num_edges(); ++e)
    if (rb.assignments[e] == Assignment::Valley) EXPECT_DOUBLE_EQ(*rb.fold_angles[e], std::numbers::pi);
  const CreasePattern br = parse_svg(svg(kSquare + blue + red), "two.svg");
  EXPECT_EQ(letters(br), (std::map<char, int>{{'B', 6}, {'M', 1}}));
  EXPECT_EQ(merge_warnings(br), (std::vector<std::string>{"two.svg: <line> #1 (line 4) and <line> #2 (line 5) draw the same crease from "
                                                          "(0, 5) to (10, 5) as valley and mountain: kept mountain (the later line, as "
                                                          "ORIPA's editor does)"}));
  // One colour at two opacities: the later fold angle.
  const CreasePattern half =
      parse_svg(svg(kSquare + red + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\" opacity=\"0.5\"/>"), "two.svg");
  EXPECT_EQ(letters(half), (std::map<char, int>{{'B', 6}, {'M', 1}}));
  for (int e = 0; e < half.num_edges(); ++e)
    if (half.assignments[e] == Assignment::Mountain) EXPECT_DOUBLE_EQ(*half.fold_angles[e], -std::numbers::pi / 2);
  EXPECT_EQ(merge_warnings(half), (std::vector<std::string>{"two.svg: <line> #1 (line 4) and <line> #2 (line 5) draw the same crease from "
                                                            "(0, 5) to (10, 5) as mountain with two opacities (fold angles -180 deg and "
                                                            "-90 deg): kept -90 deg (the later line, as ORIPA's editor does)"}));
  // The same colour twice: one edge, warned.
  SvgImportSummary s2;
  const CreasePattern same = parse_svg(svg(kSquare + red + red), "two.svg", {}, &s2);
  EXPECT_EQ(letters(same), (std::map<char, int>{{'B', 6}, {'M', 1}}));
  EXPECT_EQ(s2.duplicate_edges, 1);
  EXPECT_EQ(merge_warnings(same), (std::vector<std::string>{"two.svg: <line> #1 (line 4) and <line> #2 (line 5) draw the same crease from "
                                                            "(0, 5) to (10, 5), both as mountain: merged into one edge"}));
}

TEST(SvgReader, ACreaseOverTheBoundaryLeavesTheBoundary) {
  // A red line along the top side of the black square, drawn after it: the side stays B.
  SvgImportSummary s;
  const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\" stroke=\"red\"/>"), "side.svg", {}, &s);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 4}}));
  EXPECT_EQ(merge_warnings(p), (std::vector<std::string>{"side.svg: <rect> #1 (line 3) and <line> #1 (line 4) draw the same crease from "
                                                         "(0, 0) to (10, 0) as boundary and mountain: kept boundary (a crease drawn "
                                                         "over the paper's outline or a cut does not replace it)"}));
  ASSERT_EQ(s.merged_lines.size(), 1u);
  EXPECT_EQ(s.merged_lines[0].rule, MergedLines::Rule::Outline);
  // The black square drawn after a blue line on its side: the later line, B, too.
  const CreasePattern q = parse_svg(svg("<line x1=\"0\" y1=\"0\" x2=\"10\" y2=\"0\" stroke=\"blue\"/>" + kSquare), "side.svg", {}, &s);
  EXPECT_EQ(letters(q), (std::map<char, int>{{'B', 4}}));
  ASSERT_EQ(s.merged_lines.size(), 1u);
  EXPECT_EQ(s.merged_lines[0].rule, MergedLines::Rule::Later);
}

TEST(SvgReader, LinesDrawnTwiceAcrossCrossingsAreOneWarning) {
  // A valley across the square over a mountain, both crossed by a vertical valley: two pieces,
  // one warning naming the stretch from end to end.
  SvgImportSummary s;
  const CreasePattern p = parse_svg(svg(kSquare + "<line x1=\"5\" y1=\"0\" x2=\"5\" y2=\"10\" stroke=\"blue\"/>"
                                                  "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\"/>"
                                                  "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"blue\"/>"),
                                    "cross.svg", {}, &s);
  EXPECT_EQ(letters(p), (std::map<char, int>{{'B', 8}, {'V', 4}}));
  EXPECT_EQ(s.overwritten_edges, 2);
  ASSERT_EQ(s.merged_lines.size(), 1u);
  EXPECT_EQ(s.merged_lines[0].pieces, 2);
  EXPECT_EQ(s.merged_lines[0].stretches, 1);
  EXPECT_EQ(merge_warnings(p).size(), 1u);
  EXPECT_NE(merge_warnings(p)[0].find("from (0, 5) to (10, 5) as mountain and valley: kept valley"), std::string::npos) << merge_warnings(p)[0];
  // Many pairs: ten warnings and a tally; the summary lists them all.
  std::string many = kSquare;
  for (int k = 1; k <= 12; ++k) {
    const std::string y = std::to_string(k * 0.75);
    many += "<line x1=\"0\" y1=\"" + y + "\" x2=\"10\" y2=\"" + y + "\" stroke=\"red\"/><line x1=\"0\" y1=\"" + y + "\" x2=\"10\" y2=\"" + y +
            "\" stroke=\"blue\"/>";
  }
  SvgImportSummary sm;
  const CreasePattern m = parse_svg(svg(many), "many.svg", {}, &sm);
  EXPECT_EQ(sm.merged_lines.size(), 12u);
  const auto w = merge_warnings(m);
  ASSERT_EQ(w.size(), 11u);
  EXPECT_EQ(w.back(), "many.svg: ... and 2 more pairs of lines drawing the same crease, merged by the same rule (import --json lists each)");
}

TEST(SvgReaderBadInput, StrictLinesRefusesTwoColoursOnOneSegment) {
  SvgReadOptions strict;
  strict.strict_lines = true;
  const std::string two = svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\"/>\n"
                                        "<line x1=\"10\" y1=\"5\" x2=\"0\" y2=\"5\" stroke=\"blue\"/>");
  try {
    (void)parse_svg(two, "bad.svg", strict);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bad.svg: <line> #1 (line 4) and <line> #2 (line 5): draw the same crease from (10, 5) to (0, 5) as mountain and valley");
  }
  const std::string opacities = svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\"/>"
                                              "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\" opacity=\"0.5\"/>");
  try {
    (void)parse_svg(opacities, "bad.svg", strict);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("with two opacities (fold angles)"), std::string::npos) << e.what();
  }
  // The same colour twice is no conflict.
  EXPECT_EQ(parse_svg(svg(kSquare + "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\"/>"
                                    "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"red\"/>"),
                      "ok.svg", strict)
                .num_faces(),
            2);
}

// ---- bad SVGs -------------------------------------------------------------------------

void expect_refused(const std::string& text, const std::vector<std::string>& parts) {
  try {
    (void)parse_svg(text, "bad.svg");
    ADD_FAILURE() << "accepted: " << text.substr(0, 200);
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("bad.svg", 0), 0u) << what;
    for (const auto& p : parts) EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

TEST(SvgReaderBadInput, RefusedNamingTheElement) {
  expect_refused(svg(kSquare + "<path stroke=\"red\" d=\"M0 0 L5 5\"/><path stroke=\"red\" d=\"M0 0 C1 1 2 2 3 3\"/>"),
                 {"<path> #2", "d", "curve command 'C'"});
  expect_refused(svg(kSquare + "<path stroke=\"red\" d=\"M0 0 A5 5 0 0 1 10 10\"/>"), {"<path> #1", "'A'"});
  expect_refused(svg(kSquare + "<path stroke=\"red\" d=\"L0 0 10 10\"/>"), {"<path> #1", "begin with M"});
  expect_refused(svg(kSquare + "<path stroke=\"red\" d=\"M0 0 L10 x\"/>"), {"<path> #1", "d", "expected a number"});
  expect_refused(svg(kSquare + "<path stroke=\"red\" d=\"M0 0 L1e999 0\"/>"), {"<path> #1", "out of range"});
  expect_refused(svg(kSquare + "<polyline stroke=\"red\" points=\"0 0 10\"/>"), {"<polyline> #1", "points", "odd number"});
  expect_refused(svg(kSquare + "<line x1=\"10%\" x2=\"5\" stroke=\"red\"/>"), {"<line> #1", "x1", "relative unit"});
  expect_refused(svg("<g transform=\"rotate(1,2)\">" + kSquare + "</g>"), {"<g> #1", "transform", "rotate() takes 1 or 3"});
  expect_refused(svg("<g transform=\"spin(3)\">" + kSquare + "</g>"), {"transform", "unknown transform function 'spin'"});
  expect_refused(svg(kSquare + "<line x2=\"10\" stroke=\"rgb(1,2)\"/>"), {"<line> #1", "stroke"});
  expect_refused(svg(kSquare + "<rect width=\"5\" height=\"5\" rx=\"1\" stroke=\"red\"/>"), {"<rect> #2", "rounded corners"});
  expect_refused(svg("<line x2=\"10\" stroke=\"#888\"/>"), {"no crease lines"});
  expect_refused(svg(""), {"no crease lines"});
}

TEST(SvgReaderBadInput, XmlProblemsAndEntityExpansionAreRefused) {
  expect_refused("<svg xmlns=\"http://www.w3.org/2000/svg\"><line></svg>", {"line 1", "XML:"});
  expect_refused("not xml at all", {"XML:"});
  expect_refused("<html><body/></html>", {"root element is <html>"});
  // Billion laughs: refused at the internal subset, before any entity is declared or expanded.
  std::string lol = "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [\n <!ENTITY lol \"lol\">\n";
  for (int k = 1; k < 10; ++k) {
    lol += " <!ENTITY lol" + std::to_string(k) + " \"";
    for (int j = 0; j < 10; ++j) lol += "&lol" + (k > 1 ? std::to_string(k - 1) : std::string()) + ";";
    lol += "\">\n";
  }
  lol += "]>\n<svg xmlns=\"http://www.w3.org/2000/svg\"><desc>&lol9;</desc></svg>\n";
  expect_refused(lol, {"internal subset"});
  // An external DTD reference alone (as Illustrator writes) is fine; it is never fetched.
  const std::string illustrator = svg(kSquare, "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n");
  EXPECT_EQ(parse_svg(illustrator, "ok.svg").num_faces(), 1);
  // ... but an entity it might define is not expanded.
  expect_refused(svg(kSquare + "<desc>&nbsp;</desc>", "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"svg11.dtd\">\n"), {"entity"});
}

TEST(SvgReaderBadInput, LimitsAreEnforced) {
  std::string deep;
  for (int k = 0; k < kMaxSvgDepth + 5; ++k) deep += "<g>";
  for (int k = 0; k < kMaxSvgDepth + 5; ++k) deep += "</g>";
  expect_refused(svg(kSquare + deep), {"nested more than " + std::to_string(kMaxSvgDepth)});
  // One path with more segments than allowed: refused while reading, naming the path.
  std::string d = "M0 0";
  for (int k = 0; k <= kMaxSvgSegments; ++k) d += k % 2 ? " L0 0" : " L1 1";
  expect_refused(svg(kSquare + "<path stroke=\"red\" d=\"" + d + "\"/>"), {"<path> #1", "line segments"});
}

}}  // namespace
}  // namespace rigidfold
