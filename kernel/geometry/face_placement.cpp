#include "kernel/geometry/face_placement.hpp"

#include <cmath>

#include "kernel/math/so3.hpp"

namespace rigidfold {

Eigen::Isometry3d hinge_motion(const CreasePattern& p, int e, int side, double angle) {
  const Eigen::Vector3d a = p.vertices[p.edges[e][0]];
  const Eigen::Vector3d d = (p.vertices[p.edges[e][1]] - a).normalized();
  const double signed_angle = side == 0 ? angle : -angle;
  // Rotation R about the line through a: x -> R x + (a - R a), written out rather than as
  // three transform products.
  Eigen::Isometry3d m;
  m.linear() = rotation_about(d, signed_angle);
  m.translation() = a - m.linear() * a;
  m.makeAffine();
  return m;
}

FoldedGeometry place_faces(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& rho,
                           const Eigen::VectorXd& rho_ref, bool with_vertices) {
  const int nf = p.num_faces();
  FoldedGeometry g;
  g.face_motions.assign(nf, Eigen::Isometry3d::Identity());
  Eigen::Vector3d lo = p.vertices[0], hi = p.vertices[0];
  for (const auto& v : p.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  g.pattern_size = std::max((hi - lo).norm(), 1e-300);

  // Hinges of each face, ascending, in one array: face f's are hinges[start[f] .. start[f + 1]).
  std::vector<int> start(nf + 1, 0);
  for (int e = 0; e < p.num_edges(); ++e)
    if (t.edge_is_hinge[e]) {
      ++start[t.edge_faces[e][0] + 1];
      ++start[t.edge_faces[e][1] + 1];
    }
  for (int f = 0; f < nf; ++f) start[f + 1] += start[f];
  std::vector<int> hinges(start[nf]);
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (int e = 0; e < p.num_edges(); ++e)
      if (t.edge_is_hinge[e]) {
        hinges[next[t.edge_faces[e][0]]++] = e;
        hinges[next[t.edge_faces[e][1]]++] = e;
      }
  }
  std::vector<char> placed(nf, 0), tree_edge(p.num_edges(), 0);
  // Breadth-first over the face graph; `order` is its own queue (faces at [head, end) wait).
  std::vector<int> order;
  order.reserve(nf);
  for (int root = 0; root < nf; ++root) {
    if (placed[root]) continue;
    placed[root] = 1;
    std::size_t head = order.size();
    order.push_back(root);
    while (head < order.size()) {
      const int f = order[head++];
      for (int i = start[f]; i < start[f + 1]; ++i) {
        const int e = hinges[i];
        const int side_child = t.edge_faces[e][0] == f ? 1 : 0;
        const int child = t.edge_faces[e][side_child];
        if (placed[child]) continue;
        placed[child] = 1;
        tree_edge[e] = 1;
        g.face_motions[child] = g.face_motions[f] * hinge_motion(p, e, side_child, rho[e] - rho_ref[e]);
        order.push_back(child);
      }
    }
  }
  double max_mismatch2 = 0.0;  // squared distances, one square root at the end
  for (int e = 0; e < p.num_edges(); ++e) {
    if (!t.edge_is_hinge[e] || tree_edge[e]) continue;
    ++g.non_tree_hinges;
    const int left = t.edge_faces[e][0], right = t.edge_faces[e][1];
    const Eigen::Isometry3d expected = g.face_motions[right] * hinge_motion(p, e, 0, rho[e] - rho_ref[e]);
    // Where the two motions put v differ by (E - L) v + (e - l): one difference of the
    // motions, applied to each vertex (no cancellation of two large positions).
    const Eigen::Matrix3d linear_gap = expected.linear() - g.face_motions[left].linear();
    const Eigen::Vector3d translation_gap = expected.translation() - g.face_motions[left].translation();
    for (int v : p.faces[left]) {
      const double d2 = (linear_gap * p.vertices[v] + translation_gap).squaredNorm();
      // A NaN (from a NaN fold angle) is the worst mismatch and stays: no certificate passes on it.
      if (d2 > max_mismatch2 || (std::isnan(d2) && !std::isnan(max_mismatch2))) {
        max_mismatch2 = d2;
        g.worst_edge = e;
      }
    }
  }
  g.max_mismatch = std::sqrt(max_mismatch2);  // the largest distance: sqrt is monotone and correctly rounded
  if (!with_vertices) return g;
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
