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

Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d K;
  K << 0.0, -w.z(), w.y(),
       w.z(), 0.0, -w.x(),
       -w.y(), w.x(), 0.0;
  return K;
}

}  // namespace

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

Eigen::Vector3d so3_log(const Eigen::Matrix3d& R) {
  // Skew part gives sin(t) * axis, trace gives cos(t); atan2 of the two is accurate for
  // every t in [0, pi], unlike acos near 0 or asin near pi/2.
  const Eigen::Vector3d v(0.5 * (R(2, 1) - R(1, 2)), 0.5 * (R(0, 2) - R(2, 0)),
                          0.5 * (R(1, 0) - R(0, 1)));
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
