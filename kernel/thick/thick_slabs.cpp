#include "kernel/thick/thick_slabs.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace rigidfold {

namespace {

// Edge index of each unordered vertex pair of the flat pattern.
std::map<std::pair<int, int>, int> edge_index(const CreasePattern& flat) {
  std::map<std::pair<int, int>, int> out;
  for (int e = 0; e < flat.num_edges(); ++e)
    out[{std::min(flat.edges[e][0], flat.edges[e][1]), std::max(flat.edges[e][0], flat.edges[e][1])}] = e;
  return out;
}

}  // namespace

std::vector<PanelSlab> panel_slabs(const CreasePattern& flat, const Topology& topology, const ThickReport& report) {
  std::vector<PanelSlab> slabs(flat.num_faces());
  const double t = report.thickness;
  if (report.hinges != ThickHinges::kBennett) {
    for (PanelSlab& s : slabs) s = {0.0, t};
    return slabs;
  }
  const auto edges = edge_index(flat);
  for (int f = 0; f < flat.num_faces(); ++f) {
    const auto& face = flat.faces[f];
    double lo = 0, hi = 0;
    bool any = false;
    for (std::size_t j = 0; j < face.size(); ++j) {
      const int a = face[j], b = face[(j + 1) % face.size()];
      const auto it = edges.find({std::min(a, b), std::max(a, b)});
      if (it == edges.end()) throw std::invalid_argument("panel slabs: a side of face " + std::to_string(f) + " is not an edge");
      if (!topology.edge_is_hinge[it->second]) continue;
      const double h = report.edge_heights[it->second];
      lo = any ? std::min(lo, h) : h;
      hi = any ? std::max(hi, h) : h;
      any = true;
    }
    slabs[f] = hi > lo ? PanelSlab{lo, hi} : PanelSlab{lo, lo + t};
  }
  return slabs;
}

FoldedGeometry place_thick_sheet(const ThickReport& report, const Eigen::VectorXd& fold_angles) {
  const ThickHeightSheet& sheet = report.sheet;
  return place_faces(sheet.pattern, sheet.topology, sheet.sheet_edge_angles(fold_angles), sheet.reference_edge_angles);
}

std::vector<std::vector<Eigen::Vector3d>> slab_polygons(const CreasePattern& flat, const ThickReport& report,
                                                        const std::vector<PanelSlab>& slabs, const FoldedGeometry& placed) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  const ThickHeightSheet& sheet = report.sheet;
  for (int s = 0; s < static_cast<int>(sheet.flat_face_of_face.size()); ++s) {
    const int f = sheet.flat_face_of_face[s];
    std::vector<int> face = flat.faces[f];
    double area2 = 0;  // twice the signed area seen from +z
    for (std::size_t j = 0; j < face.size(); ++j) {
      const Eigen::Vector3d& a = flat.vertices[face[j]];
      const Eigen::Vector3d& b = flat.vertices[face[(j + 1) % face.size()]];
      area2 += a.x() * b.y() - a.y() * b.x();
    }
    if (area2 < 0) std::reverse(face.begin(), face.end());
    const Eigen::Isometry3d& motion = placed.face_motions[s];
    auto at = [&](int v, double z) {
      const Eigen::Vector3d& p = flat.vertices[v];
      return Eigen::Vector3d(motion * Eigen::Vector3d(p.x(), p.y(), z));
    };
    const double lo = slabs[f].bottom, hi = slabs[f].top;
    std::vector<Eigen::Vector3d> top, bottom;
    for (int v : face) top.push_back(at(v, hi));
    for (auto it = face.rbegin(); it != face.rend(); ++it) bottom.push_back(at(*it, lo));
    out.push_back(top);
    out.push_back(bottom);
    for (std::size_t j = 0; j < face.size(); ++j) {
      const int a = face[j], b = face[(j + 1) % face.size()];
      out.push_back({at(a, lo), at(b, lo), at(b, hi), at(a, hi)});
    }
  }
  return out;
}

}  // namespace rigidfold
