#include "kernel/thick/thick_closure_system.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel/math/so3.hpp"

namespace rigidfold {

Eigen::Isometry3d thick_loop_product(const ThickLoop& loop, const Eigen::VectorXd& joint_angles) {
  if (joint_angles.size() != static_cast<Eigen::Index>(loop.joints.size()))
    throw std::invalid_argument("thick loop: expected one angle per joint");
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  for (std::size_t i = 0; i < loop.joints.size(); ++i) M = M * dh_transform(joint_angles[i], loop.joints[i].link);
  return M;
}

void thick_loop_closure(const ThickLoop& loop, const Eigen::VectorXd& joint_angles, double length_scale,
                        Eigen::Matrix<double, 6, 1>& residual, Eigen::Matrix<double, 6, Eigen::Dynamic>* jacobian) {
  const int n = static_cast<int>(loop.joints.size());
  if (joint_angles.size() != n) throw std::invalid_argument("thick loop: expected one angle per joint");
  Eigen::Matrix3Xd axis(3, n), point(3, n);
  Eigen::Isometry3d P = Eigen::Isometry3d::Identity();
  for (int i = 0; i < n; ++i) {
    axis.col(i) = P.linear().col(2);  // joint i turns about z of frame i
    point.col(i) = P.translation();
    P = P * dh_transform(joint_angles[i], loop.joints[i].link);
  }
  const Eigen::Vector3d rotation = so3_log(P.linear());
  const Eigen::Vector3d end = P.translation();
  residual.head<3>() = rotation;
  residual.tail<3>() = end / length_scale;
  if (!jacobian) return;
  const Eigen::Matrix3d log_inverse = so3_left_jacobian_inverse(rotation);
  jacobian->resize(6, n);
  for (int i = 0; i < n; ++i) {
    jacobian->block<3, 1>(0, i) = log_inverse * axis.col(i);
    jacobian->block<3, 1>(3, i) = axis.col(i).cross(end - point.col(i)) / length_scale;
  }
}

ThickClosureSystem::ThickClosureSystem(ThickPattern pattern, const ThickClosureOptions& options)
    : pattern_(std::move(pattern)) {
  const int nc = pattern_.num_creases;
  if (nc < 0) throw std::invalid_argument("thick closure: negative crease count");
  double largest = 0.0;
  for (std::size_t k = 0; k < pattern_.loops.size(); ++k) {
    const ThickLoop& loop = pattern_.loops[k];
    const std::string where = "thick closure: loop " + std::to_string(k) + (loop.name.empty() ? "" : " (" + loop.name + ")");
    if (loop.joints.size() < 2) throw std::invalid_argument(where + " has fewer than 2 joints");
    for (std::size_t j = 0; j < loop.joints.size(); ++j) {
      const ThickJoint& joint = loop.joints[j];
      if (joint.crease < 0 || joint.crease >= nc)
        throw std::invalid_argument(where + ": joint " + std::to_string(j) + " on crease " +
                                    std::to_string(joint.crease) + " (" + std::to_string(nc) + " creases)");
      if (joint.angle_sign != 1.0 && joint.angle_sign != -1.0)
        throw std::invalid_argument(where + ": joint " + std::to_string(j) + " angle_sign must be +1 or -1");
      largest = std::max({largest, std::abs(joint.link.length), std::abs(joint.link.offset)});
    }
  }
  length_scale_ = largest > 0.0 ? largest : 1.0;
  fixed_value_.assign(nc, 0.0);
  std::vector<bool> fixed(nc, false);
  for (const auto& [c, value] : options.fixed) {
    if (c < 0 || c >= nc) throw std::invalid_argument("thick closure: fixed crease " + std::to_string(c) + " out of range");
    if (fixed[c]) throw std::invalid_argument("thick closure: crease " + std::to_string(c) + " fixed twice");
    fixed[c] = true;
    fixed_value_[c] = value;
  }
  unknown_of_crease_.assign(nc, -1);
  for (int c = 0; c < nc; ++c)
    if (!fixed[c]) {
      unknown_of_crease_[c] = static_cast<int>(free_creases_.size());
      free_creases_.push_back(c);
    }
}

Eigen::VectorXd ThickClosureSystem::creases_from_unknowns(const Eigen::VectorXd& x) const {
  if (x.size() != num_unknowns()) throw std::invalid_argument("thick closure: wrong number of unknowns");
  Eigen::VectorXd rho = Eigen::Map<const Eigen::VectorXd>(fixed_value_.data(), pattern_.num_creases);
  for (int k = 0; k < num_unknowns(); ++k) rho[free_creases_[k]] = x[k];
  return rho;
}

Eigen::VectorXd ThickClosureSystem::unknowns_from_creases(const Eigen::VectorXd& crease_angles) const {
  if (crease_angles.size() != pattern_.num_creases) throw std::invalid_argument("thick closure: wrong number of creases");
  Eigen::VectorXd x(num_unknowns());
  for (int k = 0; k < num_unknowns(); ++k) x[k] = crease_angles[free_creases_[k]];
  return x;
}

Eigen::VectorXd ThickClosureSystem::loop_joint_angles(const ThickLoop& loop, const Eigen::VectorXd& rho) const {
  Eigen::VectorXd theta(loop.joints.size());
  for (std::size_t i = 0; i < loop.joints.size(); ++i) theta[i] = joint_angle(loop.joints[i], rho[loop.joints[i].crease]);
  return theta;
}

Eigen::VectorXd ThickClosureSystem::residual(const Eigen::VectorXd& x) const {
  const Eigen::VectorXd rho = creases_from_unknowns(x);
  Eigen::VectorXd r(num_rows());
  Eigen::Matrix<double, 6, 1> block;
  for (std::size_t k = 0; k < pattern_.loops.size(); ++k) {
    thick_loop_closure(pattern_.loops[k], loop_joint_angles(pattern_.loops[k], rho), length_scale_, block, nullptr);
    r.segment<6>(6 * k) = block;
  }
  return r;
}

void ThickClosureSystem::evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::SparseMatrix<double>& J) const {
  const Eigen::VectorXd rho = creases_from_unknowns(x);
  r.resize(num_rows());
  // Every (loop row block, crease) pair that a free joint touches gets 6 stored entries,
  // whatever their values, so the pattern is the same at every x. A crease met twice in
  // one loop sums its two columns.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::Matrix<double, 6, 1> block;
  Eigen::Matrix<double, 6, Eigen::Dynamic> loop_jacobian;
  for (std::size_t k = 0; k < pattern_.loops.size(); ++k) {
    const ThickLoop& loop = pattern_.loops[k];
    thick_loop_closure(loop, loop_joint_angles(loop, rho), length_scale_, block, &loop_jacobian);
    r.segment<6>(6 * k) = block;
    for (std::size_t j = 0; j < loop.joints.size(); ++j) {
      const int u = unknown_of_crease_[loop.joints[j].crease];
      if (u < 0) continue;
      for (int row = 0; row < 6; ++row)
        entries.emplace_back(static_cast<int>(6 * k) + row, u, loop.joints[j].angle_sign * loop_jacobian(row, j));
    }
  }
  J.resize(num_rows(), num_unknowns());
  J.setFromTriplets(entries.begin(), entries.end());  // duplicates are summed
  J.makeCompressed();
}

}  // namespace rigidfold
