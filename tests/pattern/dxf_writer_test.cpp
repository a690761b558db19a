// DXF crease patterns written by kernel/pattern/dxf_writer.hpp, parsed back here as
// group-code pairs: an R12 header, the six letter layers with their ACI colours, one LINE
// per edge on its letter's layer with the pattern's coordinates bit for bit (shortest
// round-trip decimals), for every flat bundled pattern; a J edge and the tube are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "kernel/pattern/dxf_writer.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

std::vector<std::pair<int, std::string>> groups(const std::string& text) {
  std::vector<std::pair<int, std::string>> out;
  std::istringstream in(text);
  std::string code, value;
  while (std::getline(in, code)) {
    EXPECT_TRUE(std::getline(in, value)) << "a group code without a value";
    out.emplace_back(std::stoi(code), value);
  }
  return out;
}

double parse_number(const std::string& s) {
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  EXPECT_TRUE(r.ec == std::errc() && r.ptr == s.data() + s.size()) << s;
  return v;
}

struct DxfLine {
  std::string layer;
  double x1 = 0, y1 = 0, z1 = 1, x2 = 0, y2 = 0, z2 = 1;
};

struct ParsedDxf {
  std::map<std::string, int> layer_colour;
  std::vector<DxfLine> lines;
  std::string version;
};

ParsedDxf parse(const std::string& text) {
  ParsedDxf d;
  const auto g = groups(text);
  EXPECT_FALSE(g.empty());
  EXPECT_EQ(g.back(), (std::pair<int, std::string>{0, "EOF"}));
  std::string section, entity, layer;
  for (std::size_t k = 0; k < g.size(); ++k) {
    const auto& [code, value] = g[k];
    if (code == 0 && value == "SECTION") {
      section = g.at(k + 1).second;
      continue;
    }
    if (code == 9 && value == "$ACADVER") d.version = g.at(k + 1).second;
    if (code == 0) {
      entity = value;
      if (section == "ENTITIES" && value == "LINE") d.lines.emplace_back();
      continue;
    }
    if (section == "TABLES" && entity == "LAYER") {
      if (code == 2) layer = value;
      if (code == 62) d.layer_colour[layer] = std::stoi(value);
    }
    if (section == "ENTITIES" && entity == "LINE") {
      DxfLine& l = d.lines.back();
      switch (code) {
        case 8: l.layer = value; break;
        case 10: l.x1 = parse_number(value); break;
        case 20: l.y1 = parse_number(value); break;
        case 30: l.z1 = parse_number(value); break;
        case 11: l.x2 = parse_number(value); break;
        case 21: l.y2 = parse_number(value); break;
        case 31: l.z2 = parse_number(value); break;
        default: ADD_FAILURE() << "unexpected group " << code << " in a LINE";
      }
    }
  }
  return d;
}

TEST(DxfWriter, EveryFlatBundledPatternAsLinesOnLetterLayers) {
  int written = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled")) {
    if (entry.path().extension() != ".fold") continue;
    const std::string path = entry.path().string();
    SCOPED_TRACE(path);
    const CreasePattern p = read_fold(path);
    if (!p.coords_2d) {
      EXPECT_THROW(write_dxf_string(p, path), InputError);  // the tube: no flat crease pattern
      continue;
    }
    const ParsedDxf d = parse(write_dxf_string(p, path));
    EXPECT_EQ(d.version, "AC1009");
    EXPECT_EQ(d.layer_colour, (std::map<std::string, int>{{"B", 7}, {"M", 1}, {"V", 5}, {"F", 2}, {"U", 6}, {"C", 3}}));
    ASSERT_EQ(static_cast<int>(d.lines.size()), p.num_edges());
    // Every LINE is an edge of the pattern, bit for bit, on its letter's layer.
    std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, char> edge_letter;
    for (int e = 0; e < p.num_edges(); ++e) {
      const Eigen::Vector3d a = to_file_units(p, p.vertices[p.edges[e][0]]), b = to_file_units(p, p.vertices[p.edges[e][1]]);
      edge_letter[{{a.x(), a.y()}, {b.x(), b.y()}}] = assignment_letter(p.assignments[e]);
    }
    std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> seen;
    for (const auto& l : d.lines) {
      EXPECT_EQ(l.z1, 0.0);
      EXPECT_EQ(l.z2, 0.0);
      const auto key = std::make_pair(std::make_pair(l.x1, l.y1), std::make_pair(l.x2, l.y2));
      const auto it = edge_letter.find(key);
      ASSERT_NE(it, edge_letter.end()) << "LINE (" << l.x1 << ", " << l.y1 << ") - (" << l.x2 << ", " << l.y2 << ") is no edge";
      EXPECT_EQ(l.layer, std::string(1, it->second));
      EXPECT_TRUE(seen.insert(key).second) << "edge written twice";
    }
    ++written;
  }
  EXPECT_EQ(written, 12);
}

TEST(DxfWriter, RefusesAJoin) {
  CreasePattern p;
  p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}};
  p.assignments = {Assignment::Boundary, Assignment::Boundary, Assignment::Boundary, Assignment::Boundary, Assignment::Join};
  p.fold_angles.assign(5, std::nullopt);
  try {
    write_dxf_string(p, "P.fold");
    FAIL() << "a join was written";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "P.fold: edges_assignment[4]: J (join) has no layer in the DXF letter table");
  }
}

}}  // namespace
}  // namespace rigidfold
