#include "data/generators/resch_triangle.hpp"

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "data/generators/generator_common.hpp"
#include "kernel/math/number_text.hpp"

namespace rigidfold::generators {
namespace {

// A point of the pattern in thirds of grid coordinates: grid vertex (i, j) is (3i, 3j), the
// centroid of the down triangle (i+1, j), (i+1, j+1), (i, j+1) is (3i + 2, 3j + 2). Exact, so
// that faces meeting at a point share its vertex.
using Thirds = std::pair<long, long>;

struct Builder {
  const ReschTriangleParams& params;
  std::map<Thirds, int> vertex_of;
  CreasePattern pattern;

  Eigen::Vector3d position(const Thirds& q) const {
    const double i = q.first / 3.0, j = q.second / 3.0;
    return Eigen::Vector3d(params.side * (i + 0.5 * j), params.side * j * std::sqrt(3.0) / 2, 0.0);
  }

  bool inside(const std::array<Thirds, 3>& face) const {
    const Eigen::Vector3d c = (position(face[0]) + position(face[1]) + position(face[2])) / 3.0;
    return c.x() >= 0 && c.x() <= params.cols * params.side && c.y() >= 0 &&
           c.y() <= params.rows * params.side * std::sqrt(3.0) / 2;
  }

  int vertex(const Thirds& q) {
    auto [it, added] = vertex_of.emplace(q, static_cast<int>(pattern.vertices.size()));
    if (added) pattern.vertices.push_back(position(q));
    return it->second;
  }

  // Counter-clockwise whatever the order given.
  void add_face(std::array<Thirds, 3> face) {
    if (!inside(face)) return;
    const Eigen::Vector3d a = position(face[0]), b = position(face[1]), c = position(face[2]);
    if ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x() < 0) std::swap(face[1], face[2]);
    pattern.faces.push_back({vertex(face[0]), vertex(face[1]), vertex(face[2])});
  }
};

}  // namespace

CreasePattern resch_triangle(const ReschTriangleParams& params) {
  require(params.rows >= 1 && params.rows <= 400, "rows", "must be between 1 and 400, got " + std::to_string(params.rows));
  require(params.cols >= 1 && params.cols <= 400, "cols", "must be between 1 and 400, got " + std::to_string(params.cols));
  require(std::isfinite(params.side) && params.side > 0, "side", "the grid triangle side must be positive and finite");
  Builder b{params, {}, {}};
  b.pattern.coords_2d = true;
  // Each crease's letter by its end points: spokes M, centroid-to-apex V, grid edges M.
  std::map<std::pair<Thirds, Thirds>, Assignment> letter;
  auto set_letter = [&](Thirds u, Thirds v, Assignment a) { letter[{std::min(u, v), std::max(u, v)}] = a; };
  for (long j = -2; j <= params.rows + 2; ++j)
    for (long i = -params.rows / 2 - 3; i <= params.cols + 2; ++i) {
      const std::array<Thirds, 3> down{Thirds{3 * (i + 1), 3 * j}, Thirds{3 * (i + 1), 3 * (j + 1)}, Thirds{3 * i, 3 * (j + 1)}};
      if (((i - j) % 3 + 3) % 3 != 0) {
        b.add_face(down);
        continue;
      }
      const Thirds c{3 * i + 2, 3 * j + 2};
      for (int k = 0; k < 3; ++k) {
        const Thirds va = down[k], vb = down[(k + 1) % 3], opposite = down[(k + 2) % 3];
        const Thirds apex{va.first + vb.first - opposite.first, va.second + vb.second - opposite.second};
        b.add_face({c, va, apex});
        b.add_face({c, apex, vb});
        set_letter(c, va, Assignment::Mountain);
        set_letter(c, apex, Assignment::Valley);
      }
    }
  // Edges from the faces: shared by two faces a crease, else boundary.
  std::vector<Thirds> thirds_of(b.pattern.vertices.size());
  for (const auto& [q, v] : b.vertex_of) thirds_of[v] = q;
  std::map<std::pair<int, int>, int> faces_on;
  for (const std::vector<int>& f : b.pattern.faces)
    for (std::size_t k = 0; k < f.size(); ++k) ++faces_on[{std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])}];
  for (const auto& [edge, count] : faces_on) {
    b.pattern.edges.push_back({edge.first, edge.second});
    Assignment a = Assignment::Boundary;
    if (count == 2) {
      const Thirds u = thirds_of[edge.first], v = thirds_of[edge.second];
      const auto it = letter.find({std::min(u, v), std::max(u, v)});
      a = it == letter.end() ? Assignment::Mountain : it->second;
    }
    b.pattern.assignments.push_back(a);
  }
  require(!b.pattern.faces.empty(), "rows", "the rectangle holds no face");

  nlohmann::ordered_json g;
  g["kind"] = "resch_triangle";
  g["rows"] = params.rows;
  g["cols"] = params.cols;
  g["side"] = params.side;
  return finish_pattern(std::move(b.pattern), "Resch triangle tessellation",
                        "Resch triangle tessellation, " + std::to_string(params.rows) + " rows x " +
                            std::to_string(params.cols) + " grid edges, side " + short_text(params.side),
                        g);
}

}  // namespace rigidfold::generators
