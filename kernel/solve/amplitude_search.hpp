#pragma once
// Least squares on the loop closure with the fold's size fixed by a norm, and each crease
// kept on the side its letter allows: a search for a folded state near
// flat that does not presume which creases fold.
//
// Holding chosen "driving" creases at a value (the verdict's first search) fails on a
// pattern whose motion leaves those creases flat: the least residual then equals the held
// value whatever the pattern, which looks like an obstruction growing with the fold. Here
// the size is ||x||_2 = amplitude over all unknowns, so any motion of that size is a zero.
//
// Problem: minimise ||r(x)||_2^2 + (||x||_2 - amplitude)^2 over lower <= x <= upper, r the
// ClosureSystem residual (radians). Method: projected Levenberg-Marquardt. Each step solves
//     (J_f^T J_f + g_f g_f^T + mu I) d = -(J_f^T r + g_f a),   a = ||x|| - amplitude, g = x / ||x||,
// on the unknowns not held at a bound (an unknown at its bound whose gradient points out of
// the box is held), by one sparse Cholesky factorisation of J_f^T J_f + mu I (CHOLMOD, the
// pattern analysed once) and Sherman-Morrison for the dense amplitude row; the step is
// clipped to the box and accepted if the objective falls (mu / 3), otherwise mu x 4.
//
// Units: radians.
#include <Eigen/Core>
#include <vector>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

struct AmplitudeSearchOptions {
  double amplitude = 0.1;      // ||x||_2 sought (radians), > 0
  int max_iterations = 80;     // LM steps at most
  double tolerance = 1e-12;    // stop when ||r||_inf <= tolerance and |a| <= tolerance (radians)
  // Stop when the objective fell by less than this fraction over the last stall_window
  // accepted steps (a plateau of an inconsistent system). 0: off.
  int stall_window = 8;
  double stall_factor = 0.99;
  // false: projected steps (an unknown at a bound is held there while the descent points out
  // of the box). true: an unknown whose bound on one side is 0 and which lies strictly beyond
  // it (a lettered crease folded its letter's way) is stepped in log|x|, so it approaches 0
  // but never sticks there; such starts must not be 0. Finds strict folds where projected
  // steps leave creases stuck flat (Origami Simulator's triangulated hypar at ||x||_2 = 0.42:
  // projected 7e-5 rad with ~12 creases flat; logarithmic closes it).
  bool logarithmic = false;
};

struct AmplitudeSearchResult {
  Eigen::VectorXd x;               // last iterate, inside the box (radians)
  double closure_residual = 0.0;   // ||r(x)||_inf (radians)
  double amplitude = 0.0;          // ||x||_2 reached (radians)
  int iterations = 0;              // accepted steps
  int factorizations = 0;
  bool converged = false;          // closure_residual and |amplitude - sought| <= tolerance
};

// Inputs: the system; a start x0 (size num_unknowns, radians; clipped into the box);
// per-unknown bounds lower <= upper (radians, same size). Throws std::invalid_argument for
// wrong sizes, lower > upper or a non-positive amplitude.
AmplitudeSearchResult amplitude_search(const ClosureSystem& system, const Eigen::VectorXd& x0,
                                       const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                       const AmplitudeSearchOptions& options);

}  // namespace rigidfold
