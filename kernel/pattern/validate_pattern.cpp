#include "kernel/pattern/validate_pattern.hpp"
#include "kernel/math/cross2.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace {

std::string at(const std::string& source, const std::string& path) { return source + ": " + path; }
std::string edge_path(int e) { return "edges_vertices[" + std::to_string(e) + "]"; }
std::string face_path(int f) { return "faces_vertices[" + std::to_string(f) + "]"; }

double pattern_size(const CreasePattern& p) {
  Eigen::Vector3d lo = p.vertices[0], hi = p.vertices[0];
  for (const auto& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double d = (hi - lo).norm();
  return d > 0 ? d : 1.0;
}

bool is_folded_form(const CreasePattern& p) {
  if (!p.extra.contains("frame_classes") || !p.extra["frame_classes"].is_array()) return false;
  for (const auto& c : p.extra["frame_classes"])
    if (c.is_string() && c.get<std::string>() == "foldedForm") return true;
  return false;
}

// 2D coordinates of a pattern that lies in one plane; throws if it does not.
std::vector<Eigen::Vector2d> planar_coordinates(const CreasePattern& p, const std::string& source) {
  std::vector<Eigen::Vector2d> xy(p.vertices.size());
  if (p.coords_2d) {
    for (std::size_t i = 0; i < xy.size(); ++i) xy[i] = p.vertices[i].head<2>();
    return xy;
  }
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& v : p.vertices) centroid += v;
  centroid /= static_cast<double>(p.vertices.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& v : p.vertices) cov += (v - centroid) * (v - centroid).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d normal = eig.eigenvectors().col(0);
  const Eigen::Vector3d u = eig.eigenvectors().col(2), w = normal.cross(u);
  const double tol = 1e-9 * pattern_size(p);
  for (std::size_t i = 0; i < xy.size(); ++i) {
    const Eigen::Vector3d d = p.vertices[i] - centroid;
    if (std::fabs(d.dot(normal)) > tol)
      throw InputError(at(source, "faces_vertices"),
                       "missing, and the 3D vertices do not lie in one plane (vertex " + std::to_string(i) + " is off it), so faces cannot be derived");
    xy[i] = Eigen::Vector2d(d.dot(u), d.dot(w));
  }
  return xy;
}


void check_edges(const CreasePattern& p, const std::string& source) {
  const double tol = 1e-12 * pattern_size(p);
  std::unordered_map<std::uint64_t, int> seen;
  seen.reserve(2 * p.edges.size());
  for (int e = 0; e < p.num_edges(); ++e) {
    const auto [a, b] = p.edges[e];
    if (a == b) throw InputError(at(source, edge_path(e)), "edge joins vertex " + std::to_string(a) + " to itself");
    auto [lo, hi] = std::minmax(a, b);
    const std::uint64_t key = (static_cast<std::uint64_t>(lo) << 32) | static_cast<std::uint32_t>(hi);
    auto [it, fresh] = seen.emplace(key, e);
    if (!fresh)
      throw InputError(at(source, edge_path(e)), "duplicate of edge " + std::to_string(it->second) + " (vertices " +
                                                     std::to_string(lo) + ", " + std::to_string(hi) + ")");
    if ((p.vertices[a] - p.vertices[b]).norm() <= tol)
      throw InputError(at(source, edge_path(e)), "zero-length edge (vertices " + std::to_string(a) + " and " +
                                                     std::to_string(b) + " coincide)");
  }
}

void check_face_cycles(const CreasePattern& p, const std::string& source) {
  const double size = pattern_size(p);
  for (int f = 0; f < p.num_faces(); ++f) {
    const auto& face = p.faces[f];
    if (face.size() < 3) throw InputError(at(source, face_path(f)), "a face needs at least 3 vertices, found " + std::to_string(face.size()));
    std::unordered_set<int> distinct(face.begin(), face.end());
    if (distinct.size() != face.size()) throw InputError(at(source, face_path(f)), "face visits a vertex twice (not a simple closed loop)");
    if (newell_normal(p, face).norm() <= 1e-14 * size * size)
      throw InputError(at(source, face_path(f)), "face has zero area");
  }
}

// 2D crease patterns: every face counter-clockwise seen from +z. A pattern given all
// clockwise is flipped whole; a mix means faces overlap or are inconsistently oriented.
void orient_planar_faces(CreasePattern& p, const std::string& source) {
  int positive = 0, negative = 0, first_negative = -1, first_positive = -1;
  for (int f = 0; f < p.num_faces(); ++f) {
    const double z = newell_normal(p, p.faces[f]).z();
    if (z > 0) {
      ++positive;
      if (first_positive < 0) first_positive = f;
    } else {
      ++negative;
      if (first_negative < 0) first_negative = f;
    }
  }
  if (negative == 0) return;
  if (positive == 0) {
    for (auto& face : p.faces) std::reverse(face.begin(), face.end());
    p.warnings.push_back(source + ": faces_vertices: all faces were clockwise; reversed to counter-clockwise");
    return;
  }
  const int odd = positive >= negative ? first_negative : first_positive;
  throw InputError(at(source, face_path(odd)),
                   "face is oriented opposite to face " + std::to_string(odd == first_negative ? first_positive : first_negative) +
                       " (faces not consistently oriented, or overlapping in the plane)");
}

// Crossing edges and vertices lying inside edges, in a 2D crease pattern. A uniform grid
// keeps this O(E) for evenly sized creases.
void check_planar_embedding(const CreasePattern& p, const std::vector<Eigen::Vector2d>& xy, const std::string& source) {
  const int ne = p.num_edges();
  Eigen::Vector2d lo = xy[0], hi = xy[0];
  for (const auto& v : xy) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Eigen::Vector2d ext = (hi - lo).cwiseMax(1e-300);
  const double size = ext.norm();
  const double tol = 1e-10 * size;
  const int cells_per_side = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(ne))), 1, 4096);
  const Eigen::Vector2d cell = ext / cells_per_side;
  auto cell_of = [&](const Eigen::Vector2d& x) {
    const int i = std::clamp(static_cast<int>((x.x() - lo.x()) / cell.x()), 0, cells_per_side - 1);
    const int j = std::clamp(static_cast<int>((x.y() - lo.y()) / cell.y()), 0, cells_per_side - 1);
    return std::pair<int, int>(i, j);
  };
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  std::vector<std::array<int, 4>> boxes(ne);
  for (int e = 0; e < ne; ++e) {
    const Eigen::Vector2d a = xy[p.edges[e][0]], b = xy[p.edges[e][1]];
    auto [i0, j0] = cell_of(a.cwiseMin(b) - Eigen::Vector2d::Constant(tol));
    auto [i1, j1] = cell_of(a.cwiseMax(b) + Eigen::Vector2d::Constant(tol));
    boxes[e] = {i0, j0, i1, j1};
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) grid[static_cast<std::int64_t>(i) * 8192 + j].push_back(e);
  }
  // Vertices lying in the interior of an edge (T-junctions, overlapping creases).
  for (int v = 0; v < p.num_vertices(); ++v) {
    auto [i, j] = cell_of(xy[v]);
    auto it = grid.find(static_cast<std::int64_t>(i) * 8192 + j);
    if (it == grid.end()) continue;
    for (int e : it->second) {
      const int a = p.edges[e][0], b = p.edges[e][1];
      if (v == a || v == b) continue;
      const Eigen::Vector2d d = xy[b] - xy[a];
      const double t = (xy[v] - xy[a]).dot(d) / d.squaredNorm();
      if (t <= 0 || t >= 1) continue;
      if ((xy[a] + t * d - xy[v]).norm() <= tol)
        throw InputError(at(source, edge_path(e)), "vertex " + std::to_string(v) + " lies on this edge (split the edge at that vertex)");
    }
  }
  for (const auto& [key, list] : grid) {
    const int ci = static_cast<int>(key / 8192), cj = static_cast<int>(key % 8192);
    for (std::size_t x = 0; x < list.size(); ++x)
      for (std::size_t y = x + 1; y < list.size(); ++y) {
        const int e = list[x], g = list[y];
        // Test each pair only in the first cell the two boxes share.
        if (std::max(boxes[e][0], boxes[g][0]) != ci || std::max(boxes[e][1], boxes[g][1]) != cj) continue;
        const int a = p.edges[e][0], b = p.edges[e][1], c = p.edges[g][0], d = p.edges[g][1];
        if (a == c || a == d || b == c || b == d) continue;
        const Eigen::Vector2d r = xy[b] - xy[a], s = xy[d] - xy[c];
        const double denom = cross2(r, s);
        const Eigen::Vector2d qp = xy[c] - xy[a];
        if (std::fabs(denom) <= 1e-15 * r.norm() * s.norm()) {
          // Parallel: overlapping collinear segments are caught by the vertex-on-edge test.
          continue;
        }
        const double t = cross2(qp, s) / denom, u = cross2(qp, r) / denom;
        const double eps = 1e-12;
        if (t > eps && t < 1 - eps && u > eps && u < 1 - eps) {
          const Eigen::Vector2d x = xy[a] + t * r;
          throw InputError(at(source, edge_path(e)), "crosses edge " + std::to_string(g) + " at (" + std::to_string(x.x()) +
                                                         ", " + std::to_string(x.y()) + ") (overlapping creases or faces)");
        }
      }
  }
}

}  // namespace

std::vector<std::vector<int>> derive_planar_faces(const CreasePattern& p, const std::string& source) {
  const auto xy = planar_coordinates(p, source);
  const int nv = p.num_vertices(), ne = p.num_edges();
  // Half-edge h = 2e (v0->v1) or 2e+1 (v1->v0). Outgoing half-edges sorted by angle.
  auto tail = [&](int h) { return p.edges[h / 2][h % 2]; };
  auto head = [&](int h) { return p.edges[h / 2][1 - h % 2]; };
  std::vector<std::vector<int>> out(nv);
  for (int h = 0; h < 2 * ne; ++h) out[tail(h)].push_back(h);
  std::vector<int> position(2 * ne);
  for (int v = 0; v < nv; ++v) {
    auto angle = [&](int h) {
      const Eigen::Vector2d d = xy[head(h)] - xy[v];
      return std::atan2(d.y(), d.x());
    };
    std::sort(out[v].begin(), out[v].end(), [&](int a, int b) { return angle(a) < angle(b); });
    for (int k = 0; k < static_cast<int>(out[v].size()); ++k) position[out[v][k]] = k;
  }
  // next(u->v) = the half-edge leaving v just clockwise of v->u: traces faces CCW.
  auto next = [&](int h) {
    const int v = head(h);
    const int twin = h ^ 1;
    const int k = position[twin];
    const int m = static_cast<int>(out[v].size());
    return out[v][(k - 1 + m) % m];
  };
  std::vector<char> used(2 * ne, 0);
  std::vector<std::vector<int>> faces;
  for (int h0 = 0; h0 < 2 * ne; ++h0) {
    if (used[h0]) continue;
    std::vector<int> cycle;
    int h = h0;
    while (!used[h]) {
      used[h] = 1;
      cycle.push_back(h);
      h = next(h);
    }
    double area2 = 0;
    for (int hh : cycle) area2 += cross2(xy[tail(hh)], xy[head(hh)]);
    if (area2 <= 0) continue;  // the outer face of a component (clockwise)
    bool all_boundary = true, dangling = false;
    std::unordered_set<int> edges_seen;
    for (int hh : cycle) {
      const Assignment a = p.assignments.empty() ? Assignment::Unassigned : p.assignments[hh / 2];
      if (a != Assignment::Boundary && a != Assignment::Cut) all_boundary = false;
      if (!edges_seen.insert(hh / 2).second) dangling = true;
    }
    if (dangling) {
      for (int hh : cycle)
        if (std::count_if(cycle.begin(), cycle.end(), [&](int x) { return x / 2 == hh / 2; }) > 1)
          throw InputError(at(source, edge_path(hh / 2)), "dangling edge: the same face lies on both of its sides");
    }
    std::vector<int> face;
    for (int hh : cycle) face.push_back(tail(hh));
    // A bounded cycle of boundary edges only is a hole in the sheet, unless it is the whole sheet.
    if (all_boundary && !p.assignments.empty()) {
      bool has_crease = false;
      for (auto a : p.assignments) has_crease = has_crease || (a != Assignment::Boundary && a != Assignment::Cut);
      if (has_crease) continue;
    }
    faces.push_back(std::move(face));
  }
  if (faces.empty()) throw InputError(at(source, "edges_vertices"), "the edges enclose no face");
  return faces;
}

void complete_and_validate(CreasePattern& p, const std::string& source) {
  if (p.vertices.empty()) throw InputError(at(source, "vertices_coords"), "is empty");
  if (p.edges.empty()) throw InputError(at(source, "edges_vertices"), "is empty");
  for (std::size_t i = 0; i < p.vertices.size(); ++i)
    if (!p.vertices[i].allFinite()) throw InputError(at(source, "vertices_coords[" + std::to_string(i) + "]"), "coordinate is not finite");
  // Every check below and every solver after it works on coordinates of size ~1.
  normalise_length_scale(p);
  for (int e = 0; e < p.num_edges(); ++e)
    for (int k = 0; k < 2; ++k)
      if (p.edges[e][k] < 0 || p.edges[e][k] >= p.num_vertices())
        throw InputError(at(source, edge_path(e) + "[" + std::to_string(k) + "]"), "vertex index out of range");
  if (!p.assignments.empty() && p.assignments.size() != p.edges.size())
    throw InputError(at(source, "edges_assignment"), "length differs from edges_vertices");
  if (p.fold_angles.empty()) p.fold_angles.assign(p.edges.size(), std::nullopt);
  if (p.fold_angles.size() != p.edges.size()) throw InputError(at(source, "edges_foldAngle"), "length differs from edges_vertices");
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.fold_angles[e] && !(std::fabs(*p.fold_angles[e]) <= std::numbers::pi + 1e-12))
      throw InputError(at(source, "edges_foldAngle[" + std::to_string(e) + "]"), "fold angle is not finite or outside [-180, 180] deg");

  check_edges(p, source);
  const bool folded = is_folded_form(p);
  // Crossings first: face derivation and orientation assume a proper plane embedding.
  if (p.coords_2d && !folded) check_planar_embedding(p, planar_coordinates(p, source), source);
  if (p.faces.empty()) {
    p.faces = derive_planar_faces(p, source);
    p.faces_derived = true;
  }
  for (int f = 0; f < p.num_faces(); ++f)
    for (std::size_t k = 0; k < p.faces[f].size(); ++k)
      if (p.faces[f][k] < 0 || p.faces[f][k] >= p.num_vertices())
        throw InputError(at(source, face_path(f) + "[" + std::to_string(k) + "]"), "vertex index out of range");
  check_face_cycles(p, source);
  if (p.coords_2d && !folded) orient_planar_faces(p, source);

  // Assignments: fill from the face count when missing; a temporary U lets the topology
  // treat every two-face edge as joined while we count.
  const bool fill_assignments = p.assignments.empty();
  if (fill_assignments) p.assignments.assign(p.edges.size(), Assignment::Unassigned);
  const Topology topo = build_topology(p, source);
  for (int e = 0; e < p.num_edges(); ++e) {
    const int count = (topo.edge_faces[e][0] >= 0) + (topo.edge_faces[e][1] >= 0);
    if (count == 0) throw InputError(at(source, edge_path(e)), "edge lies on no face (dangling crease or stray edge)");
    if (fill_assignments) {
      p.assignments[e] = count == 1 ? Assignment::Boundary : Assignment::Unassigned;
    } else if (count == 1 && p.assignments[e] != Assignment::Boundary && p.assignments[e] != Assignment::Cut) {
      p.warnings.push_back(at(source, "edges_assignment[" + std::to_string(e) + "]") + ": edge has one face but is assigned " +
                           std::string(1, assignment_letter(p.assignments[e])) + "; it acts as boundary");
    }
  }

  if (p.coords_2d && !folded) {
    // In a flat sheet the corners around a vertex tile the plane once; more means overlap.
    for (int v = 0; v < p.num_vertices(); ++v) {
      const auto& star = topo.stars[v];
      const double sum = star.sector_sum();
      const double limit = 2 * std::numbers::pi;
      if ((star.interior() && std::fabs(sum - limit) > 1e-9) || (!star.interior() && sum > limit + 1e-9))
        throw InputError(at(source, "vertices_coords[" + std::to_string(v) + "]"),
                         "faces around this vertex overlap (their angles sum to " + std::to_string(sum * 180 / std::numbers::pi) + " deg)");
    }
  }
}

}  // namespace rigidfold
