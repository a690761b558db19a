#include "kernel/geometry/face_placement.hpp"

#include <deque>

#include "kernel/math/so3.hpp"

namespace rigidfold {

Eigen::Isometry3d hinge_motion(const CreasePattern& p, int e, int side, double angle) {
  const Eigen::Vector3d a = p.vertices[p.edges[e][0]];
  const Eigen::Vector3d d = (p.vertices[p.edges[e][1]] - a).normalized();
  const double signed_angle = side == 0 ? angle : -angle;
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.translate(a);
  m.rotate(rotation_about(d, signed_angle));
  m.translate(-a);
  return m;
}

FoldedGeometry place_faces(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& rho,
                           const Eigen::VectorXd& rho_ref) {
  const int nf = p.num_faces();
  FoldedGeometry g;
  g.face_motions.assign(nf, Eigen::Isometry3d::Identity());
  Eigen::Vector3d lo = p.vertices[0], hi = p.vertices[0];
  for (const auto& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  g.pattern_size = std::max((hi - lo).norm(), 1e-300);

  // Hinges of each face.
  std::vector<std::vector<int>> face_hinges(nf);
  for (int e = 0; e < p.num_edges(); ++e)
    if (t.edge_is_hinge[e]) {
      face_hinges[t.edge_faces[e][0]].push_back(e);
      face_hinges[t.edge_faces[e][1]].push_back(e);
    }
  std::vector<char> placed(nf, 0), tree_edge(p.num_edges(), 0);
  std::vector<int> order;
  order.reserve(nf);
  for (int root = 0; root < nf; ++root) {
    if (placed[root]) continue;
    placed[root] = 1;
    std::deque<int> queue{root};
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      order.push_back(f);
      for (int e : face_hinges[f]) {
        const int side_child = t.edge_faces[e][0] == f ? 1 : 0;
        const int child = t.edge_faces[e][side_child];
        if (placed[child]) continue;
        placed[child] = 1;
        tree_edge[e] = 1;
        g.face_motions[child] = g.face_motions[f] * hinge_motion(p, e, side_child, rho[e] - rho_ref[e]);
        queue.push_back(child);
      }
    }
  }
  for (int e = 0; e < p.num_edges(); ++e) {
    if (!t.edge_is_hinge[e] || tree_edge[e]) continue;
    ++g.non_tree_hinges;
    const int left = t.edge_faces[e][0], right = t.edge_faces[e][1];
    const Eigen::Isometry3d expected = g.face_motions[right] * hinge_motion(p, e, 0, rho[e] - rho_ref[e]);
    for (int v : p.faces[left]) {
      const double d = (expected * p.vertices[v] - g.face_motions[left] * p.vertices[v]).norm();
      if (d > g.max_mismatch) {
        g.max_mismatch = d;
        g.worst_edge = e;
      }
    }
  }
  g.vertices = p.vertices;
  std::vector<char> done(p.num_vertices(), 0);
  for (int f : order)
    for (int v : p.faces[f])
      if (!done[v]) {
        done[v] = 1;
        g.vertices[v] = g.face_motions[f] * p.vertices[v];
      }
  return g;
}

}  // namespace rigidfold
