#include "design/strings/string_vertex.hpp"

#include "kernel/vertex/miura_vertex.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace rigidfold::design {

double string_theta_limit(double alpha1, double alpha2) { return miura_theta_limit(alpha1, alpha2); }

StringVertexState string_vertex_state(double alpha1, double alpha2, double theta) {
  // The kernel's closed form (kernel/vertex/miura_vertex.hpp) for the double path; the
  // templated frame above is the same formula for automatic derivatives (tested equal).
  // Checked (closure residual, signs): a state that fails throws NoAnswerError, never returned.
  const MiuraVertexState m = miura_vertex_checked(alpha1, alpha2, theta);
  StringVertexState s;
  s.phi = m.phi;
  s.psi = m.psi;
  s.rotation = miura_vertex_rotation(alpha1, alpha2, theta);
  s.rho_a = m.fold_angles[kMiuraSpinalOut];
  s.rho_b = m.fold_angles[kMiuraPeripheral1];
  s.rho_c = m.fold_angles[kMiuraSpinalIn];
  s.rho_d = m.fold_angles[kMiuraPeripheral2];
  s.theta_out = s.rho_a / 2;
  s.theta_limit = m.theta_limit;
  return s;
}

bool string_vertex_inverse_direction(const Eigen::Vector3d& dir, double theta, double& alpha1, double& alpha2) {
  alpha1 = alpha2 = std::numeric_limits<double>::quiet_NaN();
  const double n = dir.norm();
  if (!(n > 0) || !std::isfinite(n) || !std::isfinite(theta)) return false;
  const Eigen::Vector3d a = dir / n;
  // 1 - a_x computed without cancellation from the other two components.
  const double yz2 = a.y() * a.y() + a.z() * a.z();
  if (!(yz2 > 0)) return false;
  const double one_minus_ax = a.x() > 0 ? yz2 / (1 + a.x()) : 1 - a.x();
  const double st = std::sin(theta), ct = std::cos(theta);
  const double cot1 = (a.y() * ct + a.z() * st) / one_minus_ax;
  const double cot2 = (-a.y() * ct + a.z() * st) / one_minus_ax;
  if (!(cot1 > 0) || !(cot2 > 0)) return false;
  alpha1 = std::atan(1 / cot1);
  alpha2 = std::atan(1 / cot2);
  return true;
}

bool string_vertex_inverse(double phi, double psi, double theta, double& alpha1, double& alpha2) {
  const double cp = std::cos(phi);
  return string_vertex_inverse_direction(Eigen::Vector3d(cp, cp * std::tan(psi), std::sin(phi)), theta, alpha1, alpha2);
}

}  // namespace rigidfold::design
