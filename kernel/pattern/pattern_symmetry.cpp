#include "kernel/pattern/pattern_symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "kernel/pattern/assignment.hpp"

namespace rigidfold {

namespace {

// What an edge must keep under a symmetry: crease, boundary, or rigid join.
int edge_kind(Assignment a) {
  if (is_foldable_crease(a)) return 0;
  if (a == Assignment::Boundary || a == Assignment::Cut) return 1;
  return 2;
}

// Vertex lookup by position: a hash grid of cell `cell`, searched in the 3 x 3 block.
class PointIndex {
 public:
  PointIndex(const std::vector<Eigen::Vector2d>& points, double cell) : points_(points), cell_(cell) {
    for (int i = 0; i < static_cast<int>(points.size()); ++i) grid_[key(cell_of(points[i]))].push_back(i);
  }
  int find(const Eigen::Vector2d& q, double tol) const {
    const auto [cx, cy] = cell_of(q);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = grid_.find(key({cx + dx, cy + dy}));
        if (it == grid_.end()) continue;
        for (int i : it->second)
          if ((points_[i] - q).norm() <= tol) return i;
      }
    return -1;
  }

 private:
  std::pair<long long, long long> cell_of(const Eigen::Vector2d& p) const {
    return {std::llround(std::floor(p.x() / cell_)), std::llround(std::floor(p.y() / cell_))};
  }
  static long long key(std::pair<long long, long long> c) { return c.first * 1000003LL ^ c.second; }
  const std::vector<Eigen::Vector2d>& points_;
  double cell_;
  std::unordered_map<long long, std::vector<int>> grid_;
};

}  // namespace

std::vector<PatternSymmetry> pattern_symmetries(const CreasePattern& pattern, double relative_tolerance) {
  const int n = pattern.num_vertices();
  std::vector<Eigen::Vector2d> p(n);
  for (int v = 0; v < n; ++v) {
    if (pattern.vertices[v].z() != 0.0)
      throw std::invalid_argument("vertex " + std::to_string(v) + " has z = " + std::to_string(pattern.vertices[v].z()) +
                                  ": the symmetry group needs a flat crease pattern");
    p[v] = pattern.vertices[v].head<2>();
  }
  std::vector<PatternSymmetry> group;
  PatternSymmetry identity;
  identity.vertex_map.resize(n);
  identity.edge_map.resize(pattern.num_edges());
  for (int v = 0; v < n; ++v) identity.vertex_map[v] = v;
  for (int e = 0; e < pattern.num_edges(); ++e) identity.edge_map[e] = e;
  if (n == 0) return {identity};

  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const auto& q : p) c += q;
  c /= n;
  identity.center = c;
  group.push_back(identity);
  double size = 0.0;
  for (const auto& q : p) size = std::max(size, (q - c).norm());
  if (size == 0.0) return group;
  const double tol = relative_tolerance * size;
  const PointIndex index(p, std::max(4 * tol, 1e-300));

  std::map<std::pair<int, int>, int> edge_of;
  for (int e = 0; e < pattern.num_edges(); ++e)
    edge_of[{std::min(pattern.edges[e][0], pattern.edges[e][1]), std::max(pattern.edges[e][0], pattern.edges[e][1])}] = e;

  int p0 = 0;
  for (int v = 1; v < n; ++v)
    if ((p[v] - c).norm() > (p[p0] - c).norm() + tol) p0 = v;
  const double r0 = (p[p0] - c).norm();
  const double a0 = std::atan2(p[p0].y() - c.y(), p[p0].x() - c.x());

  auto try_map = [&](const Eigen::Matrix2d& L, bool reflection, double angle) {
    PatternSymmetry s;
    s.linear = L;
    s.center = c;
    s.reflection = reflection;
    s.rotation_angle = angle;
    s.vertex_map.resize(n);
    for (int v = 0; v < n; ++v) {
      const int w = index.find(c + L * (p[v] - c), tol);
      if (w < 0) return;
      s.vertex_map[v] = w;
    }
    s.edge_map.resize(pattern.num_edges());
    for (int e = 0; e < pattern.num_edges(); ++e) {
      const int a = s.vertex_map[pattern.edges[e][0]], b = s.vertex_map[pattern.edges[e][1]];
      const auto it = edge_of.find({std::min(a, b), std::max(a, b)});
      if (it == edge_of.end() || edge_kind(pattern.assignments[it->second]) != edge_kind(pattern.assignments[e])) return;
      s.edge_map[e] = it->second;
    }
    for (const auto& g : group)
      if (g.vertex_map == s.vertex_map) return;  // already found (e.g. two candidates agree)
    group.push_back(std::move(s));
  };
  for (int q = 0; q < n; ++q) {
    if (std::fabs((p[q] - c).norm() - r0) > tol) continue;
    const double aq = std::atan2(p[q].y() - c.y(), p[q].x() - c.x());
    double turn = std::remainder(aq - a0, 2 * std::numbers::pi);
    if (turn < 0) turn += 2 * std::numbers::pi;
    Eigen::Matrix2d R;
    R << std::cos(turn), -std::sin(turn), std::sin(turn), std::cos(turn);
    if (q != p0) try_map(R, false, turn);
    // Reflection across the line through c at angle phi = (a0 + aq) / 2.
    const double phi = 0.5 * (a0 + aq);
    Eigen::Matrix2d M;
    M << std::cos(2 * phi), std::sin(2 * phi), std::sin(2 * phi), -std::cos(2 * phi);
    try_map(M, true, 0.0);
  }
  return group;
}

}  // namespace rigidfold
