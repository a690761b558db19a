#pragma once
// Displacement control of one interior vertex above a support plane, with the reaction
// force as Lagrange multipliers (seed 004's load case, no symmetry imposed).
//
// Model: the vertex of `load.vertex` is pressed against a plane on which the far ends of the
// support creases rest (frictionless, bilateral point supports: a support may slide in the
// plane but not leave it). Body frame: the frame of the vertex's crease 0 (vertex at the
// origin); crease i points along u_i(rho), the product of the fan's Rx(rho_j) Rz(alpha_j),
// and its far end is at L_i u_i (L_i its reference length). Unknowns z = (x, nu): the free
// fold angles of the ClosureSystem and the plane's unit normal nu in the body frame. Rows:
//     closure r(x) = 0                           (the ClosureSystem's, reused as they are)
//     s_i = nu . (L_i u_i) + height = 0           one per support crease: the support lies on
//                                                the plane at signed distance `height` below
//                                                the vertex along nu
//     (nu . nu - 1) / 2 = 0
// minimising the crease-spring energy: Newton on the KKT system of the Lagrangian
// E + lambda . r + sum mu_i s_i + kappa q, exact first and second derivatives
// (du_i/drho_j = u_j x u_i for j < i in fan order; closure_weighted_hessian for r).
// Reaction: mu_i is the reaction at support i (dE*/d(height) = sum mu_i); the push force on
// the vertex toward the plane is F = -sum mu_i (seed 004 eq. 3.9's F on the symmetric path).
// Stability: the Hessian of the Lagrangian reduced to the null space of the constraint
// Jacobian (dense SVD): its smallest eigenvalue < 0 means the loaded state is unstable
// (e.g. symmetry breaking). No gauge: the body frame is fixed and a spin about nu changes no
// unknown.
// Orientation: nu starts as the mean folded face normal of the fan (the sheet's +z side),
// so height > 0 is the vertex on that side of the supports (seed 004's theta < 90 deg).
// Scope: one interior vertex and its own creases (the waterbomb base); dense linear algebra.
// Units: angles radians, lengths the pattern's units, force = energy / length.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct VertexHeightLoad {
  int vertex = -1;                  // an interior vertex with a closure row block in the system
  std::vector<int> support_edges;   // creases of that vertex whose far ends rest on the plane
  double height = 0.0;              // prescribed vertex height above the plane (length)
};

struct HeightControlOptions {
  double tolerance = 1e-12;   // on |grad L|_inf / max(k) (or its rounding bound, if larger:
                              // HeightControlledEquilibrium::stationarity_bound) and the
                              // constraint rows (rad, length)
  int max_iterations = 50;
  double rank_tolerance = 1e-9;
  double stability_tolerance = 1e-9;  // eigenvalue > this * max(k): positive
  // false: skip the reduced Hessian (dense SVD, the dominant cost for large fans); the
  // result then has tangent_dimension 0, no eigenvalues and stable = false (continuation steps).
  bool compute_stability = true;
};

struct HeightControlledEquilibrium {
  bool converged = false;
  std::string message;
  int iterations = 0;
  Eigen::VectorXd x;                 // free fold angles (radians)
  Eigen::VectorXd edge_angles;       // per edge (radians)
  Eigen::Vector3d plane_normal = Eigen::Vector3d::Zero();  // nu, body frame
  Eigen::VectorXd support_reactions; // mu_i (energy / length), support_edges order
  double force = 0.0;                // -sum mu_i: > 0 pushes the vertex toward the plane
  double energy = 0.0;
  double constraint_residual = 0.0;  // largest |row| (closure rad, supports length)
  double stationarity_residual = 0.0;  // |grad_z L|_inf
  // What the stationarity test asked of it: max(tolerance x max(k), the bound on the rounding
  // of grad_z L's own evaluation, gamma_(M+9) x max_i (|grad E|_i + (|A|^T |w|)_i)), which
  // exceeds the first only where the reactions are large (near the flat state).
  double stationarity_bound = 0.0;
  int tangent_dimension = 0;
  Eigen::VectorXd reduced_hessian_eigenvalues;  // ascending
  double min_eigenvalue = 0.0;
  bool stable = false;
};

// The KKT pieces at z = (x, nu) with multipliers (lambda, mu, kappa) (num_rows() + supports
// + 1 entries): constraint rows, their Jacobian (rows x (num_unknowns() + 3)), the gradient
// and Hessian of the Lagrangian in z. The Hessian is exact where the closure rows vanish
// (closure_weighted_hessian). Exposed so that tests can check the derivatives.
struct HeightControlKkt {
  Eigen::VectorXd constraints;
  Eigen::MatrixXd jacobian;
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
};
HeightControlKkt height_control_kkt(const CreasePattern& pattern, const ClosureSystem& system, const Topology& topology,
                                   const CreaseSprings& springs, const VertexHeightLoad& load, const Eigen::VectorXd& x,
                                   const Eigen::Vector3d& nu, const Eigen::VectorXd& multipliers);

// Inputs: the system and topology of `pattern`, springs for it, the load, and a start x0
//   (free fold angles; the nearest KKT point is found, a saddle included: check stable).
// Throws std::invalid_argument for a vertex without a closure block, a support edge not in
//   its fan, or wrong sizes; never for non-convergence.
HeightControlledEquilibrium vertex_height_equilibrium(const CreasePattern& pattern, const ClosureSystem& system,
                                                      const Topology& topology, const CreaseSprings& springs,
                                                      const VertexHeightLoad& load, const Eigen::VectorXd& x0,
                                                      const HeightControlOptions& options = {});

}  // namespace rigidfold
