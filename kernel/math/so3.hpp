#pragma once
// Small SO(3) helpers shared by the kernel and design/: elementary rotations, the skew
// (hat) map and its inverse, the exponential and logarithm maps, the left Jacobian and its
// inverse, and an orthonormality check.
//
// Units and conventions: every angle is in radians; a rotation vector w is angle * unit
// axis (radians), |w| the angle; rotations are right-handed (counter-clockwise seen from
// the tip of the axis) and act on column vectors, R v. The kernel's vertex loop is
// prod_i Rx(rho_i) Rz(alpha_i) with these rot_x / rot_z (see vertex_closure.hpp).
#include <Eigen/Core>

namespace rigidfold {

// Elementary rotations about the x and z axes.
// Input: angle (radians). Returns the 3x3 rotation matrix Rx(angle) / Rz(angle).
Eigen::Matrix3d rot_x(double angle);
Eigen::Matrix3d rot_z(double angle);

// Rotation about an arbitrary axis.
// Inputs: unit_axis (norm 1, not normalised here), angle (radians).
// Returns the 3x3 rotation matrix exp(angle [unit_axis]x) (Eigen's AngleAxis, bit for bit).
Eigen::Matrix3d rotation_about(const Eigen::Vector3d& unit_axis, double angle);

// Skew (hat) matrix: [w]x, with [w]x v = w x v for every v.
// Input: any 3-vector w. Returns the 3x3 skew-symmetric matrix.
Eigen::Matrix3d skew(const Eigen::Vector3d& w);

// Inverse of skew on the skew-symmetric part of a matrix: the w with [w]x = (M - M^T) / 2.
// Input: any 3x3 M. Returns w = (M21 - M12, M02 - M20, M10 - M01) / 2, so that
// skew_part_vector(skew(w)) = w. For a rotation R of angle t about a it is sin(t) a.
Eigen::Vector3d skew_part_vector(const Eigen::Matrix3d& M);

// Exponential map: rotation vector -> rotation matrix.
// Input: w (radians). Returns exp([w]x); exactly the identity for w = 0.
Eigen::Matrix3d so3_exp(const Eigen::Vector3d& w);

// Rotation vector (angle * unit axis) of a rotation matrix: the principal SO(3) log.
// Inputs:
//   R  3x3 rotation matrix (assumed orthogonal with det +1)
// Returns phi with |phi| in [0, pi] (radians) and exp([phi]x) = R.
// Accurate to machine precision near angle 0 (no 0/0) and near pi (the axis is taken
// from the symmetric part of R there, where the skew part vanishes). At exactly pi the
// sign of the axis is arbitrary, as it must be.
Eigen::Vector3d so3_log(const Eigen::Matrix3d& R);

// Left Jacobian of SO(3) at the rotation vector w (radians):
// d/ds exp([w + s dw]x) at s = 0 equals [J_l(w) dw]x exp([w]x).
// Closed form I + (1 - cos t)/t^2 [w]x + (t - sin t)/t^3 [w]x^2 with t = |w|; its Taylor
// polynomial I + [w]x/2 + [w]x^2/6 for t < 1e-6.
Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& w);

// Inverse of the left Jacobian of SO(3) at the rotation vector phi.
// If R = exp([phi]x) and R is perturbed on the left, exp([d]x) R = exp([phi + dphi]x),
// then dphi = so3_left_jacobian_inverse(phi) * d to first order.
// Closed form I - [phi]x/2 + (1/t^2 - cot(t/2)/(2t)) [phi]x^2 with t = |phi|; a series is
// used for small t. Finite for t in [0, pi] (valid for t < 2*pi).
Eigen::Matrix3d so3_left_jacobian_inverse(const Eigen::Vector3d& phi);

// Orthonormality error of a 3x3 matrix: max_ij |(R^T R - I)_ij| (dimensionless, 0 for an
// exact rotation or reflection; check the determinant to tell them apart).
double orthonormality_error(const Eigen::Matrix3d& R);

}  // namespace rigidfold
