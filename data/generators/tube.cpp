#include "data/generators/tube.hpp"

#include <cmath>
#include <numbers>

#include "data/generators/generator_common.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/pattern/validate_pattern.hpp"

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
  p.coords_2d = false;
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
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  p.extra["file_spec"] = 1.1;
  p.extra["file_creator"] = "rigidfold generate";
  p.extra["file_title"] = "prism tube";
  p.extra["file_classes"] = nlohmann::ordered_json::array({"singleModel"});
  p.extra["frame_title"] = std::to_string(n) + "-panel prism tube";
  p.extra["frame_classes"] = nlohmann::ordered_json::array({"foldedForm"});
  p.extra["frame_attributes"] = nlohmann::ordered_json::array({"3D"});
  p.extra["rigidfold:generator"] = {{"type", "prism_tube"}, {"panels", n}, {"height", params.height},
                                    {"layers", L}, {"top_scale", params.top_scale}};
  complete_and_validate(p, "prism tube");
  const Eigen::VectorXd rho = reference_fold_angles(p, build_topology(p, "prism tube"));
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.assignments[e] == Assignment::Boundary) continue;
    p.assignments[e] = rho[e] >= 0 ? Assignment::Valley : Assignment::Mountain;
    p.fold_angles[e] = rho[e];
  }
  return p;
}

}  // namespace rigidfold::generators
