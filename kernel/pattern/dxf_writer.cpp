#include "kernel/pattern/dxf_writer.hpp"

#include "kernel/geometry/flat_development.hpp"
#include "kernel/pattern/dxf_document.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"

namespace rigidfold {
namespace {

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

  DxfDocument doc;
  for (Assignment a : kLayers) doc.add_layer(std::string(1, assignment_letter(a)), dxf_layer_colour(a));
  for (int e = 0; e < p.num_edges(); ++e) {
    const Eigen::Vector3d a = to_file_units(p, p.vertices[p.edges[e][0]]), b = to_file_units(p, p.vertices[p.edges[e][1]]);
    doc.line(std::string(1, assignment_letter(p.assignments[e])), a.head<2>(), b.head<2>());
  }
  return doc.text();
}

}  // namespace rigidfold
