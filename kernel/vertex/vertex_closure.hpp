#pragma once
// Loop closure of one vertex (spherical linkage): product, residual, exact Jacobian.
//
// Convention (the kernel's, see docs/DESIGN.md):
//   A vertex of degree n has creases 0..n-1 ordered counter-clockwise seen from +z
//   (the papers' creases 1..n), sector i lies between crease i and crease i+1 (mod n).
//   The loop closes when
//       R(rho) = Rx(rho_0) Rz(alpha_0) Rx(rho_1) Rz(alpha_1) ... Rx(rho_{n-1}) Rz(alpha_{n-1}) = I
//   (x along the current crease, z the face normal). rho_i > 0 lifts the sector after
//   crease i toward +z: valley; rho_i < 0 mountain; rho = 0 flat.
//   Sectors need not sum to 2*pi (non-developable cones, spherical linkages given by
//   their twists); any real value is accepted.
//
// All angles are in radians. Inputs are spans so that a caller can pass a std::vector,
// a std::array or an Eigen vector: std::span<const double>(v.data(), v.size()).
// rot_x, rot_z, so3_log and so3_left_jacobian_inverse live in kernel/math/so3.hpp.
#include <Eigen/Core>
#include <span>

#include "kernel/math/so3.hpp"

namespace rigidfold {

// Loop product of a vertex.
// Inputs:
//   sectors      n sector angles alpha_i (radians), alpha_i between crease i and i+1
//   fold_angles  n fold angles rho_i (radians)
// Returns R = prod_i Rx(rho_i) Rz(alpha_i) (3x3, orthogonal).
// Throws std::invalid_argument if the sizes differ or n == 0.
Eigen::Matrix3d vertex_loop_product(std::span<const double> sectors,
                                    std::span<const double> fold_angles);

// Closure residual r = log(R(rho)) (rotation vector, radians). |r| is the closure error
// of the vertex in radians: the rotation left over after going once around the vertex.
// Inputs/throws as vertex_loop_product.
Eigen::Vector3d vertex_closure_residual(std::span<const double> sectors,
                                        std::span<const double> fold_angles);

// Residual and its exact Jacobian with respect to the fold angles.
// Inputs:
//   sectors, fold_angles  as vertex_loop_product (n each)
// Outputs:
//   residual   r = log(R(rho)), 3-vector (radians)
//   jacobian   3 x n (resized; reuse it across calls to avoid allocation),
//              column i = d r / d rho_i = Jl^{-1}(r) u_i, where u_i is the axis
//              of crease i expressed in the frame of crease 0 (the vertex frame):
//              with R = P_i Rx(rho_i) S_i, dR/drho_i = [P_i e_x]x R.
//   axes       optional (nullptr to skip): 3 x n, column i = u_i (unit vectors)
// The Jacobian is smooth wherever |r| < pi (the log has its branch cut at pi).
void vertex_closure_jacobian(std::span<const double> sectors,
                             std::span<const double> fold_angles,
                             Eigen::Vector3d& residual,
                             Eigen::Matrix3Xd& jacobian,
                             Eigen::Matrix3Xd* axes = nullptr);

}  // namespace rigidfold
