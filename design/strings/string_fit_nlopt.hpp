#pragma once
// Best fit of a Miura string (transmitted mode, one actuation) to a target 3D curve, with
// fabrication bounds, by NLopt.
//
// Target: spine points Q_0 .. Q_{N+1} (S, V_0..V_{N-1}, E; world, length units).
// Unknowns x (3N + 5):  alpha1_i, alpha2_i (i = 0..N-1, radians), theta_0 (radians), w
//   (rotation vector, radians: frame C_0 = exp([w]x) F_seed), segment lengths L_0..L_N.
//   The spine starts at Q_0.
// Objective: mean over k = 1..N+1 of |P_k(x) - Q_k|^2 / Lbar^2 (Lbar: mean target segment
//   length), with its exact gradient (adjoint sums along the chain; the per-vertex
//   derivatives of the closed-form rotation by ceres::Jet).
// Bounds: alpha in [alpha_min, alpha_max]; L >= min_segment; |theta_0| <= pi/2 - margin;
//   and one inequality per vertex, |theta_0| <= theta_limit(alpha1_i, alpha2_i) - margin,
//   written smoothly as tan^4(|theta_0| + margin) sin^2(alpha2 - alpha1) <= sin^2(alpha1 + alpha2).
//   Above 30 vertices (theta_constraints = "auto") the N constraints make NLopt's
//   subproblems the bottleneck (CCSAQ/MMA: seconds per iteration at 100); the box |theta_0| <= theta_limit(alpha_min, alpha_max) - margin
//   (the smallest limit over the alpha box, so every vertex is safe) replaces them. It is
//   conservative: reported as "theta box bound" when it binds.
// Start: the closed-form sequential design (string_inverse.hpp), which is exact when the
//   target is reachable; alphas clamped where it is not.
// Algorithms (NLopt names): local "LD_SLSQP" (default up to 50 vertices: dense O(n^3) steps), "LD_MMA",
//   "LD_CCSAQ" (default above), "LN_COBYLA" (derivative-free); with `global`, first
//   "GN_ISRES" (bounded, constrained, stochastic) for global_evaluations, then the local one.
// Report: per-point error, whether every point is within `tolerance` (x Lbar), and which
//   bounds bind at the optimum (alpha at a bound, theta at a vertex's limit minus margin,
//   a length at min_segment).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/strings/string_inverse.hpp"

namespace rigidfold::design {

struct NloptFitOptions {
  std::string algorithm = "auto";      // see above
  bool global = false;                 // GN_ISRES before the local algorithm
  int global_evaluations = 20000;
  int max_evaluations = 3000;          // local
  double max_time = 60;                // seconds, each stage
  double ftol_rel = 1e-15, xtol_rel = 1e-13;
  double tolerance = 1e-9;             // reachable when every point error <= tolerance * Lbar
  std::string theta_constraints = "auto";  // "per_vertex", "box", or "auto" (per_vertex up to 30 vertices)
  bool closed_form_seed = true;        // false: start at alpha = 45 deg, seed theta0/roll (optimiser benchmarks)
  CurveDesignOptions seed;             // closed-form start (and the bounds used throughout)
};

struct NloptFitResult {
  MiuraString string;                  // width left 0 (choose with max_string_width)
  double theta0 = 0;
  StringPose pose;                     // for string_forward(string, theta0, pose)
  std::vector<double> point_errors;    // |P_k - Q_k|, k = 0..N+1 (length units)
  double max_error = 0, rms_error = 0; // length units
  double mean_segment = 1;             // Lbar
  bool reachable = false;              // max_error <= tolerance * Lbar
  bool seed_feasible = false;          // the closed form alone was exact and within bounds
  std::vector<std::string> binding;    // e.g. "alpha1[4] = alpha_max", "theta limit at vertex 7", "lengths[2] = min_segment"
  std::string algorithm;               // what ran, e.g. "GN_ISRES + LD_SLSQP"
  std::string status;                  // NLopt's result code of the last stage
  int evaluations = 0;
};

// Throws std::invalid_argument for bad points or an unknown algorithm name.
NloptFitResult fit_string_to_curve(const std::vector<Eigen::Vector3d>& points, const NloptFitOptions& options = {});

// The objective (without gradient) at a design, for reports and benchmarks: max and rms of
// |P_k - Q_k| for string_forward(s, theta0, pose).
void curve_errors(const MiuraString& s, double theta0, const StringPose& pose, const std::vector<Eigen::Vector3d>& points,
                  double& max_error, double& rms_error, std::vector<double>* per_point = nullptr);

}  // namespace rigidfold::design
