#include "design/strings/string_kinematics.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel/math/so3.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::design {

StringPose pattern_pose(double theta0) {
  StringPose p;
  p.frame = rot_x(-theta0);
  return p;
}

namespace {

StringState chain(const MiuraString& s, const std::vector<double>& theta, const StringPose& pose, ThetaMode mode) {
  validate_string(s, /*check_width=*/false);
  const int n = s.size();
  if (static_cast<int>(theta.size()) != n) throw std::invalid_argument("theta: needs one value per vertex");
  StringState st;
  st.mode = mode;
  st.theta = theta;
  st.vertices.reserve(n);
  st.frames.reserve(n + 1);
  st.spine.reserve(n + 2);
  st.min_theta_margin = 1e300;
  Eigen::Matrix3d F = pose.frame;
  Eigen::Vector3d p = pose.start;
  st.frames.push_back(F);
  st.spine.push_back(p);
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(theta[i])) throw std::invalid_argument("theta[" + std::to_string(i) + "]: must be finite");
    const double limit = string_theta_limit(s.alpha1[i], s.alpha2[i]);
    const double margin = limit - std::fabs(theta[i]);
    if (!(margin > 0))
      throw std::invalid_argument("theta[" + std::to_string(i) + "]: |theta| = " + std::to_string(std::fabs(theta[i])) +
                                  " rad reaches the vertex's theta limit " + std::to_string(limit) + " rad");
    const StringVertexState v = string_vertex_state(s.alpha1[i], s.alpha2[i], theta[i]);
    if (margin < st.min_theta_margin) {
      st.min_theta_margin = margin;
      st.limiting_vertex = i;
    }
    p += s.lengths[i] * F.col(0);  // segment s_i along the frame of crease s_i
    st.spine.push_back(p);
    F = F * v.rotation;
    st.frames.push_back(F);
    st.vertices.push_back(v);
  }
  st.spine.push_back(p + s.lengths[n] * F.col(0));
  // Fold angles per edge (numbering of build_string_pattern).
  const StringPatternIndex ix{n};
  // 3n + 1 creases, then the boundary: 2 (left) + (n + 1) (top) + 2 (right) + (n + 1) (bottom), all 0.
  st.edge_fold_angles = Eigen::VectorXd::Zero(3 * n + 1 + 2 * n + 6);
  for (int i = 0; i < n; ++i) {
    st.edge_fold_angles[ix.spinal_edge(i)] = st.vertices[i].rho_c;
    st.edge_fold_angles[ix.top_edge(i)] = st.vertices[i].rho_b;
    st.edge_fold_angles[ix.bottom_edge(i)] = st.vertices[i].rho_d;
    if (i > 0)
      st.shared_crease_mismatch = std::max(st.shared_crease_mismatch, std::fabs(st.vertices[i - 1].rho_a - st.vertices[i].rho_c));
  }
  st.edge_fold_angles[ix.spinal_edge(n)] = st.vertices[n - 1].rho_a;
  return st;
}

}  // namespace

StringState string_forward(const MiuraString& s, double theta0, const StringPose& pose) {
  std::vector<double> theta(s.size());
  for (int i = 0; i < s.size(); ++i) theta[i] = i % 2 == 0 ? theta0 : -theta0;  // theta_out = -theta: exact transmission
  return chain(s, theta, pose, ThetaMode::Transmitted);
}

StringState string_forward(const MiuraString& s, double theta0) { return string_forward(s, theta0, pattern_pose(theta0)); }

StringState string_forward_independent(const MiuraString& s, const std::vector<double>& theta, const StringPose& pose) {
  return chain(s, theta, pose, ThetaMode::Independent);
}

StringState string_forward_independent(const MiuraString& s, const std::vector<double>& theta) {
  return string_forward_independent(s, theta, pattern_pose(theta.empty() ? 0.0 : theta[0]));
}

FoldedGeometry fold_string_pattern(const CreasePattern& pattern, const StringState& state) {
  const Topology topo = build_topology(pattern, "string pattern");
  if (state.edge_fold_angles.size() != pattern.num_edges())
    throw std::invalid_argument("fold_string_pattern: the state does not belong to this pattern");
  return place_faces(pattern, topo, state.edge_fold_angles, Eigen::VectorXd::Zero(pattern.num_edges()));
}

}  // namespace rigidfold::design
