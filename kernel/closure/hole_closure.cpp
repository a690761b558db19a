#include "kernel/closure/hole_closure.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/math/so3.hpp"

namespace rigidfold {
namespace {

std::uint64_t pair_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

Eigen::Vector3d face_centroid(const CreasePattern& p, int f) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int v : p.faces[f]) c += p.vertices[v];
  return c / static_cast<double>(p.faces[f].size());
}

// Product of the step motions: fills the spatial axes w_i and points a_i when asked.
Eigen::Isometry3d loop_product(const CreasePattern& p, const HoleLoop& loop, std::span<const double> theta,
                               Eigen::Matrix3Xd* w, Eigen::Matrix3Xd* a) {
  if (theta.size() != loop.steps.size())
    throw std::invalid_argument("hole closure: expected one angle per step of the loop");
  Eigen::Isometry3d P = Eigen::Isometry3d::Identity();
  const int m = static_cast<int>(loop.steps.size());
  if (w) w->resize(3, m);
  if (a) a->resize(3, m);
  for (int i = 0; i < m; ++i) {
    const HoleStep& s = loop.steps[i];
    const Eigen::Vector3d v0 = p.vertices[p.edges[s.edge][0]];
    const Eigen::Vector3d d = (s.side == 0 ? 1.0 : -1.0) * (p.vertices[p.edges[s.edge][1]] - v0).normalized();
    if (w) w->col(i) = P.linear() * d;
    if (a) a->col(i) = P * v0;
    P = P * hinge_motion(p, s.edge, s.side, theta[i]);
  }
  return P;
}

}  // namespace

std::vector<HoleLoop> find_hole_loops(const CreasePattern& p, const Topology& t) {
  const int nf = p.num_faces();
  std::unordered_map<std::uint64_t, int> edge_of;
  for (int e = 0; e < p.num_edges(); ++e) {
    const int lo = std::min(p.edges[e][0], p.edges[e][1]), hi = std::max(p.edges[e][0], p.edges[e][1]);
    edge_of.emplace(pair_key(lo, hi), e);
  }
  auto find_edge = [&](int u, int v) {
    auto it = edge_of.find(pair_key(std::min(u, v), std::max(u, v)));
    if (it == edge_of.end()) throw std::invalid_argument("hole closure: a face side is not an edge");
    return it->second;
  };
  // Boundary half-edges (face, side) in face order, as build_topology enumerates them.
  std::unordered_map<std::uint64_t, int> boundary_index;
  std::vector<std::pair<int, int>> boundary;
  for (int f = 0; f < nf; ++f) {
    const int m = static_cast<int>(p.faces[f].size());
    for (int k = 0; k < m; ++k)
      if (!t.edge_is_hinge[find_edge(p.faces[f][k], p.faces[f][(k + 1) % m])]) {
        boundary_index.emplace(pair_key(f, k), static_cast<int>(boundary.size()));
        boundary.emplace_back(f, k);
      }
  }
  std::vector<char> visited(boundary.size(), 0);
  std::vector<int> loops_seen(t.components.size(), 0);
  std::vector<HoleLoop> out;
  int loop_index = -1;
  for (int i = 0; i < static_cast<int>(boundary.size()); ++i) {
    if (visited[i]) continue;
    ++loop_index;
    HoleLoop loop;
    loop.base_face = boundary[i].first;
    loop.component = t.face_component[loop.base_face];
    loop.boundary_loop = loop_index;
    int cur = i;
    int guard = 0;
    const int limit = 4 * nf + 4 + static_cast<int>(boundary.size());
    while (cur >= 0 && !visited[cur] && guard++ <= limit) {
      visited[cur] = 1;
      auto [f, k] = boundary[cur];
      int ff = f, kk = (k + 1) % static_cast<int>(p.faces[f].size());
      for (int steps = 0; steps < 4 * nf + 4; ++steps) {
        const auto& fc = p.faces[ff];
        const int mm = static_cast<int>(fc.size());
        const int e = find_edge(fc[kk], fc[(kk + 1) % mm]);
        if (!t.edge_is_hinge[e]) break;
        const int side = t.edge_faces[e][0] == ff ? 1 : 0;
        const int other = t.edge_faces[e][side];
        const int head = fc[kk];
        // Crossing back over the hinge just crossed cancels it (T_e(theta) T_e(theta)^-1 = I).
        if (!loop.steps.empty() && loop.steps.back().edge == e) loop.steps.pop_back();
        else loop.steps.push_back(HoleStep{e, side});
        const auto& oc = p.faces[other];
        ff = other;
        kk = static_cast<int>(std::find(oc.begin(), oc.end(), head) - oc.begin());
      }
      auto it = boundary_index.find(pair_key(ff, kk));
      cur = it == boundary_index.end() ? -1 : it->second;
    }
    if (loops_seen[loop.component]++ == 0) continue;  // the component's first loop is its outer one
    if (loop.steps.empty()) continue;
    loop.faces.push_back(loop.base_face);
    for (std::size_t s = 0; s + 1 < loop.steps.size(); ++s)
      loop.faces.push_back(t.edge_faces[loop.steps[s].edge][loop.steps[s].side]);
    out.push_back(std::move(loop));
  }
  return out;
}

void hole_closure_jacobian(const CreasePattern& p, const HoleLoop& loop, std::span<const double> theta,
                           double length_scale, Eigen::Matrix<double, 6, 1>& residual,
                           Eigen::Matrix<double, 6, Eigen::Dynamic>& jacobian) {
  Eigen::Matrix3Xd w, a;
  const Eigen::Isometry3d M = loop_product(p, loop, theta, &w, &a);
  const Eigen::Vector3d c = face_centroid(p, loop.base_face);
  const Eigen::Vector3d Mc = M * c;
  const Eigen::Vector3d phi = so3_log(M.linear());
  residual.head<3>() = phi;
  residual.tail<3>() = (Mc - c) / length_scale;
  const Eigen::Matrix3d Jinv = so3_left_jacobian_inverse(phi);
  const int m = static_cast<int>(loop.steps.size());
  jacobian.resize(6, m);
  for (int i = 0; i < m; ++i) {
    jacobian.block<3, 1>(0, i) = Jinv * w.col(i);
    jacobian.block<3, 1>(3, i) = w.col(i).cross(Mc - a.col(i)) / length_scale;
  }
}

Eigen::Matrix<double, 6, 1> hole_closure_residual(const CreasePattern& p, const HoleLoop& loop,
                                                  std::span<const double> theta, double length_scale) {
  const Eigen::Isometry3d M = loop_product(p, loop, theta, nullptr, nullptr);
  const Eigen::Vector3d c = face_centroid(p, loop.base_face);
  Eigen::Matrix<double, 6, 1> r;
  r.head<3>() = so3_log(M.linear());
  r.tail<3>() = (M * c - c) / length_scale;
  return r;
}

}  // namespace rigidfold
