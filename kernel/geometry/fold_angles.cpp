#include "kernel/geometry/fold_angles.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace rigidfold {

Eigen::VectorXd reference_fold_angles(const CreasePattern& p, const Topology& t) {
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) {
    if (!t.edge_is_hinge[e]) continue;
    // Equal normals (every hinge of a flat sheet): the atan2 below would give exactly 0.
    if (t.face_normals[t.edge_faces[e][0]] == t.face_normals[t.edge_faces[e][1]]) continue;
    const Eigen::Vector3d d = (p.vertices[p.edges[e][1]] - p.vertices[p.edges[e][0]]).normalized();
    const Eigen::Vector3d& n_left = t.face_normals[t.edge_faces[e][0]];
    const Eigen::Vector3d& n_right = t.face_normals[t.edge_faces[e][1]];
    const double s = n_right.cross(n_left).dot(d), c = n_right.dot(n_left);
    if (std::fabs(s) < 1e-12 && c < 0) {  // flat-folded: the sign is not in the geometry
      double sign = 1.0;
      if (p.fold_angles[e]) sign = *p.fold_angles[e] < 0 ? -1.0 : 1.0;
      else if (p.assignments[e] == Assignment::Mountain) sign = -1.0;
      rho[e] = sign * std::numbers::pi;
    } else {
      rho[e] = std::atan2(s, c);
    }
  }
  return rho;
}

Eigen::VectorXd fold_angle_vector(const std::vector<std::optional<double>>& angles) {
  Eigen::VectorXd rho(static_cast<Eigen::Index>(angles.size()));
  for (std::size_t e = 0; e < angles.size(); ++e) rho[static_cast<Eigen::Index>(e)] = angles[e].value_or(0.0);
  return rho;
}

Eigen::VectorXd stored_fold_angles(const CreasePattern& p) { return fold_angle_vector(p.fold_angles); }

}  // namespace rigidfold
