#include "kernel/pattern/topology.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold {
namespace {

std::uint64_t half_edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

struct Corner {
  int face;
  int vertex;
  int prev, next;    // neighbouring vertices in the face cycle
  int edge_out = -1;  // edge (vertex, next)
  int edge_in = -1;   // edge (prev, vertex)
};

// Minimal union-find for components.
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(n) {
    for (int i = 0; i < n; ++i) parent[i] = i;
  }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

double VertexStar::sector_sum() const {
  double s = 0.0;
  for (const auto& f : fans)
    for (double a : f.sectors) s += a;
  return s;
}

Eigen::Vector3d newell_normal(const CreasePattern& p, const std::vector<int>& face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const Eigen::Vector3d& origin = p.vertices[face[0]];
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Eigen::Vector3d a = p.vertices[face[k]] - origin;
    const Eigen::Vector3d b = p.vertices[face[(k + 1) % face.size()]] - origin;
    n += a.cross(b);
  }
  return n;
}

double corner_angle(const Eigen::Vector3d& prev, const Eigen::Vector3d& at, const Eigen::Vector3d& next,
                    const Eigen::Vector3d& normal) {
  const Eigen::Vector3d a = next - at;
  const Eigen::Vector3d b = prev - at;
  // atan2 of (sin, cos) keeps full accuracy for tiny and near-pi angles.
  double angle = std::atan2(a.cross(b).dot(normal.normalized()), a.dot(b));
  if (angle <= 0.0) angle += 2.0 * std::numbers::pi;
  return angle;
}

namespace {

// Undirected edge lookup: (a, b) in either order -> edge index, -1 if the pattern has none.
class EdgeIndex {
 public:
  explicit EdgeIndex(const CreasePattern& p) {
    const int ne = p.num_edges();
    edge_of_.reserve(2 * ne);
    for (int e = 0; e < ne; ++e) {
      auto [a, b] = std::minmax(p.edges[e][0], p.edges[e][1]);
      edge_of_.emplace(half_edge_key(a, b), e);
    }
  }
  int find(int a, int b) const {
    auto [lo, hi] = std::minmax(a, b);
    auto it = edge_of_.find(half_edge_key(lo, hi));
    return it == edge_of_.end() ? -1 : it->second;
  }

 private:
  std::unordered_map<std::uint64_t, int> edge_of_;  // undirected (min, max) -> edge index
};

// Step 1: manifoldness; no edge may be a side of more than two faces.
void check_manifold(const CreasePattern& p, const EdgeIndex& edges, const std::string& source) {
  std::vector<int> uses(p.num_edges(), 0);
  for (int f = 0; f < p.num_faces(); ++f) {
    const auto& face = p.faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int e = edges.find(face[k], face[(k + 1) % face.size()]);
      if (e >= 0 && ++uses[e] > 2)
        throw InputError(source + ": faces_vertices[" + std::to_string(f) + "]",
                         "edge " + std::to_string(e) + " (vertices " + std::to_string(p.edges[e][0]) + "-" +
                             std::to_string(p.edges[e][1]) + ") is shared by more than two faces (non-manifold)");
    }
  }
}

// Step 2: the faces on each side of every edge (checking that the faces are consistently
// oriented), face normals and areas, and which edges are hinges. Returns every face corner
// with its incoming and outgoing edges.
std::vector<Corner> attach_faces_to_edges(const CreasePattern& p, const EdgeIndex& edges, const std::string& source,
                                         Topology& t) {
  const int ne = p.num_edges(), nf = p.num_faces();
  std::vector<int> edge_face_count(ne, 0);
  std::vector<Corner> corners;
  for (int f = 0; f < nf; ++f) {
    const auto& face = p.faces[f];
    const Eigen::Vector3d n = newell_normal(p, face);
    t.face_areas[f] = 0.5 * n.norm();
    t.face_normals[f] = n.norm() > 0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::UnitZ();
    const int m = static_cast<int>(face.size());
    for (int k = 0; k < m; ++k) {
      const int a = face[k], b = face[(k + 1) % m];
      const int e = edges.find(a, b);
      if (e < 0)
        throw InputError(source + ": faces_vertices[" + std::to_string(f) + "]",
                         "side " + std::to_string(a) + "-" + std::to_string(b) + " is not an edge");
      const int side = (p.edges[e][0] == a) ? 0 : 1;  // 0: face on the left of v0->v1
      if (t.edge_faces[e][side] >= 0)
        throw InputError(source + ": faces_vertices[" + std::to_string(f) + "]",
                         "faces " + std::to_string(t.edge_faces[e][side]) + " and " + std::to_string(f) +
                             " traverse edge " + std::to_string(e) + " in the same direction (faces not consistently oriented)");
      t.edge_faces[e][side] = f;
      ++edge_face_count[e];
      corners.push_back({f, face[k], face[(k + m - 1) % m], face[(k + 1) % m]});
    }
  }
  for (auto& c : corners) {
    c.edge_out = edges.find(c.vertex, c.next);
    c.edge_in = edges.find(c.prev, c.vertex);
  }
  for (int e = 0; e < ne; ++e) {
    const Assignment a = p.assignments[e];
    t.edge_is_hinge[e] = edge_face_count[e] == 2 && a != Assignment::Boundary && a != Assignment::Cut;
  }
  return corners;
}

// Corners grouped by vertex; successor of a corner = the corner across its incoming edge.
struct CornerGraph {
  const std::vector<Corner>& corners;
  const Topology& t;
  std::vector<std::vector<int>> vertex_corners;

  CornerGraph(const std::vector<Corner>& c, const Topology& topology, int nv)
      : corners(c), t(topology), vertex_corners(nv) {
    for (int i = 0; i < static_cast<int>(corners.size()); ++i) vertex_corners[corners[i].vertex].push_back(i);
  }
  int corner_of(int face, int vertex) const {
    for (int i : vertex_corners[vertex])
      if (corners[i].face == face) return i;
    return -1;
  }
  int successor(int ci) const {
    const Corner& c = corners[ci];
    if (!t.edge_is_hinge[c.edge_in]) return -1;
    const auto& ef = t.edge_faces[c.edge_in];
    const int other = ef[0] == c.face ? ef[1] : ef[0];
    return corner_of(other, c.vertex);
  }
  bool predecessor_exists(int ci) const { return t.edge_is_hinge[corners[ci].edge_out]; }
};

// Step 3: the star of vertex v, its corners chained into fans across hinges.
void build_star(const CreasePattern& p, const CornerGraph& g, int v, Topology& t) {
  const std::vector<int>& around = g.vertex_corners[v];
  std::vector<char> used(around.size(), 0);
  auto local = [&](int ci) { return static_cast<int>(std::find(around.begin(), around.end(), ci) - around.begin()); };
  auto walk = [&](int start, bool closed) {
    Fan fan;
    fan.closed = closed;
    int ci = start;
    while (ci >= 0 && !used[local(ci)]) {
      used[local(ci)] = 1;
      const Corner& c = g.corners[ci];
      fan.edges.push_back(c.edge_out);
      fan.sectors.push_back(corner_angle(p.vertices[c.prev], p.vertices[c.vertex], p.vertices[c.next], t.face_normals[c.face]));
      fan.faces.push_back(c.face);
      const int nxt = g.successor(ci);
      if (nxt < 0) fan.edges.push_back(c.edge_in);
      ci = nxt;
    }
    t.stars[v].fans.push_back(std::move(fan));
  };
  // Open fans start at a corner whose outgoing edge is not a hinge.
  for (int ci : around)
    if (!used[local(ci)] && !g.predecessor_exists(ci)) walk(ci, false);
  // What is left are closed fans; start each at its lowest edge index, for determinism.
  for (std::size_t k = 0; k < around.size(); ++k) {
    if (used[k]) continue;
    int best = around[k];
    int cur = g.successor(best);
    while (cur >= 0 && cur != around[k]) {
      if (g.corners[cur].edge_out < g.corners[best].edge_out) best = cur;
      cur = g.successor(cur);
    }
    walk(best, true);
  }
}

// Step 4: components (faces joined across hinges) and their vertex, edge and face counts.
void find_components(const CreasePattern& p, Topology& t) {
  const int nv = p.num_vertices(), ne = p.num_edges(), nf = p.num_faces();
  DisjointSets sets(std::max(nf, 1));
  for (int e = 0; e < ne; ++e)
    if (t.edge_is_hinge[e]) sets.unite(t.edge_faces[e][0], t.edge_faces[e][1]);
  std::unordered_map<int, int> comp_index;
  t.face_component.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const int r = sets.find(f);
    auto it = comp_index.find(r);
    if (it == comp_index.end()) it = comp_index.emplace(r, static_cast<int>(comp_index.size())).first;
    t.face_component[f] = it->second;
  }
  t.components.resize(comp_index.size());
  for (int f = 0; f < nf; ++f) ++t.components[t.face_component[f]].faces;
  for (int e = 0; e < ne; ++e) {
    // A joined edge is one surface edge; an unjoined edge with two faces counts on both sides.
    for (int side = 0; side < 2; ++side) {
      const int f = t.edge_faces[e][side];
      if (f < 0) continue;
      if (t.edge_is_hinge[e] && side == 1) continue;
      ++t.components[t.face_component[f]].edges;
    }
  }
  for (int v = 0; v < nv; ++v)
    for (const auto& fan : t.stars[v].fans) ++t.components[t.face_component[fan.faces.front()]].vertices;
}

// Step 5: boundary loops, half-edges without a joined partner chained around the sheet;
// each loop is counted in its component.
void trace_boundary_loops(const CreasePattern& p, const EdgeIndex& edges, Topology& t) {
  const int nf = p.num_faces();
  std::vector<std::pair<int, int>> boundary_half_edges;  // (face, k): side k of face
  for (int f = 0; f < nf; ++f) {
    const int m = static_cast<int>(p.faces[f].size());
    for (int k = 0; k < m; ++k) {
      const int e = edges.find(p.faces[f][k], p.faces[f][(k + 1) % m]);
      if (!t.edge_is_hinge[e]) boundary_half_edges.emplace_back(f, k);
    }
  }
  std::unordered_map<std::uint64_t, int> be_index;  // (face, k) -> index
  for (int i = 0; i < static_cast<int>(boundary_half_edges.size()); ++i)
    be_index.emplace(half_edge_key(boundary_half_edges[i].first, boundary_half_edges[i].second), i);
  std::vector<char> visited(boundary_half_edges.size(), 0);
  for (int i = 0; i < static_cast<int>(boundary_half_edges.size()); ++i) {
    if (visited[i]) continue;
    std::vector<int> loop;
    int cur = i;
    int guard = 0;
    while (cur >= 0 && !visited[cur] && guard++ <= static_cast<int>(boundary_half_edges.size())) {
      visited[cur] = 1;
      auto [f, k] = boundary_half_edges[cur];
      const auto& face = p.faces[f];
      const int m = static_cast<int>(face.size());
      loop.push_back(face[k]);
      // Walk to the next unjoined side: step along the face, crossing hinges around the head vertex.
      int ff = f, kk = (k + 1) % m;
      int steps = 0;
      while (steps++ < 4 * nf + 4) {
        const auto& fc = p.faces[ff];
        const int mm = static_cast<int>(fc.size());
        const int e = edges.find(fc[kk], fc[(kk + 1) % mm]);
        if (!t.edge_is_hinge[e]) break;
        const int other = t.edge_faces[e][0] == ff ? t.edge_faces[e][1] : t.edge_faces[e][0];
        const int head = fc[kk];
        const auto& oc = p.faces[other];
        const int pos = static_cast<int>(std::find(oc.begin(), oc.end(), head) - oc.begin());
        ff = other;
        kk = pos;
      }
      auto it = be_index.find(half_edge_key(ff, kk));
      cur = it == be_index.end() ? -1 : it->second;
    }
    t.boundary_loops.push_back(std::move(loop));
    ++t.components[t.face_component[boundary_half_edges[i].first]].boundary_loops;
  }
}

// Step 6: Euler characteristic, genus and holes of every component.
void classify_components(Topology& t) {
  for (auto& c : t.components) {
    c.euler_characteristic = c.vertices - c.edges + c.faces;
    c.genus = std::max(0, (2 - c.boundary_loops - c.euler_characteristic) / 2);
    c.holes = std::max(0, c.boundary_loops - 1);
  }
}

}  // namespace

Topology build_topology(const CreasePattern& p, const std::string& source) {
  const int nv = p.num_vertices(), ne = p.num_edges(), nf = p.num_faces();
  Topology t;
  t.edge_faces.assign(ne, {-1, -1});
  t.edge_is_hinge.assign(ne, false);
  t.face_normals.resize(nf);
  t.face_areas.resize(nf);
  const EdgeIndex edges(p);

  check_manifold(p, edges, source);
  const std::vector<Corner> corners = attach_faces_to_edges(p, edges, source, t);
  const CornerGraph graph(corners, t, nv);
  t.stars.resize(nv);
  for (int v = 0; v < nv; ++v) {
    build_star(p, graph, v, t);
    if (t.stars[v].interior()) t.interior_vertices.push_back(v);
  }
  find_components(p, t);
  trace_boundary_loops(p, edges, t);
  classify_components(t);
  return t;
}

}  // namespace rigidfold
