#pragma once
// SE(3) loop closure of a thick-panel pattern (thick_pattern.hpp): unknowns, residual and
// exact sparse Jacobian, in the same form as the zero-thickness ClosureSystem
// (kernel/closure/closure_system.hpp): num_unknowns(), num_rows(), residual(x),
// evaluate(x, r, J) with a Jacobian pattern that never changes.
//
// Unknowns x: fold angles rho (radians) of the creases that are not fixed, in increasing
//   crease order. Fixed creases enter as constants (ThickClosureOptions::fixed).
// Rows: 6 per loop, loop k in rows 6k .. 6k+5:
//   r[0..2] = so3_log(R_M)        (radians)
//   r[3..5] = p_M / length_scale  (dimensionless)
//   where M = prod_i T_i(theta_i) = [R_M, p_M] (dh_link.hpp) and p_M is where the loop takes
//   the origin of the first joint's frame; length_scale is the largest link length or
//   offset of the pattern (1 when all are 0), so both halves of the residual weigh alike.
// Jacobian (product of exponentials): with P_i = T_0 ... T_{i-1}, joint i turns about the
//   spatial axis w_i = R_{P_i} e_z through o_i = p_{P_i}, so dM/dtheta_i = [xi_i] M with
//   xi_i = (w_i, o_i x w_i), and
//     d r_rot / d theta_i   = Jl^{-1}(r_rot) w_i,
//     d r_trans / d theta_i = w_i x (p_M - o_i) / length_scale,
//   times angle_sign for d/d rho. Smooth while |r_rot| < pi.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "kernel/thick/thick_pattern.hpp"

namespace rigidfold {

struct ThickClosureOptions {
  std::vector<std::pair<int, double>> fixed;  // (crease, fold angle in radians) held at a value
};

// Residual (6) and 6 x n Jacobian with respect to the loop's joint angles theta_i (in joint
// order, not crease order) of one loop. length_scale > 0.
void thick_loop_closure(const ThickLoop& loop, const Eigen::VectorXd& joint_angles, double length_scale,
                        Eigen::Matrix<double, 6, 1>& residual, Eigen::Matrix<double, 6, Eigen::Dynamic>* jacobian);

// The product M = prod_i T_i(theta_i) of one loop (joint angles in joint order, radians).
Eigen::Isometry3d thick_loop_product(const ThickLoop& loop, const Eigen::VectorXd& joint_angles);

class ThickClosureSystem {
 public:
  // Throws std::invalid_argument for a joint on a crease out of range, an angle_sign other
  // than +-1, a loop with fewer than 2 joints, a fixed crease out of range or fixed twice.
  explicit ThickClosureSystem(ThickPattern pattern, const ThickClosureOptions& options = {});

  int num_unknowns() const { return static_cast<int>(free_creases_.size()); }
  int num_rows() const { return 6 * static_cast<int>(pattern_.loops.size()); }
  int num_creases() const { return pattern_.num_creases; }
  double length_scale() const { return length_scale_; }
  const ThickPattern& pattern() const { return pattern_; }
  int crease_of_unknown(int k) const { return free_creases_[k]; }
  int unknown_of_crease(int c) const { return unknown_of_crease_[c]; }  // -1 if fixed

  // Unknowns <-> per-crease fold angles (radians; fixed creases take their value).
  Eigen::VectorXd creases_from_unknowns(const Eigen::VectorXd& x) const;
  Eigen::VectorXd unknowns_from_creases(const Eigen::VectorXd& crease_angles) const;

  // Residual r(x) (size num_rows()).
  Eigen::VectorXd residual(const Eigen::VectorXd& x) const;
  // Residual and exact Jacobian (num_rows() x num_unknowns(), compressed column-major). The
  // sparsity pattern depends only on the system, so a factorisation's symbolic analysis can
  // be reused across calls.
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& residual, Eigen::SparseMatrix<double>& jacobian) const;

 private:
  ThickPattern pattern_;
  std::vector<int> free_creases_;
  std::vector<int> unknown_of_crease_;
  std::vector<double> fixed_value_;
  double length_scale_ = 1.0;
  Eigen::VectorXd loop_joint_angles(const ThickLoop& loop, const Eigen::VectorXd& crease_angles) const;
};

}  // namespace rigidfold
