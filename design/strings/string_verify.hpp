#pragma once
// Verification of a string's closed form by the kernel's general loop-closure solver.
//
// Builds the pattern's ClosureSystem with the driven crease s_0 fixed at 2 theta_0 (every
// other M/V crease free: 3N unknowns, 3N closure rows), runs the Newton projection from
// the closed-form fold angles (optionally perturbed, to show the solver is not just handed
// the answer), folds the pattern with face placement from the solver's angles, and
// compares: fold angles (solver vs closed form, radians) and spine points (folded pattern
// vs the closed-form spine in the same pose, lengths).
#include <Eigen/Core>

#include "design/strings/string_kinematics.hpp"

namespace rigidfold::design {

struct StringVerification {
  bool converged = false;
  int iterations = 0;
  double closure_residual = 0;    // ||r||_inf after Newton (radians)
  double max_angle_error = 0;     // max |rho_solver - rho_closed_form| over creases (radians)
  double max_spine_error = 0;     // max distance, folded spine vs closed-form spine (length units)
  double placement_mismatch = 0;  // face placement's closure mismatch (length units)
  Eigen::VectorXd solver_angles;  // per edge (radians)
  FoldedGeometry folded;          // from the solver's angles, in the pattern pose
};

// state must be a Transmitted-mode state of `s` in the pattern pose (string_forward(s,
// theta0)); pattern = build_string_pattern(s, state.edge_fold_angles).
// perturbation: the Newton start is closed form + perturbation * (deterministic
// pseudo-random values in [-1, 1]) on the free creases (radians).
StringVerification verify_string_with_general_solver(const MiuraString& s, const CreasePattern& pattern,
                                                     const StringState& state, double perturbation = 0.0);

}  // namespace rigidfold::design
