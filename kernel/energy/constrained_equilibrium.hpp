#pragma once
// Equilibria of the crease-spring energy on the loop-closure manifold, and their stability
// (docs/DESIGN.md kernel/energy). No symmetry is imposed: the unknowns are all
// free fold angles x of a ClosureSystem, the constraints its residual r(x) = 0.
//
// Method: projected Newton on the manifold. At a point x on the manifold (r(x) = 0 to the
// corrector's 1e-12 rad), with J = dr/dx and g = dE/dx:
//   - the tangent space is the null space N of J (dense SVD, rank cut
//     rank_tolerance * sigma_max), so redundant closure rows are harmless;
//   - the Lagrange multipliers are the least-squares solution of J^T lambda = -g, and the
//     stationarity residual is |N^T g|_inf (= |g + J^T lambda|_inf);
//   - the Hessian of the Lagrangian L = E + lambda^T r is
//         H_L = diag(k_free) + sum_k lambda_k Hess r_k(x)   (closure_weighted_hessian)
//     and its reduction to the tangent space, H_r = N^T H_L N, decides stability: a
//     minimum has H_r positive definite. There is no rigid-body gauge in this formulation:
//     the unknowns are fold angles, which a rigid motion of the whole sheet does not change.
//   - the step is the Newton step in the tangent space, p = -N H_r^-1 N^T g (with |eigenvalues|
//     where H_r is indefinite, so a minimiser moves away from saddles), capped, then
//     projected back onto the manifold (newton_project), with a backtracking line search on
//     E. Converges quadratically near a regular minimum.
// Cost: a dense SVD of J per step, O(rows * unknowns^2): meant for patterns up to a few
//   hundred creases (a single vertex, small tessellations).
// Units: angles in radians, energies in the unit of the stiffness (energy / rad^2) times rad^2.
// Singular points of the manifold (e.g. the flat state) are not equilibria this method can
// certify: there J loses rank and the tangent space jumps.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct EquilibriumOptions {
  // Converged when |N^T g|_inf <= stationarity_tolerance * max(max k_e * 1 rad, |g|_inf)
  // and the closure residual <= closure_tolerance.
  double stationarity_tolerance = 1e-12;
  double closure_tolerance = 1e-12;  // radians
  double rank_tolerance = 1e-9;      // singular values of J below this times sigma_max span the tangent space
  double max_step = 0.2;             // |p|_inf cap per Newton step (radians)
  int max_iterations = 100;
  // An eigenvalue of H_r counts as positive when > stability_tolerance * max(k_e).
  double stability_tolerance = 1e-9;
};

struct Equilibrium {
  bool converged = false;
  std::string message;                 // why not converged ("" when converged)
  int iterations = 0;
  Eigen::VectorXd x;                   // free fold angles (radians), system order
  Eigen::VectorXd edge_angles;         // per edge (radians)
  Eigen::VectorXd multipliers;         // lambda, one per closure row (energy / rad)
  double energy = 0.0;
  double closure_residual = 0.0;       // |r(x)|_inf (radians)
  double stationarity_residual = 0.0;  // |N^T g|_inf (energy / rad)
  int tangent_dimension = 0;           // dim null(J): the DOF at x
  Eigen::VectorXd reduced_hessian_eigenvalues;  // of N^T H_L N, ascending (energy / rad^2)
  double min_eigenvalue = 0.0;         // smallest of them (+inf when the tangent space is 0-dimensional)
  bool stable = false;                 // converged and min_eigenvalue > stability threshold
};

// Evaluates the equilibrium conditions at x (which should lie on the manifold): energy,
// multipliers, stationarity, reduced Hessian. `converged` reports whether x satisfies them
// within the options' tolerances (no iteration is done).
// Throws std::invalid_argument if x or the springs have the wrong size.
Equilibrium analyse_equilibrium(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                                const Eigen::VectorXd& x, const EquilibriumOptions& options = {});

// Minimises the energy on the manifold from x0 (free fold angles, radians; projected onto
// the manifold first). Inputs: system built from `topology` (build_topology of the
// pattern the springs belong to). Never throws for non-convergence: check converged.
Equilibrium find_equilibrium(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                             const Eigen::VectorXd& x0, const EquilibriumOptions& options = {});

// Every distinct stable state reached from the given starts (each a vector of free fold
// angles), in order of increasing energy; two states are the same when their fold angles
// differ by <= same_state_tolerance (radians, inf-norm).
std::vector<Equilibrium> stable_states(const ClosureSystem& system, const Topology& topology,
                                       const CreaseSprings& springs, const std::vector<Eigen::VectorXd>& starts,
                                       const EquilibriumOptions& options = {}, double same_state_tolerance = 1e-6);

}  // namespace rigidfold
