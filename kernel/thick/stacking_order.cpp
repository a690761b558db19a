#include "kernel/thick/stacking_order.hpp"
#include "kernel/math/cross2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/folded_output.hpp"

namespace rigidfold {

namespace {

using Poly = std::vector<Eigen::Vector2d>;


double signed_area(const Poly& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) a += cross2(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a;
}

// Sutherland-Hodgman: the part of polygon `subject` inside the convex, counter-clockwise `clip`.
Poly clip_convex(Poly subject, const Poly& clip) {
  for (std::size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
    const Eigen::Vector2d a = clip[i], b = clip[(i + 1) % clip.size()];
    auto side = [&](const Eigen::Vector2d& x) { return cross2(b - a, x - a); };
    Poly out;
    for (std::size_t j = 0; j < subject.size(); ++j) {
      const Eigen::Vector2d p = subject[j], q = subject[(j + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + (sp / (sp - sq)) * (q - p));
    }
    subject = std::move(out);
  }
  return subject;
}

}  // namespace

StackingOrder stacking_order(const CreasePattern& flat, const Topology& topology, const ThickHeightSheet& sheet,
                             const std::vector<PanelSlab>& slabs, const Eigen::VectorXd& fold_angles) {
  const int nf = flat.num_faces();
  if (static_cast<int>(slabs.size()) != nf) throw std::invalid_argument("stacking order: one slab per face needed");
  if (fold_angles.size() != flat.num_edges()) throw std::invalid_argument("stacking order: one fold angle per edge needed");
  std::vector<int> sheet_face(nf, -1);
  for (int s = 0; s < static_cast<int>(sheet.flat_face_of_face.size()); ++s) {
    const int f = sheet.flat_face_of_face[s];
    if (f >= 0 && f < nf && sheet_face[f] < 0) sheet_face[f] = s;
  }
  const FoldedGeometry placed =
      place_faces(sheet.pattern, sheet.topology, sheet.sheet_edge_angles(fold_angles), sheet.reference_edge_angles);

  // Each slab's centre and top normal, folded.
  std::vector<Eigen::Isometry3d> pose(nf);
  std::vector<Eigen::Vector3d> centre(nf), normal(nf);
  for (int f = 0; f < nf; ++f) {
    if (sheet_face[f] < 0) throw std::invalid_argument("stacking order: face " + std::to_string(f) + " has no face in the sheet");
    pose[f] = placed.face_motions[sheet_face[f]];
    Eigen::Vector2d c = Eigen::Vector2d::Zero();
    for (int v : flat.faces[f]) c += flat.vertices[v].head<2>();
    c /= static_cast<double>(flat.faces[f].size());
    centre[f] = pose[f] * Eigen::Vector3d(c.x(), c.y(), 0.5 * (slabs[f].bottom + slabs[f].top));
    normal[f] = pose[f].linear() * Eigen::Vector3d::UnitZ();
  }

  Eigen::Vector3d lo = flat.vertices.empty() ? Eigen::Vector3d::Zero() : flat.vertices[0], hi = lo;
  for (const Eigen::Vector3d& v : flat.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double size = (hi - lo).norm();
  auto side = [&](double height) { return height > 1e-9 * size ? 1 : (height < -1e-9 * size ? -1 : 0); };

  StackingOrder out;
  for (int e = 0; e < flat.num_edges(); ++e) {
    if (!topology.edge_is_hinge[e]) continue;
    CreaseStacking c;
    c.edge = e;
    c.face_a = topology.edge_faces[e][0];
    c.face_b = topology.edge_faces[e][1];
    c.b_side_of_a = side((centre[c.face_b] - centre[c.face_a]).dot(normal[c.face_a]));
    c.a_side_of_b = side((centre[c.face_a] - centre[c.face_b]).dot(normal[c.face_b]));
    const Assignment letter = flat.assignments[e];
    c.has_letter = letter == Assignment::Valley || letter == Assignment::Mountain;
    if (c.has_letter) {
      const int want = letter == Assignment::Valley ? 1 : -1;
      c.agrees_with_letter = c.b_side_of_a == want && c.a_side_of_b == want;
      if (!c.agrees_with_letter) ++out.letter_disagreements;
    }
    out.creases.push_back(c);
  }

  if (nf == 0) return out;
  out.normal = normal[0];
  bool turned = false;
  for (int f = 0; f < nf; ++f) {
    out.max_tilt = std::max(out.max_tilt, std::acos(std::min(1.0, std::abs(normal[f].dot(out.normal)))));
    turned = turned || normal[f].dot(out.normal) < 0;
  }
  out.flat_folded = out.max_tilt <= 1e-6 && turned;
  if (!out.flat_folded) return out;

  // Footprints seen along n, as triangles (the faces' own ear clipping), counter-clockwise.
  const Eigen::Vector3d n = out.normal;
  const Eigen::Vector3d u = n.unitOrthogonal(), w = n.cross(u);
  auto seen = [&](int f, int v) {
    const Eigen::Vector3d x = pose[f] * Eigen::Vector3d(flat.vertices[v].x(), flat.vertices[v].y(), slabs[f].bottom);
    return Eigen::Vector2d(x.dot(u), x.dot(w));
  };
  std::vector<std::vector<Poly>> triangles(nf);
  for (int f = 0; f < nf; ++f) {
    for (const std::array<int, 3>& t : triangulate_face(flat, flat.faces[f])) {
      Poly p{seen(f, t[0]), seen(f, t[1]), seen(f, t[2])};
      if (signed_area(p) < 0) std::swap(p[1], p[2]);
      triangles[f].push_back(p);
    }
    StackedPanel s;
    s.face = f;
    const double mid = centre[f].dot(n), half = 0.5 * (slabs[f].top - slabs[f].bottom);
    s.low = mid - half;
    s.high = mid + half;
    out.panels.push_back(s);
  }
  std::sort(out.panels.begin(), out.panels.end(), [](const StackedPanel& a, const StackedPanel& b) {
    return a.low + a.high < b.low + b.high || (a.low + a.high == b.low + b.high && a.face < b.face);
  });
  for (int i = 0; i < nf; ++i)
    for (int j = i + 1; j < nf; ++j) {
      const int a = out.panels[i].face, b = out.panels[j].face;
      double area = 0;
      for (const Poly& ta : triangles[a])
        for (const Poly& tb : triangles[b]) {
          const Poly common = clip_convex(ta, tb);
          if (common.size() >= 3) area += std::abs(signed_area(common));
        }
      if (!(area > 1e-9 * size * size)) continue;
      StackedPair pair;
      pair.lower = a;
      pair.upper = b;
      pair.gap = out.panels[j].low - out.panels[i].high;
      pair.overlap_area = area;
      out.overlaps.push_back(pair);
    }
  // Layers: longest chain below, in height order (pairs are listed lower first).
  std::vector<int> layer(nf, 0);
  for (int i = 0; i < nf; ++i) {
    const int b = out.panels[i].face;
    for (const StackedPair& p : out.overlaps)
      if (p.upper == b) layer[b] = std::max(layer[b], layer[p.lower] + 1);
  }
  for (StackedPanel& s : out.panels) {
    s.layer = layer[s.face];
    out.layers = std::max(out.layers, s.layer + 1);
  }
  out.min_gap = 0.0;
  for (std::size_t k = 0; k < out.overlaps.size(); ++k)
    out.min_gap = k == 0 ? out.overlaps[k].gap : std::min(out.min_gap, out.overlaps[k].gap);
  return out;
}

}  // namespace rigidfold
