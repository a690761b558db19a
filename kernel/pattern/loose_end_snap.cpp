#include "kernel/pattern/loose_end_snap.hpp"

#include <algorithm>
#include <limits>

namespace rigidfold {

LooseEndSnap snap_loose_ends(std::vector<LabelledSegment>& segments, const PlanarArrangement& arrangement, double snap,
                             double merge_tolerance, std::int64_t max_pairs) {
  LooseEndSnap out;
  if (!(snap > 0)) return out;
  const auto& X = arrangement.vertices;
  const auto& E = arrangement.edges;
  const int nv = static_cast<int>(X.size()), ne = static_cast<int>(E.size());
  std::vector<int> degree(nv, 0), only_edge(nv, -1);
  for (int e = 0; e < ne; ++e)
    for (int v : E[e]) {
      ++degree[v];
      only_edge[v] = e;
    }
  std::vector<int> loose;
  for (int v = 0; v < nv; ++v) {
    if (degree[v] != 1) continue;
    const auto& e = E[only_edge[v]];
    const int w = e[0] == v ? e[1] : e[0];
    if ((X[v] - X[w]).norm() > snap) loose.push_back(v);  // shorter: an overshoot, not a line stopping short
  }
  if (loose.empty()) return out;
  if (static_cast<std::int64_t>(loose.size()) * (nv + ne) > max_pairs) {
    out.skipped_too_many = true;
    return out;
  }
  std::vector<char> is_target(nv, 0), moved(nv, 0);
  for (int v : loose) {
    if (is_target[v]) continue;
    const Eigen::Vector2d p = X[v];
    double best = std::numeric_limits<double>::infinity();
    int best_vertex = -1;
    for (int u = 0; u < nv; ++u) {
      if (u == v || moved[u]) continue;
      const double d = (X[u] - p).norm();
      if (d < best) {
        best = d;
        best_vertex = u;
      }
    }
    Eigen::Vector2d target = p;
    bool onto_line = false;
    if (best_vertex >= 0 && best <= snap) {
      target = X[best_vertex];
      is_target[best_vertex] = 1;
    } else {
      best = std::numeric_limits<double>::infinity();
      for (int e = 0; e < ne; ++e) {
        if (E[e][0] == v || E[e][1] == v || moved[E[e][0]] || moved[E[e][1]]) continue;
        const Eigen::Vector2d a = X[E[e][0]], d = X[E[e][1]] - a;
        const double len2 = d.squaredNorm();
        if (!(len2 > 0)) continue;
        const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
        const Eigen::Vector2d q = a + t * d;
        const double dist = (q - p).norm();
        if (dist < best) {
          best = dist;
          target = q;
        }
      }
      if (!(best <= snap)) continue;
      onto_line = true;
    }
    moved[v] = 1;
    ++out.ends_snapped;
    out.onto_lines += onto_line ? 1 : 0;
    out.max_distance = std::max(out.max_distance, best);
    // The arrangement merged the ends drawn here within the tolerance (chains of merges reach a
    // little further: twice it).
    for (auto& s : segments) {
      for (Eigen::Vector2d* end : {&s.a, &s.b}) {
        if ((*end - p).norm() <= 2 * merge_tolerance) {
          *end = target;
          if (out.source_example < 0) out.source_example = s.source;
        }
      }
    }
  }
  return out;
}

}  // namespace rigidfold
