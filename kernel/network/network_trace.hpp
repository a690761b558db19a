#pragma once
// Closed configurations of a LinkageNetwork and its motion driven by one input joint: the
// input-output relations of the network (seed 003's transmission theta_1^a -> ...).
//
// Units: radians. Every returned configuration has its closure residual checked:
// ||r||_inf <= tolerance (1e-12 rad by default) - a point that misses is never returned.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/network/network_closure.hpp"

namespace rigidfold {

struct NetworkSearchOptions {
  int max_starts = 64;            // random starts after the guess (joints uniform in [-pi, pi])
  std::uint64_t seed = 17;        // SplitMix64 seed: the search is the same on every platform
  NetworkNewtonOptions newton;    // its `held` is replaced by the input joint
};

struct NetworkConfiguration {
  bool found = false;
  Eigen::VectorXd q;              // closed configuration (radians) when found
  double residual = 0.0;          // ||r||_inf at q (found), or the least reached (not found)
  int starts = 0;                 // Newton runs made (the guess counts as one)
};

// A closed configuration with joint `input` held at `value` (input = -1: nothing held).
// Tries `guess` (size num_unknowns(), or empty) first, then deterministic random starts.
// Throws std::invalid_argument for a bad input index or guess size.
NetworkConfiguration find_network_configuration(const NetworkClosure& system, int input, double value,
                                                const Eigen::VectorXd& guess, const NetworkSearchOptions& options = {});

struct NetworkTraceOptions {
  double tolerance = 1e-12;       // closure tolerance of every point (radians)
  double min_substep = 1e-7;      // give up below this input increment (radians)
  double max_jump = 0.35;         // largest change of any joint in one sub-step (radians):
                                  // above it the step is halved (no jump to another branch)
  double rank_tolerance = 1e-9;   // DOF of each point (network_mobility)
};

struct NetworkTracePoint {
  double input = 0.0;             // input joint value (radians)
  Eigen::VectorXd q;              // configuration (radians)
  double residual = 0.0;          // ||r||_inf (radians), <= tolerance
  int dof = 0;                    // network DOF at q (input free)
  double sigma_kept = 0.0, sigma_dropped = 0.0;  // singular values either side of the rank cut
};

struct NetworkTrace {
  std::vector<NetworkTracePoint> points;  // the start first, then one per step reached
  bool complete = false;                  // every step reached
  std::string stop_reason;                // empty when complete
  int newton_runs = 0;
};

// Drives joint `input` from q_start[input] to `end_value` in `steps` equal steps (>= 1),
// each step by Newton with the input held, from the previous point (halving the increment
// where Newton fails or a joint would jump by more than max_jump). q_start must be closed
// (||r||_inf <= tolerance). Stops at a motion limit or singular point (the increment falls
// below min_substep), with the points reached so far.
// Throws std::invalid_argument for a bad index, size, steps < 1, or a start that is not closed.
NetworkTrace trace_network(const NetworkClosure& system, const Eigen::VectorXd& q_start, int input, double end_value,
                           int steps, const NetworkTraceOptions& options = {});

// Whether the network moves with the input: from the closed q, Newton with joint `input`
// held at q[input] + delta and at q[input] - delta (delta > 0, radians). Returns how many of
// the two close to `tolerance` (0, 1 or 2). A first-order DOF > 0 at a singular point (the
// flat state of developable vertices, where every axis lies in one plane) over-counts; 0
// here is the evidence that the configuration does not move with this input.
int probe_input_motion(const NetworkClosure& system, const Eigen::VectorXd& q, int input, double delta = 1e-3,
                       double tolerance = 1e-12);

}  // namespace rigidfold
