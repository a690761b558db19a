#include "kernel/vertex/vertex_closure.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rigidfold {

namespace {

void check_sizes(std::span<const double> sectors, std::span<const double> fold_angles) {
  if (sectors.size() != fold_angles.size()) {
    throw std::invalid_argument("vertex closure: " + std::to_string(sectors.size()) +
                                " sectors but " + std::to_string(fold_angles.size()) +
                                " fold angles");
  }
  if (sectors.empty()) throw std::invalid_argument("vertex closure: vertex of degree 0");
}

// P <- P * Rx(angle), touching only the two columns that change.
void right_multiply_rot_x(Eigen::Matrix3d& P, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector3d c1 = P.col(1), c2 = P.col(2);
  P.col(1) = c * c1 + s * c2;
  P.col(2) = -s * c1 + c * c2;
}

// P <- P * Rz(angle).
void right_multiply_rot_z(Eigen::Matrix3d& P, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector3d c0 = P.col(0), c1 = P.col(1);
  P.col(0) = c * c0 + s * c1;
  P.col(1) = -s * c0 + c * c1;
}

}  // namespace

Eigen::Matrix3d vertex_loop_product(std::span<const double> sectors,
                                    std::span<const double> fold_angles) {
  check_sizes(sectors, fold_angles);
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i < sectors.size(); ++i) {
    right_multiply_rot_x(P, fold_angles[i]);
    right_multiply_rot_z(P, sectors[i]);
  }
  return P;
}

Eigen::Vector3d vertex_closure_residual(std::span<const double> sectors,
                                        std::span<const double> fold_angles) {
  return so3_log(vertex_loop_product(sectors, fold_angles));
}

void vertex_closure_jacobian(std::span<const double> sectors,
                             std::span<const double> fold_angles,
                             Eigen::Vector3d& residual,
                             Eigen::Matrix3Xd& jacobian,
                             Eigen::Matrix3Xd* axes) {
  check_sizes(sectors, fold_angles);
  const auto n = static_cast<Eigen::Index>(sectors.size());
  // Columns first hold the crease axes; the resize is a no-op when the caller reuses J,
  // so a solver sweeping many vertices does not allocate here.
  jacobian.resize(3, n);
  // P_i = prod_{j<i} Rx(rho_j) Rz(alpha_j); crease i's axis is P_i e_x (Rx(rho_i) fixes e_x).
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
  for (Eigen::Index i = 0; i < n; ++i) {
    jacobian.col(i) = P.col(0);
    right_multiply_rot_x(P, fold_angles[i]);
    right_multiply_rot_z(P, sectors[i]);
  }
  if (axes != nullptr) *axes = jacobian;
  residual = so3_log(P);
  const Eigen::Matrix3d Jinv = so3_left_jacobian_inverse(residual);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d u = jacobian.col(i);
    jacobian.col(i) = Jinv * u;
  }
}

}  // namespace rigidfold
