#pragma once
// Bifurcations on a 1-DOF path: locating the singular point between two path points, and
// leaving a singular point along a tangent line (DESIGN.md, "Bifurcation").
//
// Locating. Between two points xa, xb of a traced 1-DOF branch whose bordered determinant
//   g = det[Ua^T J(x); ta^T] (Ua: n-1 leading left singular vectors of J(xa), ta: unit null
//   vector at xa, oriented to xb) changes sign, the path is parametrised by the pseudo-
//   arclength s = ta . (x - xa) (radians). On the branch, the test function
//   f(s) = sigma_{n-1}(J(x(s))) (the second smallest of the n singular values; the kernel
//   is 2-dimensional at a simple bifurcation) vanishes linearly at s*. We march toward s*
//   from xa ON THE BRANCH: each step covers half the remaining distance to the current
//   secant estimate of the root of f and is corrected (Newton on [r; ta.(x - xa) - s])
//   from the previous point along its tangent. Marching from one side keeps every point on
//   our branch: a chord or bisection evaluation near s* can converge onto the crossing
//   branch instead, which moves the sign change of g (measured: 1.4e-4 rad off on Type 2M).
//   Stop when the secant estimate moves by <= parameter_tolerance; x* is then corrected at
//   the estimate. `parameter_uncertainty` is the last move.
// Leaving. From a singular point x* along a unit tangent line d (tangent_cone.hpp): hold the
//   unknown j with the largest |d_j| at x*_j + h d_j and Newton-project x* + h d. Away from
//   x* the branch is regular for the held unknown, so Newton converges quadratically; the
//   returned point's chord (x - x*)/|x - x*| is compared with d to confirm the line.
//
// Units: radians. Dense linear algebra: meant for the small and medium patterns where
//   bifurcations are analysed (n up to a few hundred unknowns).
#include <Eigen/Core>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

struct LocatedSingularPoint {
  bool found = false;            // g changed sign over [xa, xb] and the root converged
  Eigen::VectorXd x;             // the point (unknowns, radians), on the manifold
  double parameter = 0.0;        // s* = ta . (x* - xa), pseudo-arclength from xa (radians)
  double parameter_uncertainty = 0.0;  // last change of the secant estimate (radians)
  int steps = 0;                 // marching steps
  double residual = 0.0;         // ||r(x)||_inf
  int evaluations = 0;           // Newton projections made
  // Independent check: singular values of J(x) there. At a bifurcation of a 1-DOF path the
  // kernel grows to 2: sigma_{n-1} (second smallest of the n) is ~0.
  double sigma_max = 0.0, sigma_second_smallest = 0.0;
};

// Inputs: two consecutive points xa, xb of a DOF-1 path (on the manifold), tolerance on the
// parameter (radians). Returns found = false when g does not change sign between them or the
// march fails.
LocatedSingularPoint locate_singular_point(const ClosureSystem& system, const Eigen::VectorXd& xa,
                                           const Eigen::VectorXd& xb, double parameter_tolerance = 1e-10);

struct BranchDeparture {
  bool converged = false;
  Eigen::VectorXd x;             // point on the branch at distance ~h from x* (radians)
  int held_unknown = -1;
  double residual = 0.0;
  double chord_alignment = 0.0;  // (x - x*) . d / |x - x*|: 1 on the predicted line
};

// Inputs: a singular point x_star (on the manifold), a unit direction d, a step h > 0
// (radians; the sign of d picks the side).
BranchDeparture leave_singular_point(const ClosureSystem& system, const Eigen::VectorXd& x_star,
                                     const Eigen::VectorXd& d, double h);

}  // namespace rigidfold
