#include "data/generators/waterbomb_tessellation.hpp"

#include <string>
#include <vector>

#include "data/generators/generator_common.hpp"

namespace rigidfold::generators {

CreasePattern waterbomb_tessellation(const WaterbombTessellationParams& params) {
  require(params.rows >= 1 && params.rows <= 2000, "rows", "must be between 1 and 2000, got " + std::to_string(params.rows));
  require(params.cols >= 1 && params.cols <= 2000, "cols", "must be between 1 and 2000, got " + std::to_string(params.cols));
  const int nr = params.rows, nc = params.cols;
  auto vertex = [&](int k, int j) { return j * (nc + 1) + k; };
  CreasePattern p;
  p.coords_2d = true;
  for (int j = 0; j <= nr; ++j)
    for (int k = 0; k <= nc; ++k) p.vertices.emplace_back(2.0 * k + (j % 2), static_cast<double>(j), 0.0);
  // Horizontal segments: boundary on the first and last row.
  for (int j = 0; j <= nr; ++j)
    for (int k = 0; k < nc; ++k) {
      p.edges.push_back({vertex(k, j), vertex(k + 1, j)});
      p.assignments.push_back(j == 0 || j == nr ? Assignment::Boundary : Assignment::Mountain);
    }
  // Strip between rows j and j+1: merge both rows by x; consecutive merged nodes are joined
  // by a diagonal, and three consecutive ones form a triangle. The first and last diagonals
  // of a strip lie on the zig-zag side boundary.
  for (int j = 0; j < nr; ++j) {
    std::vector<int> merged;
    const bool lower_first = j % 2 == 0;  // the row with offset 0 starts further left
    for (int k = 0; k <= nc; ++k) {
      merged.push_back(lower_first ? vertex(k, j) : vertex(k, j + 1));
      merged.push_back(lower_first ? vertex(k, j + 1) : vertex(k, j));
    }
    const int count = static_cast<int>(merged.size());
    for (int s = 0; s + 1 < count; ++s) {
      p.edges.push_back({merged[s], merged[s + 1]});
      p.assignments.push_back(s == 0 || s + 2 == count ? Assignment::Boundary : Assignment::Valley);
    }
    for (int s = 0; s + 2 < count; ++s) {
      const int a = merged[s], b = merged[s + 1], c = merged[s + 2];
      // Counter-clockwise: the apex b lies above the base a-c when b is in the upper row.
      const bool b_up = p.vertices[b].y() > p.vertices[a].y();
      p.faces.push_back(b_up ? std::vector<int>{a, c, b} : std::vector<int>{a, b, c});
    }
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  nlohmann::ordered_json g;
  g["kind"] = "waterbomb_tessellation";
  g["rows"] = nr;
  g["cols"] = nc;
  return finish_pattern(std::move(p), "Waterbomb tessellation " + std::to_string(nr) + "x" + std::to_string(nc),
                        "degree-6 waterbomb vertices; horizontal M, diagonals V; multi-DOF", g);
}

}  // namespace rigidfold::generators
