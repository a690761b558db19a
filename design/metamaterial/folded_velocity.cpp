#include "design/metamaterial/folded_velocity.hpp"

#include <deque>
#include <limits>
#include <stdexcept>

namespace rigidfold::metamaterial {

FoldedVelocity folded_velocity(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& rho,
                               const Eigen::VectorXd& rho_dot, const Eigen::VectorXd& reference_angles,
                               int root_face) {
  const int nf = p.num_faces(), ne = p.num_edges();
  if (rho.size() != ne || rho_dot.size() != ne || reference_angles.size() != ne)
    throw std::invalid_argument("folded_velocity: rho, rho_dot and reference angles need one entry per edge");
  if (root_face < 0 || root_face >= nf) throw std::invalid_argument("folded_velocity: root face out of range");

  FoldedVelocity out;
  out.face_motions.assign(nf, Eigen::Isometry3d::Identity());
  out.face_omega.assign(nf, Eigen::Vector3d::Zero());
  out.face_v.assign(nf, Eigen::Vector3d::Zero());
  std::vector<std::vector<int>> face_hinges(nf);
  for (int e = 0; e < ne; ++e)
    if (t.edge_is_hinge[e]) {
      face_hinges[t.edge_faces[e][0]].push_back(e);
      face_hinges[t.edge_faces[e][1]].push_back(e);
    }
  std::vector<char> placed(nf, 0);
  std::vector<int> order;
  placed[root_face] = 1;
  std::deque<int> queue{root_face};
  while (!queue.empty()) {
    const int f = queue.front();
    queue.pop_front();
    order.push_back(f);
    for (int e : face_hinges[f]) {
      const bool child_is_left = t.edge_faces[e][0] != f;
      const int child = t.edge_faces[e][child_is_left ? 0 : 1];
      if (placed[child]) continue;
      placed[child] = 1;
      const double sign = child_is_left ? 1.0 : -1.0;
      const double beta = sign * (rho[e] - reference_angles[e]);
      const double beta_dot = sign * rho_dot[e];
      const Eigen::Vector3d a = p.vertices[p.edges[e][0]];
      const Eigen::Vector3d d = (p.vertices[p.edges[e][1]] - a).normalized();
      // Hinge motion in reference coordinates: rotate by beta about the line (a, d).
      Eigen::Isometry3d h = Eigen::Isometry3d::Identity();
      h.translate(a);
      h.rotate(Eigen::AngleAxisd(beta, d));
      h.translate(-a);
      const Eigen::Isometry3d& parent = out.face_motions[f];
      out.face_motions[child] = parent * h;
      // The folded axis: carried by the parent.
      const Eigen::Vector3d a_folded = parent * a;
      const Eigen::Vector3d d_folded = parent.linear() * d;
      out.face_omega[child] = out.face_omega[f] + beta_dot * d_folded;
      out.face_v[child] = out.face_v[f] + beta_dot * a_folded.cross(d_folded);
      queue.push_back(child);
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.positions.assign(p.num_vertices(), Eigen::Vector3d::Constant(nan));
  out.velocities.assign(p.num_vertices(), Eigen::Vector3d::Constant(nan));
  std::vector<char> done(p.num_vertices(), 0);
  for (int f : order)
    for (int v : p.faces[f])
      if (!done[v]) {
        done[v] = 1;
        const Eigen::Vector3d x = out.face_motions[f] * p.vertices[v];
        out.positions[v] = x;
        out.velocities[v] = out.face_omega[f].cross(x) + out.face_v[f];
      }
  return out;
}

}  // namespace rigidfold::metamaterial
