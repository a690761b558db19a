#pragma once
// Bifurcations on a 1-DOF path: locating the singular point between two path points, and
// leaving a singular point along a tangent line (docs/DESIGN.md, "Bifurcation").
//
// Locating. Between two points xa, xb of a traced 1-DOF branch whose bordered determinant
//   g = det[Ua^T J(x); ta^T] (Ua: n-1 leading left singular vectors of J(xa), ta: unit null
//   vector at xa, oriented to xb) changes sign, the path is parametrised by the pseudo-
//   arclength s = ta . (x - xa) (radians). Two stages:
//   1. Start. On the branch, f(s) = sigma_{n-1}(J(x(s))) (the second smallest of the n
//      singular values; the kernel is 2-dimensional at a simple bifurcation) vanishes
//      linearly at s*. We march toward s* from xa ON THE BRANCH: each step covers half the
//      remaining distance to the current secant estimate of the root of f and is corrected
//      (Newton on [r; ta.(x - xa) - s]) from the previous point along its tangent. Marching
//      from one side keeps every point on our branch: a chord or bisection evaluation near
//      s* can converge onto the crossing branch instead (measured: 1.4e-4 rad off on
//      Type 2M). This start is only ~1e-7 rad from the point (Type 2M): the secant of a
//      singular value is no location.
//   2. Location. Gauss-Newton on the regular extended system of branch_point_system.hpp
//      (closure, J^T Ua c = 0, |c| = 1) from that start: quadratic convergence, and a
//      Newton-Kantorovich bound on |x - x*|_2 (`error_bound`) that is tested against a
//      50-digit solve.
// Leaving. From a singular point x* along a unit tangent line d (tangent_cone.hpp): hold the
//   unknown j with the largest |d_j| at x*_j + h d_j and Newton-project x* + h d. Away from
//   x* the branch is regular for the held unknown, so Newton converges quadratically; the
//   returned point's chord (x - x*)/|x - x*| is compared with d to confirm the line.
//
// Units: radians. Dense linear algebra: meant for the small and medium patterns where
//   bifurcations are analysed (n up to a few hundred unknowns).
#include <Eigen/Core>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/branch_point_system.hpp"

namespace rigidfold {

struct LocatedSingularPoint {
  bool found = false;            // g changed sign over [xa, xb], the march converged and the
                                 // extended system converged to a point inside [xa, xb]
  Eigen::VectorXd x;             // the point (unknowns, radians), on the manifold
  double parameter = 0.0;        // s* = ta . (x* - xa), pseudo-arclength from xa (radians)
  double error_bound = 0.0;      // bound on |x - x*|_2 over the unknowns (radians), so on
                                 // every fold angle; from refinement (+inf if not converged)
  BranchPointSolve refinement;   // stage 2: iterations, residuals, the bound's ingredients
  int steps = 0;                 // marching steps (stage 1)
  double residual = 0.0;         // ||r(x)||_inf
  int evaluations = 0;           // Newton projections made
  // Independent check: singular values of J(x) there. At a bifurcation of a 1-DOF path the
  // kernel grows to 2: sigma_{n-1} (second smallest of the n) is ~0.
  double sigma_max = 0.0, sigma_second_smallest = 0.0;
};

// Inputs: the system and the topology it was built from; two consecutive points xa, xb of a
// DOF-1 path (on the manifold); the march's stop on the change of its secant estimate
// (radians; stage 1 only). Returns found = false when g does not change sign between them,
// the march fails, or the extended system does not converge inside the bracket.
LocatedSingularPoint locate_singular_point(const ClosureSystem& system, const Topology& topology,
                                           const Eigen::VectorXd& xa, const Eigen::VectorXd& xb,
                                           double parameter_tolerance = 1e-10);

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
