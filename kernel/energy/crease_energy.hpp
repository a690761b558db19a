#pragma once
// Crease-spring energy of a crease pattern (seed 004 eqs 2.9, 3.7; docs/DESIGN.md kernel/energy):
//
//     E(rho) = sum_e 1/2 k_e (rho_e - rhobar_e)^2
//
// over every edge e, with k_e the torsional stiffness (0 for edges without a spring) and
// rhobar_e the rest fold angle, the angle at which the spring is unstrained.
// Units: rho, rhobar in radians (FOLD sign: valley > 0, mountain < 0); k in energy per
// radian^2 (N m / rad for SI input, crease_stiffness.hpp); E in the energy unit of k.
// The energy is separable: gradient k_e (rho_e - rhobar_e), Hessian diag(k_e), both exact.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

struct CreaseSprings {
  Eigen::VectorXd stiffness;    // per edge, >= 0 (energy / rad^2)
  Eigen::VectorXd rest_angles;  // per edge, radians, in [-pi, pi]
};

// Checked springs for `pattern`: both vectors have num_edges() entries, every stiffness is
// finite and >= 0, every rest angle finite and in [-pi, pi].
// Throws InputError naming the place ("stiffness[e]", "rest_angles[e]" or the size).
CreaseSprings make_crease_springs(const CreasePattern& pattern, const Eigen::VectorXd& stiffness,
                                  const Eigen::VectorXd& rest_angles);

// E at per-edge fold angles `edge_angles` (size = springs' size; radians).
// Throws std::invalid_argument on a size mismatch (as do the two below).
double crease_energy(const CreaseSprings& springs, const Eigen::VectorXd& edge_angles);
// dE/drho (per edge, energy / rad).
Eigen::VectorXd crease_energy_gradient(const CreaseSprings& springs, const Eigen::VectorXd& edge_angles);
// d2E/drho2 (per edge x per edge, diagonal, energy / rad^2); constant in rho.
Eigen::SparseMatrix<double> crease_energy_hessian(const CreaseSprings& springs);

}  // namespace rigidfold
