#include "kernel/thick/dh_link.hpp"

#include "kernel/math/so3.hpp"

namespace rigidfold {

Eigen::Isometry3d dh_transform(double joint_angle, const DhLink& link) {
  // Rz(theta) Tz(d) Tx(a) Rx(alpha): rotation Rz Rx, translation Rz (a, 0, d).
  const Eigen::Matrix3d turn = rot_z(joint_angle);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = turn * rot_x(link.twist);
  T.translation() = turn * Eigen::Vector3d(link.length, 0.0, link.offset);
  return T;
}

}  // namespace rigidfold
