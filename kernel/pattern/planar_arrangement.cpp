#include "kernel/pattern/planar_arrangement.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace rigidfold {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

std::uint64_t pair_key(std::int64_t a, std::int64_t b) {
  return (static_cast<std::uint64_t>(a) << 32) ^ static_cast<std::uint64_t>(static_cast<std::uint32_t>(b));
}

// Uniform grid over the segments' bounding box: each segment is entered in the cells its
// tolerance-thickened line passes through (not its bounding box, so long diagonals cost
// O(cells crossed)), and segments sharing a cell are candidate pairs.
std::vector<std::pair<int, int>> candidate_pairs(const std::vector<LabelledSegment>& s, double tol, std::int64_t max_pairs) {
  const int n = static_cast<int>(s.size());
  Eigen::Vector2d lo = s[0].a, hi = s[0].a;
  for (const auto& g : s) {
    lo = lo.cwiseMin(g.a).cwiseMin(g.b);
    hi = hi.cwiseMax(g.a).cwiseMax(g.b);
  }
  lo.array() -= 2 * tol;
  hi.array() += 2 * tol;
  const int cells = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(n))), 1, 2048);
  const Eigen::Vector2d cell = (hi - lo) / cells;
  auto index = [&](double x, int axis) {
    return static_cast<int>(std::clamp(std::floor((x - lo[axis]) / cell[axis]), 0.0, cells - 1.0));
  };
  std::vector<std::pair<std::int64_t, int>> entries;
  entries.reserve(static_cast<std::size_t>(n) * 4);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = s[k].a, b = s[k].b, d = b - a;
    // Walk along the major axis; on each slab the segment's minor-axis range, thickened.
    const int major = std::fabs(d.x()) >= std::fabs(d.y()) ? 0 : 1, minor = 1 - major;
    const int i0 = index(std::min(a[major], b[major]) - tol, major), i1 = index(std::max(a[major], b[major]) + tol, major);
    for (int i = i0; i <= i1; ++i) {
      const double x0 = std::max(lo[major] + i * cell[major], std::min(a[major], b[major])) - tol;
      const double x1 = std::min(lo[major] + (i + 1) * cell[major], std::max(a[major], b[major])) + tol;
      double y0, y1;
      if (d[major] == 0) {
        y0 = std::min(a[minor], b[minor]);
        y1 = std::max(a[minor], b[minor]);
      } else {
        const double slope = d[minor] / d[major];
        const double ya = a[minor] + (x0 - a[major]) * slope, yb = a[minor] + (x1 - a[major]) * slope;
        y0 = std::max(std::min(ya, yb), std::min(a[minor], b[minor]));
        y1 = std::min(std::max(ya, yb), std::max(a[minor], b[minor]));
      }
      const int j0 = index(y0 - tol, minor), j1 = index(y1 + tol, minor);
      for (int j = j0; j <= j1; ++j) {
        const std::int64_t key = major == 0 ? static_cast<std::int64_t>(i) * cells + j : static_cast<std::int64_t>(j) * cells + i;
        entries.emplace_back(key, k);
      }
    }
  }
  std::sort(entries.begin(), entries.end());
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t g = 0; g < entries.size();) {
    std::size_t h = g;
    while (h < entries.size() && entries[h].first == entries[g].first) ++h;
    const auto count = static_cast<std::int64_t>(h - g);
    if (static_cast<std::int64_t>(pairs.size()) + count * (count - 1) / 2 > max_pairs)
      throw std::length_error("more than " + std::to_string(max_pairs) + " pairs of nearby segments to test (many overlapping lines)");
    for (std::size_t x = g; x < h; ++x)
      for (std::size_t y = x + 1; y < h; ++y)
        if (entries[x].second != entries[y].second) pairs.emplace_back(entries[x].second, entries[y].second);
    g = h;
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

PlanarArrangement build_planar_arrangement(const std::vector<LabelledSegment>& input, const ArrangementOptions& options) {
  const double tol = options.tolerance;
  if (!(tol > 0) || !std::isfinite(tol)) throw std::invalid_argument("planar arrangement: tolerance must be positive");
  PlanarArrangement out;
  std::vector<LabelledSegment> s;
  for (const auto& g : input) {
    if ((g.b - g.a).norm() <= tol) ++out.zero_length_segments;
    else s.push_back(g);
  }
  if (s.empty()) return out;
  const int n = static_cast<int>(s.size());
  {
    Eigen::Vector2d lo = s[0].a, hi = s[0].a;
    for (const auto& g : s) {
      if (!g.a.allFinite() || !g.b.allFinite()) throw std::invalid_argument("planar arrangement: coordinate is not finite");
      lo = lo.cwiseMin(g.a).cwiseMin(g.b);
      hi = hi.cwiseMax(g.a).cwiseMax(g.b);
    }
    if (!((hi - lo).maxCoeff() / tol <= 1e15)) throw std::invalid_argument("planar arrangement: tolerance below 1e-15 of the extent");
  }

  // Points 2k and 2k+1 are the ends of segment k; crossings are appended.
  std::vector<Eigen::Vector2d> pts, rounding;  // rounding: per point, half-widths per axis
  pts.reserve(2 * static_cast<std::size_t>(n));
  for (const auto& g : s) {
    pts.push_back(g.a);
    pts.push_back(g.b);
    rounding.push_back(g.a_rounding);
    rounding.push_back(g.b_rounding);
  }
  std::vector<std::vector<std::pair<double, int>>> splits(n);
  for (int k = 0; k < n; ++k) splits[k] = {{0.0, 2 * k}, {1.0, 2 * k + 1}};
  std::vector<std::pair<int, int>> unions;

  // End `p` of another segment against segment k: inside it splits k; near k's own end it
  // is the same vertex (merged even if slightly more than `tol` from that end).
  auto touch = [&](int k, int p) {
    const Eigen::Vector2d a = s[k].a, d = s[k].b - s[k].a;
    const double len = d.norm();
    const double t = (pts[p] - a).dot(d) / (len * len);
    const double tc = std::clamp(t, 0.0, 1.0);
    const double gap = (a + tc * d - pts[p]).norm();
    if (gap > tol) return false;
    if (tc * len <= tol) {
      unions.emplace_back(p, 2 * k);
    } else if ((1 - tc) * len <= tol) {
      unions.emplace_back(p, 2 * k + 1);
    } else {
      splits[k].emplace_back(tc, p);  // k now bends through p: a point moved by `gap`
      if (gap > 0) {
        ++out.merged_points;
        out.max_merge_distance = std::max(out.max_merge_distance, gap);
      }
    }
    return true;
  };

  for (const auto& [i, j] : candidate_pairs(s, tol, options.max_candidate_pairs)) {
    bool touched = false;
    for (int p : {2 * j, 2 * j + 1}) touched = touch(i, p) || touched;
    for (int p : {2 * i, 2 * i + 1}) touched = touch(j, p) || touched;
    if (touched) {
      ++out.touches;
      continue;
    }
    const Eigen::Vector2d r = s[i].b - s[i].a, q = s[j].b - s[j].a, ac = s[j].a - s[i].a;
    const double denom = cross2(r, q);
    if (std::fabs(denom) <= 1e-12 * r.norm() * q.norm()) continue;  // parallel, apart
    const double t = cross2(ac, q) / denom, u = cross2(ac, r) / denom;
    if (t <= 0 || t >= 1 || u <= 0 || u >= 1) continue;
    const int x = static_cast<int>(pts.size());
    pts.push_back(s[i].a + t * r);
    {
      // First-order move of the crossing: each line shifts across itself by at most d (the
      // larger rounding of its ends, Euclidean), so the crossing moves by <= (d_i + d_j) / sin;
      // twice that covers the second-order terms while d is small against the lengths.
      const double di = std::max(s[i].a_rounding.norm(), s[i].b_rounding.norm());
      const double dj = std::max(s[j].a_rounding.norm(), s[j].b_rounding.norm());
      const double sine = std::fabs(denom) / (r.norm() * q.norm());
      const double move = 2 * (di + dj) / sine;
      const bool small = std::max(di, dj) <= 1e-3 * std::min(r.norm(), q.norm());
      rounding.push_back(Eigen::Vector2d::Constant(small ? move : INFINITY));
    }
    splits[i].emplace_back(t, x);
    splits[j].emplace_back(u, x);
    ++out.crossings;
  }

  // Merge points closer than the tolerance: hash by tolerance-sized cells, test neighbours.
  const int np = static_cast<int>(pts.size());
  UnionFind uf(np);
  for (const auto& [a, b] : unions) uf.unite(a, b);
  {
    struct Hash {
      std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& c) const {
        return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(c.first) * 1000003u ^ static_cast<std::uint64_t>(c.second));
      }
    };
    std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::vector<int>, Hash> cells;
    // Cells counted from the lower-left corner: at most extent / tol <= 1e15 per axis.
    Eigen::Vector2d lo = pts[0];
    for (const auto& x : pts) lo = lo.cwiseMin(x);
    auto cell_of = [&](const Eigen::Vector2d& x) {
      return std::pair<std::int64_t, std::int64_t>(static_cast<std::int64_t>(std::floor((x.x() - lo.x()) / tol)),
                                                   static_cast<std::int64_t>(std::floor((x.y() - lo.y()) / tol)));
    };
    for (int p = 0; p < np; ++p) {
      const auto c = cell_of(pts[p]);
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
          auto it = cells.find({c.first + dx, c.second + dy});
          if (it == cells.end()) continue;
          for (int o : it->second)
            if ((pts[o] - pts[p]).norm() <= tol) uf.unite(o, p);
        }
      cells[c].push_back(p);
    }
  }
  // A vertex sits at the mean of the drawn ends in its cluster (crossings only when it has
  // none), so exactly shared ends keep their exact coordinates: where every drawn end of the
  // cluster is the same point, that point itself (a floating-point mean of n equal numbers
  // may miss it by an ulp, and a written pattern must read back bit for bit).
  std::vector<int> root(np);
  for (int p = 0; p < np; ++p) root[p] = uf.find(p);
  std::vector<Eigen::Vector2d> sum_end(np, Eigen::Vector2d::Zero()), sum_all(np, Eigen::Vector2d::Zero());
  std::vector<int> count_end(np, 0), count_all(np, 0), first_end(np, -1);
  std::vector<char> ends_equal(np, 1);
  for (int p = 0; p < np; ++p) {
    const int r = root[p];
    sum_all[r] += pts[p];
    ++count_all[r];
    if (p < 2 * n) {
      sum_end[r] += pts[p];
      ++count_end[r];
      if (first_end[r] < 0) first_end[r] = p;
      else if (pts[p] != pts[first_end[r]]) ends_equal[r] = 0;
    }
  }
  std::vector<Eigen::Vector2d> position(np);
  for (int p = 0; p < np; ++p) {
    if (root[p] != p) continue;
    if (count_end[p] > 0) position[p] = ends_equal[p] ? pts[first_end[p]] : Eigen::Vector2d(sum_end[p] / count_end[p]);
    else position[p] = sum_all[p] / count_all[p];
  }
  {
    std::vector<std::vector<int>> members(np);
    for (int p = 0; p < np; ++p) members[root[p]].push_back(p);
    for (int r = 0; r < np; ++r) {
      if (members[r].size() < 2) continue;
      std::vector<std::pair<double, double>> distinct;
      for (int p : members[r]) {
        distinct.emplace_back(pts[p].x(), pts[p].y());
        out.max_merge_distance = std::max(out.max_merge_distance, (pts[p] - position[r]).norm());
      }
      std::sort(distinct.begin(), distinct.end());
      out.merged_points += static_cast<int>(std::unique(distinct.begin(), distinct.end()) - distinct.begin()) - 1;
    }
  }

  // Edges along each segment between consecutive distinct vertices; an edge drawn twice is
  // kept once: with the label of higher priority, else the later segment's (header comment).
  struct Edge {
    int u, v, label, source;
    bool alive = true;
  };
  std::vector<Edge> edges;
  std::unordered_map<std::uint64_t, int> edge_of;
  auto priority = [&](int label) {
    return label >= 0 && label < static_cast<int>(options.label_priority.size()) ? options.label_priority[label] : 0;
  };
  // Where the last record of each list ends: the segment drawing it and the vertex, to
  // extend it by that segment's next piece over the same line.
  std::pair<int, int> conflict_end{-1, -1}, duplicate_end{-1, -1};
  auto record = [&](std::vector<LabelConflict>& list, std::pair<int, int>& end, const LabelConflict& c, int segment, int u, int v) {
    if (!list.empty() && end == std::pair(segment, u)) {
      LabelConflict& last = list.back();
      if (last.source_a == c.source_a && last.source_b == c.source_b && last.label_a == c.label_a && last.label_b == c.label_b &&
          last.label_kept == c.label_kept) {
        last.to = c.to;
        ++last.pieces;
        end.second = v;
        return;
      }
    }
    list.push_back(c);
    end = {segment, v};
  };
  auto add_edge = [&](int segment, int u, int v, int label, int source) {
    const std::uint64_t key = pair_key(std::min(u, v), std::max(u, v));
    auto [it, fresh] = edge_of.emplace(key, static_cast<int>(edges.size()));
    if (fresh) {
      edges.push_back({u, v, label, source});
      return;
    }
    Edge& old = edges[it->second];
    LabelConflict c{old.source, source, old.label, label, old.label, position[u], position[v], 1};
    if (old.label == label) {
      ++out.duplicate_edges;
      record(out.duplicates, duplicate_end, c, segment, u, v);
      return;
    }
    if (priority(label) >= priority(old.label)) {
      old.label = c.label_kept = label;
      old.source = source;
    }
    record(out.conflicts, conflict_end, c, segment, u, v);
  };
  for (int k = 0; k < n; ++k) {
    auto& list = splits[k];
    std::sort(list.begin(), list.end());
    int prev = -1;
    for (const auto& [t, p] : list) {
      const int r = root[p];
      if (prev >= 0 && r != prev) add_edge(k, prev, r, s[k].label, s[k].source);
      prev = r;
    }
  }

  if (options.remove_collinear_degree2) {
    std::vector<std::vector<int>> incident(np);
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
      incident[edges[e].u].push_back(e);
      incident[edges[e].v].push_back(e);
    }
    for (int v = 0; v < np; ++v) {
      auto& inc = incident[v];
      inc.erase(std::remove_if(inc.begin(), inc.end(), [&](int e) { return !edges[e].alive; }), inc.end());
      if (inc.size() != 2) continue;
      Edge& e1 = edges[inc[0]];
      Edge& e2 = edges[inc[1]];
      if (e1.label != e2.label) continue;
      const int a = e1.u == v ? e1.v : e1.u, b = e2.u == v ? e2.v : e2.u;
      if (a == b || edge_of.count(pair_key(std::min(a, b), std::max(a, b)))) continue;
      const Eigen::Vector2d pa = position[a], pb = position[b], pv = position[v];
      const Eigen::Vector2d d = pb - pa;
      if ((pa - pv).dot(pb - pv) >= 0) continue;  // v is not between a and b
      if (std::fabs(cross2(d, pv - pa)) / d.norm() > tol) continue;
      e1.alive = e2.alive = false;
      const int id = static_cast<int>(edges.size());
      edges.push_back({a, b, e1.label, std::min(e1.source, e2.source)});
      edge_of.erase(pair_key(std::min(a, v), std::max(a, v)));
      edge_of.erase(pair_key(std::min(b, v), std::max(b, v)));
      edge_of.emplace(pair_key(std::min(a, b), std::max(a, b)), id);
      incident[a].push_back(id);
      incident[b].push_back(id);
      inc.clear();
      ++out.collinear_vertices_removed;
    }
  }

  std::vector<Eigen::Vector2d> box_lo(np, Eigen::Vector2d::Constant(INFINITY)), box_hi(np, Eigen::Vector2d::Constant(-INFINITY));
  for (int p = 0; p < np; ++p) {
    box_lo[root[p]] = box_lo[root[p]].cwiseMin(pts[p] - rounding[p]);
    box_hi[root[p]] = box_hi[root[p]].cwiseMax(pts[p] + rounding[p]);
  }
  std::vector<int> vertex_id(np, -1);
  for (const Edge& e : edges) {
    if (!e.alive) continue;
    for (int p : {e.u, e.v})
      if (vertex_id[p] < 0) {
        vertex_id[p] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(position[p]);
        out.vertex_lo.push_back(box_lo[p]);
        out.vertex_hi.push_back(box_hi[p]);
      }
    out.edges.push_back({vertex_id[e.u], vertex_id[e.v]});
    out.edge_label.push_back(e.label);
    out.edge_source.push_back(e.source);
  }
  return out;
}

}  // namespace rigidfold
