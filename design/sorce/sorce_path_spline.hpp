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
// Units: t dimensionless, angles radians (rho > 0 valley, docs/DESIGN.md).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "design/sorce/sorce_function.hpp"
#include "kernel/analysis/trace_motion.hpp"

namespace rigidfold::sorce {

// Interpolating quintic spline through values[k] at t_k = k / N, N = values.size() - 1 >= 7.
// Returns f with f(t_k) = values[k] and the spline's exact derivatives; defined on [0, 1]
// (beyond it, the polynomial pieces' extension). Throws InputError("values") if fewer than 8
// values or a value is not finite.
ScalarFunction quintic_spline(const std::vector<double>& values);

// The synchronized parameter t of a path (both run 0 -> 1 from flat to the last step).
//  kDrive:     t = drive / final drive (the trace's own equal steps).
//  kArcLength: t = arc length of the path in fold-angle space (Euclidean norm over all
//              edges' rho) / total, up to the spline's accuracy: rho_e(t) = spline_e(tau(t)),
//              tau the drive parameter and tau(t) a quintic spline through the inverse arc
//              length at as many equal t steps as the trace has, so the path's points are the
//              same and only their timing changes. Every fold's rate is then
//              |rho_e'| = L * (its share of the speed): a fold that the drive parameter runs
//              fast near an end (vertex A's minor folds run at mu pi = 9.0 rad per unit t at
//              t = 1 against 1.1 at t = 0) is slowed there and the slow ones sped up, as the
//              seed's eq 35 does for a single vertex, so that the offsets' few polynomial
//              terms can shape the profiles at both ends (tests/sorce/sorce_design_optimize_test.cpp).
//  kHalfTangent: tan(pi t / 2) proportional to the geometric mean over the folding creases of
//              |tan(rho_e / 2)| (normalised so t = 1 at the last step), by the same tau(t)
//              spline. On a flat-foldable degree-4 vertex (tan(rho_e/2) = m_e tan(rho_drive/2))
//              this is exactly the seed's eq 35 parameter: the major folds' half tangents are
//              sqrt(mu) tan(pi t/2), the minor ones tan(pi t/2)/sqrt(mu), so every fold's rate
//              is finite and non-zero at both ends, minor and major swapping roles at t = 1.
//              Needs that mean to increase along the path (else InputError("branch")): a
//              crease that turns back or ends flat may break it.
enum class PathParameter { kDrive, kArcLength, kHalfTangent };
const char* to_string(PathParameter p);  // "drive", "arc_length", "half_tangent"

// The traced path of one branch as splines per crease.
struct PathSpline {
  PathParameter parameter = PathParameter::kDrive;
  double arc_length = 0.0;        // total length of the path in fold-angle space (radians)
  int drive = -1;                 // driving crease (edge index)
  double final_drive = 0.0;       // its angle at t = 1 (radians)
  std::vector<double> knots;      // t of the samples: 0 (flat, added), then each step
                                  // (equally spaced for kDrive; increasing, 0 and 1 at the ends, for kArcLength)
  Eigen::MatrixXd samples;        // rho per edge (rows) at each knot (columns), radians
  std::vector<ScalarFunction> rho;  // per edge (non-hinge edges: their samples, 0 for a flat sheet)
  // The branch's exact path (MotionBranch::tan_half_ratio, the multiplier model) instead of the
  // splines: rho_e on the drive parameter is then exact at every t, whatever the step count.
  // The arc-length and half-tangent parameters still map t through their tau(t) spline.
  bool exact = false;
};

// A branch that carries the multiplier model's exact path (tan_half_ratio) gets that path
// instead of the splines (PathSpline::exact); the knots and samples are the same.
// Inputs: a traced branch (steps with rho per edge, equally spaced drive angles as
// trace_motion gives them, flat state excluded) and the number of edges. Throws
// InputError("branch") if it is not traced or has fewer than 7 steps, or if its drive
// angles are not 0-based equal steps (relative 1e-9) of one sign; for kArcLength also if the
// path's speed ||rho'|| vanishes somewhere (a stop: no arc-length parameter there).
// Cost of kArcLength: one Gauss quadrature of the speed per knot interval and a Newton solve
// per sample at construction (O(steps * edges)), then two spline evaluations per rho_e(t).
PathSpline path_spline(const MotionBranch& branch, int num_edges, PathParameter parameter = PathParameter::kDrive);

// What t is and how rho_e(t) is made, for people (e.g. "t = drive / final drive, quintic spline
// per crease").
std::string parameter_definition(const PathSpline& path);

}  // namespace rigidfold::sorce
