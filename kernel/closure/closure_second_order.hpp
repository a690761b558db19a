#pragma once
// Second directional derivative of a ClosureSystem's residual, D^2 r(x)[t, t]: the
// quadratic term that decides which first-order tangents at a singular point are real
// branches (tangent_cone.hpp).
//
// Rows as ClosureSystem::residual:
//   - vertex rows: exact (vertex_closure_second_derivative), valid on the manifold;
//   - equality rows: 0 (they are linear);
//   - hole rows: central difference of the exact Jacobian, (J(x + h t) - J(x - h t)) t / 2h
//     with h = 1e-5 / max(1, |t|_inf) (error ~1e-10 relative); stated, not hidden.
// Inputs: the system and the topology it was built from (its vertex rows use
//   topology.stars[v].fans[0], as ClosureSystem does), a point x and a direction t (both
//   num_unknowns(), radians). Output: num_rows() values (radians per unit^2).
// Throws std::invalid_argument on a size mismatch.
#include <Eigen/Core>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

Eigen::VectorXd closure_second_derivative(const ClosureSystem& system, const Topology& topology,
                                          const Eigen::VectorXd& x, const Eigen::VectorXd& t);

// The weighted Hessian H(w) = sum_k w_k Hess r_k(x) (n x n, symmetric, radians per unit^2):
// the derivative of J(x)^T w in x, which the branch-point system (branch_point_system.hpp)
// needs. Rows as above: vertex rows D^2 r[e_i, e_j] = vee(skew(d2R/drho_i drho_j)) with
// d2R/drho_i drho_j = [a_i]x [a_j]x R (i <= j in fan order, a_i crease i's axis), the same
// value as vertex_closure_second_derivative by polarisation in O(d^2) per vertex of degree d
// (exact on the manifold, O(|r(x)|) off it); equality rows 0;
// hole rows by central differences of the exact Jacobian (h = 1e-5, column by column).
// Inputs: x (num_unknowns()), w (num_rows()). Throws std::invalid_argument on a size mismatch.
Eigen::MatrixXd closure_weighted_hessian(const ClosureSystem& system, const Topology& topology,
                                         const Eigen::VectorXd& x, const Eigen::VectorXd& w);

}  // namespace rigidfold
