#include "kernel/pattern/dxf_writer.hpp"

#include <charconv>

#include "kernel/geometry/flat_development.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"

namespace rigidfold {
namespace {

std::string number(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x + 0.0);  // shortest round trip; no -0
  return std::string(buf, r.ptr);
}

// One group: its code and value, each on its own line.
void group(std::string& s, int code, const std::string& value) {
  s += std::to_string(code);
  s += '\n';
  s += value;
  s += '\n';
}

constexpr Assignment kLayers[] = {Assignment::Boundary, Assignment::Mountain, Assignment::Valley,
                                  Assignment::Flat,     Assignment::Unassigned, Assignment::Cut};

}  // namespace

int dxf_layer_colour(Assignment a) {
  switch (a) {
    case Assignment::Boundary: return 7;
    case Assignment::Mountain: return 1;
    case Assignment::Valley: return 5;
    case Assignment::Flat: return 2;
    case Assignment::Unassigned: return 6;
    case Assignment::Cut: return 3;
    case Assignment::Join: return 0;
  }
  return 0;
}

std::string write_dxf_string(const CreasePattern& input, const std::string& source) {
  if (input.edges.empty()) throw InputError(source, "no edges to draw");
  for (int e = 0; e < input.num_edges(); ++e)
    if (input.assignments[e] == Assignment::Join)
      throw InputError(source + ": edges_assignment[" + std::to_string(e) + "]", "J (join) has no layer in the DXF letter table");
  const FlatDevelopment dev = flat_development(input, source);
  const CreasePattern& p = dev.pattern;

  std::string s;
  s.reserve(600 + 90 * p.edges.size());
  group(s, 0, "SECTION");
  group(s, 2, "HEADER");
  group(s, 9, "$ACADVER");
  group(s, 1, "AC1009");
  group(s, 0, "ENDSEC");
  group(s, 0, "SECTION");
  group(s, 2, "TABLES");
  group(s, 0, "TABLE");
  group(s, 2, "LAYER");
  group(s, 70, std::to_string(std::size(kLayers)));
  for (Assignment a : kLayers) {
    group(s, 0, "LAYER");
    group(s, 2, std::string(1, assignment_letter(a)));
    group(s, 70, "0");
    group(s, 62, std::to_string(dxf_layer_colour(a)));
    group(s, 6, "CONTINUOUS");
  }
  group(s, 0, "ENDTAB");
  group(s, 0, "ENDSEC");
  group(s, 0, "SECTION");
  group(s, 2, "ENTITIES");
  for (int e = 0; e < p.num_edges(); ++e) {
    const Eigen::Vector3d a = to_file_units(p, p.vertices[p.edges[e][0]]), b = to_file_units(p, p.vertices[p.edges[e][1]]);
    group(s, 0, "LINE");
    group(s, 8, std::string(1, assignment_letter(p.assignments[e])));
    group(s, 10, number(a.x()));
    group(s, 20, number(a.y()));
    group(s, 30, "0");
    group(s, 11, number(b.x()));
    group(s, 21, number(b.y()));
    group(s, 31, "0");
  }
  group(s, 0, "ENDSEC");
  group(s, 0, "EOF");
  return s;
}

}  // namespace rigidfold
