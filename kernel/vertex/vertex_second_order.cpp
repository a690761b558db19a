#include "kernel/vertex/vertex_second_order.hpp"

#include <stdexcept>

#include "kernel/math/so3.hpp"

namespace rigidfold {

Eigen::Vector3d vertex_closure_second_derivative(std::span<const double> sectors,
                                                 std::span<const double> fold_angles,
                                                 std::span<const double> direction) {
  const std::size_t n = sectors.size();
  if (n == 0 || fold_angles.size() != n || direction.size() != n)
    throw std::invalid_argument("vertex_closure_second_derivative: sectors, fold angles and direction need the same size > 0");
  // X = [e_x]x commutes with Rx, so d/ds Rx(rho + s t) = t X Rx and the second derivative is t^2 X^2 Rx.
  const Eigen::Matrix3d X = skew(Eigen::Vector3d::UnitX());
  const Eigen::Matrix3d X2 = X * X;
  // Running product P and its first two derivatives in s (product rule, one factor at a time).
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity(), P1 = Eigen::Matrix3d::Zero(), P2 = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Matrix3d A = rot_x(fold_angles[i]) * rot_z(sectors[i]);
    const Eigen::Matrix3d A1 = direction[i] * (X * A);
    const Eigen::Matrix3d A2 = (direction[i] * direction[i]) * (X2 * A);
    P2 = P2 * A + 2.0 * P1 * A1 + P * A2;
    P1 = P1 * A + P * A1;
    P = P * A;
  }
  return skew_part_vector(P2);
}

}  // namespace rigidfold
