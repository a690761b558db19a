#include "kernel/pattern/pattern_components.hpp"

namespace rigidfold {

std::vector<PatternComponent> split_components(const CreasePattern& pattern, const Topology& topology) {
  const int count = static_cast<int>(topology.components.size());
  std::vector<PatternComponent> out(count);
  // Local index of each whole vertex in each piece (-1: not in it), filled face by face.
  std::vector<std::vector<int>> local_vertex(count, std::vector<int>(pattern.num_vertices(), -1));
  for (int f = 0; f < pattern.num_faces(); ++f) {
    const int c = topology.face_component[f];
    PatternComponent& piece = out[c];
    std::vector<int> face;
    for (int v : pattern.faces[f]) {
      int& local = local_vertex[c][v];
      if (local < 0) {
        local = static_cast<int>(piece.vertex_of.size());
        piece.vertex_of.push_back(v);
        piece.pattern.vertices.push_back(pattern.vertices[v]);
      }
      face.push_back(local);
    }
    piece.pattern.faces.push_back(std::move(face));
    piece.face_of.push_back(f);
  }
  for (int e = 0; e < pattern.num_edges(); ++e) {
    const std::array<int, 2>& faces = topology.edge_faces[e];
    const int f = faces[0] >= 0 ? faces[0] : faces[1];
    if (f < 0) continue;
    const int c = topology.face_component[f];
    PatternComponent& piece = out[c];
    piece.pattern.edges.push_back({local_vertex[c][pattern.edges[e][0]], local_vertex[c][pattern.edges[e][1]]});
    piece.pattern.assignments.push_back(pattern.assignments[e]);
    piece.pattern.fold_angles.push_back(e < static_cast<int>(pattern.fold_angles.size()) ? pattern.fold_angles[e]
                                                                                        : std::nullopt);
    piece.edge_of.push_back(e);
  }
  for (PatternComponent& piece : out) {
    piece.pattern.length_exponent = pattern.length_exponent;
    piece.pattern.coords_2d = pattern.coords_2d;
    piece.pattern.faces_derived = pattern.faces_derived;
    piece.pattern.fold_angles_in_file = pattern.fold_angles_in_file;
  }
  return out;
}

}  // namespace rigidfold
