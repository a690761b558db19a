#pragma once
// Second-order term of one vertex's loop closure along a direction: the curvature that the
// tangent cone of a singular point is built from (docs/DESIGN.md, "Bifurcation").
//
// With R(s) = prod_i Rx(rho_i + s t_i) Rz(alpha_i) (vertex_closure.hpp convention) and
// r(s) = log R(s), returns r''(0) = D^2 r(rho)[t, t].
// Valid AT A CLOSED LOOP (R(rho) = I), which is where tangent cones are computed: there
// R = exp([w]x) with w(0) = 0 gives R'' = [w'']x + [w']x^2, and [w']x^2 is symmetric, so
// w'' = vee(skew(R'')) exactly. Off the manifold the error is O(|r(rho)|).
//
// Inputs: sectors alpha_i, fold angles rho_i, direction t_i (n each; radians, radians,
//   radians per unit of s). Output: 3-vector (radians per unit s^2), in the frame of
//   crease 0 like vertex_closure_residual. Throws std::invalid_argument on size mismatch.
#include <Eigen/Core>
#include <span>

namespace rigidfold {

Eigen::Vector3d vertex_closure_second_derivative(std::span<const double> sectors,
                                                 std::span<const double> fold_angles,
                                                 std::span<const double> direction);

}  // namespace rigidfold
