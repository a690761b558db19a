#include "design/sorce/sorce_closure.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <array>
#include <cmath>
#include <string>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

Eigen::Matrix4d rot_y(double a) {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.block<3, 3>(0, 0) = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
  return T;
}

Eigen::Matrix<double, 6, 6> adjoint(const Eigen::Matrix4d& T) {
  const Eigen::Matrix3d R = T.block<3, 3>(0, 0);
  const Eigen::Vector3d p = T.block<3, 1>(0, 3);
  Eigen::Matrix3d px;
  px << 0, -p.z(), p.y(), p.z(), 0, -p.x(), -p.y(), p.x(), 0;
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  A.block<3, 3>(0, 0) = R;
  A.block<3, 3>(3, 3) = R;
  A.block<3, 3>(3, 0) = px * R;
  return A;
}

struct Joint {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  Eigen::Matrix<double, 6, 1> twist_rate = Eigen::Matrix<double, 6, 1>::Zero();  // dT/dt T^-1 as (omega, v)
  double dgamma = 0.0;
};

Joint joint(const FoldMotion& m, double t) {
  const Jet g = m.gamma(t), zl = m.z_left(t), zr = m.z_right(t);
  const VectorJet d = m.d ? m.d(t) : VectorJet{};
  const Eigen::Vector3d a(d[0][0], d[1][0] - zl[0], 0.0), da(d[0][1], d[1][1] - zl[1], 0.0);
  const Eigen::Vector3d b(0.0, zr[0], 0.0), db(0.0, zr[1], 0.0);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(g[0], Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Joint j;
  j.T.block<3, 3>(0, 0) = R;
  j.T.block<3, 1>(0, 3) = a + R * b;
  // T = [R, a + R b]: dT T^-1 = [gamma' [e_z]x, a' + R b' - gamma' e_z x a].
  const Eigen::Vector3d omega = g[1] * Eigen::Vector3d::UnitZ();
  j.twist_rate << omega, da + R * db - omega.cross(a);
  j.dgamma = g[1];
  return j;
}

}  // namespace

VertexClosure vertex_closure(const SorceVertex& v, double t, double rank_tolerance) {
  VertexClosure c;
  Eigen::Matrix4d P = Eigen::Matrix4d::Identity();
  Eigen::Vector4d rates;
  for (int j = 0; j < 4; ++j) {
    const Joint J = joint(v.folds[j], t);
    if (J.dgamma == 0.0) throw InputError("t", "gamma'(t) = 0 on fold " + std::to_string(j + 1));
    c.jacobian.col(j) = adjoint(P) * J.twist_rate / J.dgamma;
    rates[j] = J.dgamma;
    P = P * J.T * rot_y(v.sectors[j]);
  }
  c.product = P;
  c.error = (P - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff();
  // SVD of [J 0] (6x6, square, so without the QR preconditioner, in which GCC 12 finds a
  // maybe-uninitialized warning in Eigen): its two extra singular values are 0, last.
  // Dynamic size: the fixed-size SVD draws the same warning.
  Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(6, 6);
  padded.leftCols(4) = c.jacobian;
  Eigen::JacobiSVD<Eigen::MatrixXd, Eigen::NoQRPreconditioner> svd(padded);
  c.singular_values = svd.singularValues().head(4);
  for (int k = 0; k < 4; ++k)
    if (c.singular_values[k] <= rank_tolerance * c.singular_values[0]) ++c.nullity;
  c.rate_residual = (c.jacobian * rates).norm() / rates.norm();
  return c;
}

}  // namespace rigidfold::sorce
