#include "kernel/thick/thick_sheet.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel/geometry/fold_angles.hpp"
#include "kernel/thick/thick_closure_system.hpp"

namespace rigidfold {

Eigen::VectorXd ThickSheet::edge_angles_from_creases(const Eigen::VectorXd& rho) const {
  Eigen::VectorXd edges = reference_edge_angles;
  for (std::size_t c = 0; c < edge_of_crease.size(); ++c)
    edges[edge_of_crease[c]] += factor[c] * (rho[c] - reference_creases[c]);
  return edges;
}

Eigen::VectorXd ThickSheet::creases_from_edge_angles(const Eigen::VectorXd& edges) const {
  Eigen::VectorXd rho(edge_of_crease.size());
  for (std::size_t c = 0; c < edge_of_crease.size(); ++c)
    rho[c] = reference_creases[c] + factor[c] * (edges[edge_of_crease[c]] - reference_edge_angles[edge_of_crease[c]]);
  return rho;
}

ThickSheet thick_sheet_from_loop(const ThickPattern& thick, const Eigen::VectorXd& closed_creases, double closure_tolerance) {
  if (thick.loops.size() != 1) throw std::invalid_argument("thick sheet: needs exactly one loop, got " + std::to_string(thick.loops.size()));
  const ThickLoop& loop = thick.loops[0];
  const int n = static_cast<int>(loop.joints.size());
  if (n != thick.num_creases) throw std::invalid_argument("thick sheet: every crease must be one joint of the loop");
  std::vector<bool> seen(n, false);
  for (const ThickJoint& j : loop.joints) {
    if (j.crease < 0 || j.crease >= n || seen[j.crease]) throw std::invalid_argument("thick sheet: a crease is used twice or out of range");
    seen[j.crease] = true;
  }
  const ThickClosureSystem system(thick);
  const double gap = system.residual(closed_creases).cwiseAbs().maxCoeff();
  if (!(gap <= closure_tolerance))
    throw std::invalid_argument("thick sheet: the loop does not close at the given state (residual " + std::to_string(gap) + ")");

  // Frames of the joints at the closed state: joint i turns about z of frame i.
  std::vector<Eigen::Isometry3d> frame(n);
  Eigen::Isometry3d P = Eigen::Isometry3d::Identity();
  for (int i = 0; i < n; ++i) {
    frame[i] = P;
    P = P * dh_transform(joint_angle(loop.joints[i], closed_creases[loop.joints[i].crease]), loop.joints[i].link);
  }
  // Hinge segment of joint i: on its axis, beside the stretch between the feet of the two
  // common normals (o_i and o_i + d_i z_i), so that two hinges whose axes meet (a = 0) do
  // not share a point and the panel between them is a proper trapezoid.
  const double h = system.length_scale();
  ThickSheet sheet;
  CreasePattern& p = sheet.pattern;
  p.coords_2d = false;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d o = frame[i].translation(), z = frame[i].linear().col(2);
    const double middle = 0.5 * loop.joints[i].link.offset;
    p.vertices.push_back(o + (middle + h) * z);        // inner end, vertex 2i
    p.vertices.push_back(o + (middle + 2.0 * h) * z);  // outer end, vertex 2i+1
  }
  auto inner = [&](int i) { return 2 * (i % n); };
  auto outer = [&](int i) { return 2 * (i % n) + 1; };
  for (int i = 0; i < n; ++i) {
    p.edges.push_back({inner(i), outer(i)});
    p.assignments.push_back(Assignment::Unassigned);
  }
  for (int i = 0; i < n; ++i) {
    p.edges.push_back({outer(i), outer(i + 1)});
    p.assignments.push_back(Assignment::Boundary);
    p.edges.push_back({inner(i + 1), inner(i)});
    p.assignments.push_back(Assignment::Boundary);
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  for (int i = 0; i < n; ++i) p.faces.push_back({inner(i), outer(i), outer(i + 1), inner(i + 1)});  // panel after joint i
  sheet.topology = build_topology(p, "thick sheet");
  sheet.options.close_holes = true;
  sheet.reference_edge_angles = reference_fold_angles(p, sheet.topology);
  sheet.reference_creases = closed_creases;
  sheet.edge_of_crease.assign(n, -1);
  sheet.factor.assign(n, 0.0);
  // Across hinge i the panel after joint i turns relative to the panel before it by
  // Delta theta_i about +z_i (= the hinge's v0 -> v1 direction). A FOLD fold angle turns the
  // face on the left of v0 -> v1 by +Delta rho relative to the right one (hinge_motion), so
  // Delta rho = +Delta theta when the panel after joint i is the left face, else -Delta theta;
  // and Delta theta = angle_sign * Delta rho_c.
  for (int i = 0; i < n; ++i) {
    const ThickJoint& j = loop.joints[i];
    const int after = i;  // face index of the panel after joint i
    const double side = sheet.topology.edge_faces[i][0] == after ? 1.0 : -1.0;
    sheet.edge_of_crease[j.crease] = i;
    sheet.factor[j.crease] = side * j.angle_sign;
  }
  return sheet;
}

}  // namespace rigidfold
