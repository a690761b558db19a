#pragma once
// Least-squares design of a Miura string from target deflection trajectories, by Ceres.
//
// Target: M drive samples theta_j (radians; the driven crease s_0 is at 2 theta_j) and
// for every vertex i the wanted phi_ij, psi_ij (radians) at those samples. Vertex i sees
// theta_i = (-1)^i theta_j (Transmitted, the one-DOF string) or theta_j (Independent).
// Unknowns: (alpha1_i, alpha2_i), bounded to [alpha_min, alpha_max] (Ceres parameter
// bounds). Residuals: phi_i(theta) - phi_ij and psi_i(theta) - psi_ij (radians), with
// automatic derivatives (ceres::AutoDiffCostFunction over string_vertex_frame). Vertices
// do not interact (theta_i does not depend on alpha), so the problem is block diagonal;
// one Ceres problem holds them all (sparse normal Cholesky).
// A sample beyond a vertex's theta limit makes its residual invalid (Ceres rejects the step).
// Start: the per-vertex closed-form inverse at the sample of largest |theta| where it
// exists, else alpha1 = alpha2 = 45 deg.
#include <string>
#include <vector>

#include "design/strings/string_inverse.hpp"

namespace rigidfold::design {

struct TrajectoryTarget {
  std::vector<double> theta;              // M drive samples (radians, nonzero)
  std::vector<std::vector<double>> phi;   // [vertex][sample] (radians)
  std::vector<std::vector<double>> psi;   // [vertex][sample] (radians), |psi| < pi/2
  ThetaMode mode = ThetaMode::Transmitted;
};

struct TrajectoryFitResult {
  std::vector<double> alpha1, alpha2;     // radians
  std::vector<double> vertex_rms;         // per vertex: rms of its 2M residuals (radians)
  double max_residual = 0;                // max |residual| over all (radians)
  double final_cost = 0;                  // Ceres cost (1/2 sum of squares)
  int iterations = 0;
  bool converged = false;                 // Ceres reported CONVERGENCE
  std::vector<std::string> binding;       // "alpha1[3] = alpha_max", ...
  std::string report;                     // Ceres BriefReport
};

// Throws std::invalid_argument for inconsistent sizes or non-finite values.
// closed_form_start = false starts every vertex at alpha1 = alpha2 = 45 deg (tests and
// benchmarks of the optimiser itself).
TrajectoryFitResult fit_string_trajectories(const TrajectoryTarget& target, const StringBounds& bounds = {},
                                            int max_iterations = 200, bool closed_form_start = true);

}  // namespace rigidfold::design
