#pragma once
// C^3 folding path from solver samples (seed 002 digest section 4: "spline it through solver
// samples; it must be C^3 if curvature is needed").
//
// The kernel's trace (kernel/analysis/trace_motion.hpp) gives the fold angles rho_e at steps
// equally spaced in the driving crease's angle. The synchronized parameter is
//   t = drive / final drive  (the flat state rho = 0 at t = 0 is added; t = 1 the last step),
// so the samples are equispaced in t. Each crease's rho_e(t) is interpolated by a quintic
// B-spline on those knots (C^4: value and derivatives 1-3 continuous), with its first and
// second derivatives at both ends taken from the degree-7 polynomial through the 8 samples
// nearest that end (no natural end conditions: they would force rho'' = 0 at t = 0, 1 and
// cost the spline its order there). The Jets are exact derivatives of the spline.
// Accuracy on a smooth path with N intervals: value O(N^-6), k-th derivative O(N^(k-6))
// (measured in tests/sorce/sorce_path_spline_test.cpp).
//
// Units: t dimensionless, angles radians (rho > 0 valley, DESIGN.md).
#include <Eigen/Core>
#include <vector>

#include "design/sorce/sorce_function.hpp"
#include "kernel/analysis/trace_motion.hpp"

namespace rigidfold::sorce {

// Interpolating quintic spline through values[k] at t_k = k / N, N = values.size() - 1 >= 7.
// Returns f with f(t_k) = values[k] and the spline's exact derivatives; defined on [0, 1]
// (beyond it, the polynomial pieces' extension). Throws InputError("values") if fewer than 8
// values or a value is not finite.
ScalarFunction quintic_spline(const std::vector<double>& values);

// The traced path of one branch as splines per crease.
struct PathSpline {
  int drive = -1;                 // driving crease (edge index)
  double final_drive = 0.0;       // its angle at t = 1 (radians)
  std::vector<double> knots;      // t of the samples: 0 (flat, added), then each step
  Eigen::MatrixXd samples;        // rho per edge (rows) at each knot (columns), radians
  std::vector<ScalarFunction> rho;  // per edge (non-hinge edges: their samples, 0 for a flat sheet)
};

// Inputs: a traced branch (steps with rho per edge, equally spaced drive angles as
// trace_motion gives them, flat state excluded) and the number of edges. Throws
// InputError("branch") if it is not traced or has fewer than 7 steps, or if its drive
// angles are not 0-based equal steps (relative 1e-9) of one sign.
PathSpline path_spline(const MotionBranch& branch, int num_edges);

}  // namespace rigidfold::sorce
