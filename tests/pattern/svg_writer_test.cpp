// SVG crease patterns written by kernel/pattern/svg_writer.hpp: every bundled pattern
// written as SVG and read back by the SVG reader (svg_reader.hpp) gives the same FOLD,
// compared as sets: vertex coordinates bit for bit (the writer prints the shortest decimal
// that reads back to the same double, the reader flips y back exactly, and a vertex drawn
// by several line ends sits at their mean, which for equal doubles is the double itself),
// edges as unordered vertex pairs with their letters and fold angles (to one ulp: the opacity
// written is the double whose product with pi, as the reader forms it, is nearest to the
// angle; the products of consecutive opacities are about 1.6 ulp of the angle apart, so not
// every angle is reachable exactly, and none is off by more than one ulp), faces as cyclic vertex
// lists with their orientation. A 3D pattern is compared against its flat development
// (flat_development.hpp); the bundled tube has none and is refused, naming its hole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/flat_development.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/svg_reader.hpp"
#include "kernel/pattern/svg_writer.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::vector<std::string> bundled_files() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled"))
    if (entry.path().extension() == ".fold") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// The fold angle the reader gives an edge of letter a written with angle rho.
std::optional<double> expected_angle(Assignment a, const std::optional<double>& rho) {
  if (a == Assignment::Flat) return 0.0;
  if (has_fold_sign(a) && rho && *rho != 0) return rho;
  return std::nullopt;
}

bool within_one_ulp(double got, double want) {
  return got == want || got == std::nextafter(want, 4.0) || got == std::nextafter(want, -4.0);
}

std::vector<int> canonical_cycle(std::vector<int> f) {
  std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  return f;
}

// `got` (read back) against `want` (a flat pattern), as sets.
void expect_same_as_sets(const CreasePattern& want, const CreasePattern& got, const std::string& name) {
  SCOPED_TRACE(name);
  EXPECT_EQ(got.length_exponent, want.length_exponent);
  ASSERT_EQ(got.num_vertices(), want.num_vertices());
  std::map<std::pair<double, double>, int> where;
  for (int v = 0; v < want.num_vertices(); ++v) {
    EXPECT_EQ(want.vertices[v].z(), 0.0);
    where[{want.vertices[v].x(), want.vertices[v].y()}] = v;
  }
  ASSERT_EQ(static_cast<int>(where.size()), want.num_vertices()) << "two vertices at one point";
  std::vector<int> to_want(got.num_vertices(), -1);
  for (int v = 0; v < got.num_vertices(); ++v) {
    const auto it = where.find({got.vertices[v].x(), got.vertices[v].y()});
    ASSERT_NE(it, where.end()) << "vertex " << v << " (" << got.vertices[v].x() << ", " << got.vertices[v].y()
                               << ") is at no vertex of the pattern (bit for bit)";
    to_want[v] = it->second;
  }
  ASSERT_EQ(got.num_edges(), want.num_edges());
  std::map<std::pair<int, int>, int> edge_of;
  for (int e = 0; e < want.num_edges(); ++e)
    edge_of[{std::min(want.edges[e][0], want.edges[e][1]), std::max(want.edges[e][0], want.edges[e][1])}] = e;
  for (int e = 0; e < got.num_edges(); ++e) {
    const int a = to_want[got.edges[e][0]], b = to_want[got.edges[e][1]];
    const auto it = edge_of.find({std::min(a, b), std::max(a, b)});
    ASSERT_NE(it, edge_of.end()) << "edge " << e << " joins vertices " << a << " and " << b << ", which no edge of the pattern joins";
    const int w = it->second;
    EXPECT_EQ(got.assignments[e], want.assignments[w]) << "edge " << w;
    const auto angle = expected_angle(want.assignments[w], want.fold_angles[w]);
    ASSERT_EQ(got.fold_angles[e].has_value(), angle.has_value()) << "edge " << w;
    if (angle) {
      EXPECT_TRUE(within_one_ulp(*got.fold_angles[e], *angle)) << "edge " << w << ": " << *got.fold_angles[e] << " for " << *angle;
    }
  }
  std::set<std::vector<int>> want_faces, got_faces;
  for (const auto& f : want.faces) want_faces.insert(canonical_cycle(f));
  for (const auto& f : got.faces) {
    std::vector<int> g;
    for (int v : f) g.push_back(to_want[v]);
    got_faces.insert(canonical_cycle(g));
  }
  EXPECT_EQ(got_faces, want_faces);
}

TEST(SvgWriter, EveryBundledPatternReadsBackTheSame) {
  int compared = 0, refused = 0;
  for (const auto& path : bundled_files()) {
    const CreasePattern p = read_fold(path);
    std::string svg;
    try {
      svg = write_svg_string(p, path);
    } catch (const InputError& e) {
      // Only the tube (a 3D sheet with a hole) has no flat crease pattern.
      EXPECT_FALSE(p.coords_2d) << path << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("1 hole"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      ++refused;
      continue;
    }
    const CreasePattern q = parse_svg(svg, path + ".svg");
    expect_same_as_sets(flat_development(p, path).pattern, q, path);
    ++compared;
  }
  EXPECT_EQ(compared, 12);
  EXPECT_EQ(refused, 1);  // miura_tube_6_alpha60.fold
}

CreasePattern square_with_diagonal(Assignment diagonal, std::optional<double> rho) {
  CreasePattern p;
  p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}};
  p.assignments = {Assignment::Boundary, Assignment::Boundary, Assignment::Boundary, Assignment::Boundary, diagonal};
  p.fold_angles = {std::nullopt, std::nullopt, std::nullopt, std::nullopt, rho};
  return p;
}

TEST(SvgWriter, WritesColoursOpacityAndFlippedY) {
  const std::string svg = write_svg_string(square_with_diagonal(Assignment::Valley, std::numbers::pi / 2), "sq");
  EXPECT_NE(svg.find("<line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"-1\" stroke=\"#0000ff\" stroke-opacity=\"0.5\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<line x1=\"1\" y1=\"0\" x2=\"1\" y2=\"-1\" stroke=\"#000000\"/>"), std::string::npos) << svg;
  EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n') - 6, 5) << svg;  // 5 lines besides the header and footer
  const std::string m = write_svg_string(square_with_diagonal(Assignment::Mountain, -std::numbers::pi / 2), "sq");
  EXPECT_NE(m.find("stroke=\"#ff0000\" stroke-opacity=\"0.5\""), std::string::npos) << m;
  // No angle: transparent, which the reader reads as no angle.
  const std::string none = write_svg_string(square_with_diagonal(Assignment::Mountain, std::nullopt), "sq");
  EXPECT_NE(none.find("stroke=\"#ff0000\" stroke-opacity=\"0\""), std::string::npos) << none;
  const CreasePattern back = parse_svg(none, "none.svg");
  int mountains = 0;
  for (int e = 0; e < back.num_edges(); ++e) {
    if (back.assignments[e] != Assignment::Mountain) continue;
    EXPECT_FALSE(back.fold_angles[e].has_value());
    ++mountains;
  }
  EXPECT_EQ(mountains, 1);
}

TEST(SvgWriter, EveryAngleRoundTripsToOneUlp) {
  // Degrees as a FOLD file gives them, through radians and the opacity; most come back bit
  // for bit, the rest one ulp off (see the top of this file).
  int exact = 0, total = 0;
  for (double deg = -180; deg <= 180; deg += 0.37) {
    if (deg == 0) continue;
    const double rho = deg * std::numbers::pi / 180;
    const Assignment a = rho < 0 ? Assignment::Mountain : Assignment::Valley;
    const CreasePattern q = parse_svg(write_svg_string(square_with_diagonal(a, rho), "sq"), "sq.svg");
    int found = 0;
    for (int e = 0; e < q.num_edges(); ++e)
      if (q.assignments[e] == a) {
        ASSERT_TRUE(q.fold_angles[e].has_value());
        EXPECT_TRUE(within_one_ulp(*q.fold_angles[e], rho)) << deg << " deg: " << *q.fold_angles[e] - rho;
        exact += *q.fold_angles[e] == rho;
        ++found;
      }
    EXPECT_EQ(found, 1);
    ++total;
  }
  EXPECT_GT(exact, total / 2);
}

TEST(SvgWriter, RefusesWhatTheConventionCannotSay) {
  auto message = [](const CreasePattern& p) {
    try {
      write_svg_string(p, "P.fold");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(square_with_diagonal(Assignment::Join, std::nullopt)),
            "P.fold: edges_assignment[4]: J (join) has no colour in Origami Simulator's SVG convention");
  EXPECT_EQ(message(square_with_diagonal(Assignment::Mountain, 0.5)),
            "P.fold: edges_foldAngle[4]: a mountain with a positive fold angle: an SVG opacity cannot say it");
  EXPECT_EQ(message(square_with_diagonal(Assignment::Valley, -0.5)),
            "P.fold: edges_foldAngle[4]: a valley with a negative fold angle: an SVG opacity cannot say it");
}

// A folded 3D Miura (the bundled 12 x 12 folded by its own fold angles) is written as its
// development, which is the flat pattern again up to a rigid motion: same edge lengths and
// face areas, every face counter-clockwise; its SVG reads back as that development.
TEST(SvgWriter, FoldedFormIsWrittenAsItsDevelopment) {
  const std::string path = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_12x12_folded.fold";
  const CreasePattern flat = read_fold(path);
  const Topology t = build_topology(flat, path);
  const FoldedGeometry g = place_faces(flat, t, stored_fold_angles(flat), Eigen::VectorXd::Zero(flat.num_edges()));
  ASSERT_LT(g.relative_mismatch(), 1e-12);
  CreasePattern folded = flat;
  folded.vertices = g.vertices;
  folded.coords_2d = false;
  double zmax = 0;
  for (const auto& v : folded.vertices) zmax = std::max(zmax, std::fabs(v.z()));
  ASSERT_GT(zmax, 0.1);  // really folded
  const FlatDevelopment dev = flat_development(folded, "folded");
  EXPECT_TRUE(dev.unfolded);
  EXPECT_LT(dev.relative_mismatch, 1e-12);
  // Congruent to the flat pattern: 1e-12 of the size covers the rounding of folding and
  // unfolding 12 rows of faces (about 1e-14 here).
  const double size = g.pattern_size;
  for (int e = 0; e < flat.num_edges(); ++e) {
    const double want = (flat.vertices[flat.edges[e][0]] - flat.vertices[flat.edges[e][1]]).norm();
    const double got = (dev.pattern.vertices[flat.edges[e][0]] - dev.pattern.vertices[flat.edges[e][1]]).norm();
    EXPECT_NEAR(got, want, 1e-12 * size) << "edge " << e;
  }
  const Topology td = build_topology(dev.pattern, "dev");
  for (int f = 0; f < flat.num_faces(); ++f) {
    EXPECT_NEAR(td.face_areas[f], t.face_areas[f], 1e-12 * size * size) << "face " << f;
    EXPECT_GT(td.face_normals[f].z(), 0.999999) << "face " << f << " is not counter-clockwise seen from +z";
  }
  const CreasePattern q = parse_svg(write_svg_string(folded, "folded"), "folded.svg");
  expect_same_as_sets(dev.pattern, q, "folded Miura");
}

TEST(SvgWriter, RefusesAFoldedFormThatIsNotDevelopable) {
  const std::string path = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/miura_4x4_alpha60.fold";
  const CreasePattern flat = read_fold(path);
  const Topology t = build_topology(flat, path);
  CreasePattern cone = flat;
  cone.coords_2d = false;
  // Lift one interior vertex: its sectors now sum to less than 360 deg.
  cone.vertices[t.interior_vertices.front()].z() = 0.2;
  try {
    write_svg_string(cone, "cone.fold");
    FAIL() << "a cone was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cone.fold: the folded form is not developable"), std::string::npos) << e.what();
  }
}

}}  // namespace
}  // namespace rigidfold
