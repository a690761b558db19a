#include "kernel/math/so3.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace rigidfold {

Eigen::Matrix3d rot_x(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << 1.0, 0.0, 0.0,
       0.0, c, -s,
       0.0, s, c;
  return R;
}

Eigen::Matrix3d rot_z(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  R << c, -s, 0.0,
       s, c, 0.0,
       0.0, 0.0, 1.0;
  return R;
}

Eigen::Matrix3d rotation_about(const Eigen::Vector3d& unit_axis, double angle) {
  return Eigen::AngleAxisd(angle, unit_axis).toRotationMatrix();
}

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d K;
  K << 0.0, -w.z(), w.y(),
       w.z(), 0.0, -w.x(),
       -w.y(), w.x(), 0.0;
  return K;
}

Eigen::Vector3d skew_part_vector(const Eigen::Matrix3d& M) {
  return Eigen::Vector3d(0.5 * (M(2, 1) - M(1, 2)), 0.5 * (M(0, 2) - M(2, 0)), 0.5 * (M(1, 0) - M(0, 1)));
}

Eigen::Matrix3d so3_exp(const Eigen::Vector3d& w) {
  const double t = w.norm();
  if (t == 0) return Eigen::Matrix3d::Identity();
  return rotation_about(w / t, t);
}

Eigen::Vector3d so3_log(const Eigen::Matrix3d& R) {
  // Skew part gives sin(t) * axis, trace gives cos(t); atan2 of the two is accurate for
  // every t in [0, pi], unlike acos near 0 or asin near pi/2.
  const Eigen::Vector3d v = skew_part_vector(R);
  const double s = v.norm();
  const double c = 0.5 * (R.trace() - 1.0);
  const double t = std::atan2(s, c);

  if (c >= 0.0) {
    // t <= pi/2: the skew part carries the axis with full relative precision.
    if (s == 0.0) return Eigen::Vector3d::Zero();
    return (t / s) * v;  // t/s -> 1 as t -> 0, no cancellation
  }
  // t > pi/2: sin(t) gets small, so take the axis from the symmetric part,
  // (R + R^T)/2 - cos(t) I = (1 - cos t) a a^T, using its largest column.
  Eigen::Matrix3d B = 0.5 * (R + R.transpose());
  B.diagonal().array() -= c;
  int k = 0;
  B.diagonal().maxCoeff(&k);
  Eigen::Vector3d a = B.col(k).normalized();
  if (a.dot(v) < 0.0) a = -a;  // the skew part fixes the sign (ambiguous only at t = pi)
  return t * a;
}

Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& w) {
  const double t = w.norm();
  const Eigen::Matrix3d W = skew(w);
  if (t < 1e-6) return Eigen::Matrix3d::Identity() + 0.5 * W + W * W / 6.0;
  return Eigen::Matrix3d::Identity() + (1 - std::cos(t)) / (t * t) * W + (t - std::sin(t)) / (t * t * t) * W * W;
}

Eigen::Matrix3d so3_left_jacobian_inverse(const Eigen::Vector3d& phi) {
  const double t = phi.norm();
  double coeff;  // 1/t^2 - cot(t/2) / (2 t)
  if (t < 0.1) {
    // Series of the coefficient; the closed form cancels catastrophically near 0.
    const double t2 = t * t;
    coeff = 1.0 / 12.0 + t2 * (1.0 / 720.0 + t2 * (1.0 / 30240.0 + t2 * (1.0 / 1209600.0)));
  } else {
    coeff = 1.0 / (t * t) - std::cos(0.5 * t) / (2.0 * t * std::sin(0.5 * t));
  }
  const Eigen::Matrix3d K = skew(phi);
  return Eigen::Matrix3d::Identity() - 0.5 * K + coeff * (K * K);
}

double orthonormality_error(const Eigen::Matrix3d& R) {
  return (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
}

}  // namespace rigidfold
