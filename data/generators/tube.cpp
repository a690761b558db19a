#include "data/generators/tube.hpp"

#include <cmath>
#include <numbers>

#include "data/generators/generator_common.hpp"

namespace rigidfold::generators {

std::vector<Eigen::Vector2d> regular_polygon(int n, double r, double phase) {
  std::vector<Eigen::Vector2d> out;
  for (int k = 0; k < n; ++k) {
    const double t = phase + 2 * std::numbers::pi * k / n;
    out.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return out;
}

CreasePattern prism_tube(const TubeParams& params) {
  const int n = static_cast<int>(params.section.size());
  require(n >= 3, "section", "needs at least 3 points");
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = params.section[k], b = params.section[(k + 1) % n], c = params.section[(k + 2) % n];
    require((b - a).x() * (c - b).y() - (b - a).y() * (c - b).x() > 0, "section",
            "must be a convex polygon, counter-clockwise");
  }
  require(std::isfinite(params.height) && params.height > 0, "height", "must be positive");
  require(params.layers >= 1, "layers", "must be at least 1");
  require(std::isfinite(params.top_scale) && params.top_scale > 0, "top_scale", "must be positive");
  const int L = params.layers;
  CreasePattern p;
  for (int l = 0; l <= L; ++l) {
    const double s = 1.0 + (params.top_scale - 1.0) * l / L;
    for (int k = 0; k < n; ++k)
      p.vertices.emplace_back(s * params.section[k].x(), s * params.section[k].y(), params.height * l / L);
  }
  auto vid = [&](int k, int l) { return l * n + (k % n); };
  for (int l = 0; l < L; ++l)
    for (int k = 0; k < n; ++k) {
      p.edges.push_back({vid(k, l), vid(k, l + 1)});
      p.assignments.push_back(Assignment::Unassigned);
    }
  for (int l = 0; l <= L; ++l)
    for (int k = 0; k < n; ++k) {
      p.edges.push_back({vid(k, l), vid(k + 1, l)});
      p.assignments.push_back(l == 0 || l == L ? Assignment::Boundary : Assignment::Unassigned);
    }
  for (int l = 0; l < L; ++l)
    for (int k = 0; k < n; ++k) p.faces.push_back({vid(k, l), vid(k + 1, l), vid(k + 1, l + 1), vid(k, l + 1)});
  return finish_folded_pattern(std::move(p), "prism tube", std::to_string(n) + "-panel prism tube",
                               {{"type", "prism_tube"}, {"panels", n}, {"height", params.height}, {"layers", L},
                                {"top_scale", params.top_scale}});
}

}  // namespace rigidfold::generators
