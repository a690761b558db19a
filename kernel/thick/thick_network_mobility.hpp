#pragma once
// Mobility of a thick pattern given as a network of DH loops that share creases
// (thick_pattern.hpp, ThickClosureSystem), and the test that names the loops that lock it:
//
//   thick_network_mobility: at a closed state, the network's first-order DOF (free creases
//     minus rank of the exact Jacobian, jacobian_rank with its stated tolerance) and, per
//     loop, the DOF of its 6 rows alone over its creases. DOF 0 at a state is a proof of
//     rigidity there only if the state is regular (compare rank.sigma_kept with the cut).
//   thick_network_hold: drive one crease to a value and find the state nearest to closure
//     (damped Gauss-Newton / Levenberg-Marquardt on the 2-norm of the residual, from a start
//     state). A minimum whose residual stays above the tolerance while the same driver
//     closes the network elsewhere is the witness that the network cannot reach that crease
//     angle; the loops whose rows carry the residual there are named.
//
// Only creases in at least one loop are unknowns; all others are held at the given state's
// value (a flap crease at no thick vertex moves freely and is not counted).
// Units: fold angles in radians; residual rows as ThickClosureSystem (radians, and lengths
// over the pattern's largest link length).
#include <Eigen/Core>
#include <vector>

#include "kernel/solve/rank.hpp"
#include "kernel/thick/thick_closure_system.hpp"
#include "kernel/thick/thick_pattern.hpp"

namespace rigidfold {

struct ThickLoopMobility {
  int loop = -1;
  int creases = 0;          // free creases of the loop
  int dof_alone = 0;        // creases - rank of its 6 rows (same tolerance as the network's)
  double residual = 0.0;    // ||its 6 rows||_inf at the state
};

struct ThickNetworkMobility {
  int dof = 0;                       // free creases - rank
  int free_creases = 0;
  RankResult rank;
  double state_residual = 0.0;       // ||r||_inf
  std::vector<ThickLoopMobility> loops;
  std::vector<int> locked_loops;     // loops with dof_alone == 0
};

// Inputs: the network, a state (one fold angle per crease), closure_tolerance, rank options.
// Throws std::invalid_argument if the state's size is wrong or it does not close within
// closure_tolerance.
ThickNetworkMobility thick_network_mobility(const ThickPattern& pattern, const Eigen::VectorXd& creases,
                                            double closure_tolerance = 1e-10, const RankOptions& rank_options = {});

struct ThickHoldResult {
  Eigen::VectorXd creases;           // the best state found (the held crease at its value)
  double residual = 0.0;             // ||r||_inf there
  double residual_norm = 0.0;        // ||r||_2 there (what was minimised)
  bool stationary = false;           // ||J^T r|| small relative to ||J|| ||r|| (a minimum reached, not stopped)
  int iterations = 0;
  std::vector<double> loop_residual; // ||rows of loop k||_inf
  std::vector<int> open_loops;       // loops with loop_residual > tolerance
};

// Inputs: the network; the crease to hold and its value (radians); a start state (one per
// crease; the held crease is set to value); tolerance for open loops; iteration cap.
ThickHoldResult thick_network_hold(const ThickPattern& pattern, int held_crease, double value, const Eigen::VectorXd& start,
                                   double tolerance = 1e-10, int max_iterations = 200);

}  // namespace rigidfold
