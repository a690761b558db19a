#pragma once
// From a weakly folded state to a strictly folded one (strict and weak
// foldability). A folded point found by a sign-bounded search often leaves some M/V creases
// exactly flat (on their bound) although the pattern has strictly folded states nearby; the
// general verdict then could only certify weak foldability.
//
// Method: the M/V creases of x that are flat (s_i x_i <= flat_fraction x ||x||_inf, s_i the
// letter's sign: valley +1, mountain -1) are held at s_i tau ||x||_inf and the other unknowns
// are Newton-projected onto the closure manifold (newton_project: minimum-norm steps, so the
// point moves the least distance). A crease the projection leaves flat or turns against its
// letter joins the held ones and the projection is repeated (at most 8 rounds); tau = 1e-2,
// then 1e-3. The held values can be reached when those creases' rows of the null space of J
// are independent near x (to first order: a tangent direction that folds each of them its
// own way); where no strict motion exists (two straight lettered lines crossing at a
// degree-4 vertex) the projection does not close and nothing is returned.
//
// Units: radians.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

// Inputs: the system; a closed point x (per unknown, radians); the letter's sign per EDGE
// (+1 valley, -1 mountain, 0 none; size num_edges); the closure tolerance (radians, ||r||_inf).
// Output: a point closed to the tolerance at which every lettered crease has
// s_i x_i > flat_fraction x ||x||_inf, or nullopt (none found, or x has no flat lettered crease).
std::optional<Eigen::VectorXd> push_off_flat_creases(const ClosureSystem& system, const Eigen::VectorXd& x,
                                                     const std::vector<int>& edge_signs, double tolerance,
                                                     double flat_fraction = 1e-6);

}  // namespace rigidfold
