#include "kernel/thick/hinge_heights.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "kernel/closure/hole_closure.hpp"
#include "kernel/geometry/fold_angles.hpp"

namespace rigidfold {

double hinge_height(double panel_bottom, double panel_thickness, HingePlacement placement) {
  switch (placement) {
    case HingePlacement::kTop: return panel_bottom + panel_thickness;
    case HingePlacement::kBottom: return panel_bottom;
    case HingePlacement::kMid: return panel_bottom + 0.5 * panel_thickness;
  }
  throw std::invalid_argument("hinge_height: unknown placement");
}

Eigen::VectorXd ThickHeightSheet::sheet_edge_angles(const Eigen::VectorXd& fold_angles) const {
  Eigen::VectorXd edges = reference_edge_angles;
  edges.head(fold_angles.size()) += fold_angles;
  return edges;
}

Eigen::VectorXd ThickHeightSheet::fold_angles(const Eigen::VectorXd& sheet_edges) const {
  const Eigen::Index flat_edges = static_cast<Eigen::Index>(sheet_edges.size()) - static_cast<Eigen::Index>(num_cut_edges);
  return sheet_edges.head(flat_edges) - reference_edge_angles.head(flat_edges);
}

ThickHeightSheet thick_sheet_from_hinge_heights(const CreasePattern& flat, const Topology& topology,
                                                const std::vector<double>& heights, double truncation) {
  if (static_cast<int>(heights.size()) != flat.num_edges())
    throw std::invalid_argument("thick sheet: expected one height per edge (" + std::to_string(flat.num_edges()) + "), got " +
                                std::to_string(heights.size()));
  if (!(truncation > 0 && truncation < 0.5)) throw std::invalid_argument("thick sheet: truncation must lie in (0, 0.5)");
  for (int e = 0; e < flat.num_edges(); ++e)
    if (!std::isfinite(heights[e])) throw std::invalid_argument("thick sheet: height of edge " + std::to_string(e) + " is not finite");

  ThickHeightSheet sheet;
  CreasePattern& p = sheet.pattern;
  p.coords_2d = false;
  p.length_exponent = flat.length_exponent;
  // Cut point of edge e near its end vertex v: on the hinge line at the edge's height.
  std::map<std::pair<int, int>, int> cut_point;  // (vertex, edge) -> new vertex
  auto point = [&](int v, int e) {
    const auto key = std::make_pair(v, e);
    if (auto it = cut_point.find(key); it != cut_point.end()) return it->second;
    const int w = flat.edges[e][0] == v ? flat.edges[e][1] : flat.edges[e][0];
    Eigen::Vector3d x = flat.vertices[v] + truncation * (flat.vertices[w] - flat.vertices[v]);
    x.z() = heights[e];
    p.vertices.push_back(x);
    return cut_point[key] = p.num_vertices() - 1;
  };
  for (int e = 0; e < flat.num_edges(); ++e) {
    p.edges.push_back({point(flat.edges[e][0], e), point(flat.edges[e][1], e)});
    p.assignments.push_back(flat.assignments[e]);
  }
  std::map<std::pair<int, int>, int> edge_of_pair;
  for (int e = 0; e < flat.num_edges(); ++e)
    edge_of_pair[{std::min(flat.edges[e][0], flat.edges[e][1]), std::max(flat.edges[e][0], flat.edges[e][1])}] = e;
  auto flat_edge = [&](int a, int b) {
    auto it = edge_of_pair.find({std::min(a, b), std::max(a, b)});
    if (it == edge_of_pair.end()) throw std::invalid_argument("thick sheet: a face side is not an edge");
    return it->second;
  };
  // find_hole_loops takes the first boundary side met (in face order) to be on a component's
  // outer boundary and closes every other boundary loop. So the face that leads is one with
  // a side on the flat pattern's boundary, its polygon starting with that side; otherwise
  // the cut edges of a truncated vertex would come first and that vertex would get no loop
  // of its own (the outer loop would stand in for it).
  int lead_face = 0, lead_side = 0;
  bool found = false;
  for (int f = 0; f < flat.num_faces() && !found; ++f)
    for (int j = 0; j < static_cast<int>(flat.faces[f].size()) && !found; ++j) {
      const auto& face = flat.faces[f];
      if (!topology.edge_is_hinge[flat_edge(face[j], face[(j + 1) % face.size()])]) {
        lead_face = f;
        lead_side = j;
        found = true;
      }
    }
  std::vector<int> order{lead_face};
  for (int f = 0; f < flat.num_faces(); ++f)
    if (f != lead_face) order.push_back(f);
  for (int f : order) {
    const auto& face = flat.faces[f];
    const int k = static_cast<int>(face.size());
    const int first = f == lead_face ? lead_side : 0;
    std::vector<int> polygon;
    for (int step = 0; step < k; ++step) {
      const int j = (first + step) % k;
      const int a = face[j], b = face[(j + 1) % k];
      const int e = flat_edge(a, b);
      polygon.push_back(point(a, e));
      polygon.push_back(point(b, e));
      // Cut edge at corner b, from this side's end to the next side's start.
      const int next = flat_edge(b, face[(j + 2) % k]);
      p.edges.push_back({point(b, e), point(b, next)});
      p.assignments.push_back(Assignment::Boundary);
    }
    p.faces.push_back(polygon);
    sheet.flat_face_of_face.push_back(f);
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  sheet.topology = build_topology(p, "thick sheet");
  sheet.options.close_holes = true;
  sheet.reference_edge_angles = reference_fold_angles(p, sheet.topology);
  sheet.num_cut_edges = p.num_edges() - flat.num_edges();
  // Which flat vertex each hole surrounds: the one vertex that every crease its loop crosses
  // shares (edges 0 .. E-1 of the sheet are the flat pattern's edges).
  for (const HoleLoop& loop : find_hole_loops(p, sheet.topology)) {
    std::map<int, int> count;
    for (const HoleStep& step : loop.steps)
      for (int v : flat.edges[step.edge]) ++count[v];
    int vertex = -1;
    for (const auto& [v, c] : count)
      if (c == static_cast<int>(loop.steps.size())) vertex = v;
    sheet.vertex_of_hole.push_back(vertex);
  }
  return sheet;
}

}  // namespace rigidfold
