#pragma once
// Tangent cone of the constraint manifold r(x) = 0 at a point that may be singular
// (docs/DESIGN.md, "Bifurcation"): the directions in which curves of solutions leave the point.
//
// First order: a tangent lies in the kernel of J, t = N c (N: orthonormal kernel basis,
//   k = dim). Second order: r(x(s)) = 0 along a curve x(s) = x + s t + s^2/2 w needs
//   J w + D^2 r[t, t] = 0, solvable iff the quadratic term vanishes on the left null space
//   U of J (p = dim):       q_j(c) = u_j^T D^2 r(x)[N c, N c] = 0,   j = 1..p.
//   The cone is the set of unit c solving these p homogeneous quadratics. A point is
//   REGULAR when p = 0 after removing redundant rows, i.e. rank J = m (never the case
//   for a redundant system) -- so instead we test: if every q_j vanishes identically the
//   whole kernel is tangent (regular, dimension k manifold).
//   Solutions come in lines (c and -c): each line is a branch through the point, traced
//   both ways. At the flat state of a flat-foldable pattern first-order rank says nothing
//   (every vertex loses its normal row); the quadratic conditions sort the kernel into the
//   real folding branches.
// Method: dense SVD of J (the point's Jacobian; meant for singular points of patterns up to
//   a few hundred creases), quadratic forms H_j (k x k) by exact polarisation of
//   closure_second_derivative, then Gauss-Newton on [q(c); |c|^2 - 1] = 0 from
//   deterministic pseudo-random unit starts; solutions merged up to sign.
//   A line is ISOLATED when the quadratics' gradients span the sphere's tangent space at c
//   (rank k - 1); otherwise the cone there is a continuum (e.g. a multi-DOF point) and the
//   directions returned are samples of it.
// The second-order cone is necessary, not sufficient: a direction can fail at higher
//   order. Callers confirm each line by leaving the point along it (bifurcation.hpp).
//
// Units: x in radians; directions are unit vectors in unknown space.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct TangentConeOptions {
  double rank_tolerance = 1e-8;       // singular values <= this * sigma_max count as zero
  int starts = 240;                   // Gauss-Newton starts on the unit sphere of the kernel
  std::uint64_t seed = 7;
  double quadratic_tolerance = 1e-9;  // |q(c)|_inf <= this * max_j |H_j| accepts a solution
  double same_line = 1e-6;            // 1 - |c1 . c2| below this: same line
  int max_lines = 64;
};

struct TangentLine {
  Eigen::VectorXd direction;          // unit, in unknown space; its largest entry is > 0
  double quadratic_residual = 0.0;    // |q(c)|_inf / max_j |H_j|
  bool isolated = true;
};

struct TangentCone {
  int kernel_dimension = 0;           // k = n - rank J (first-order DOF)
  int left_null_dimension = 0;        // p = m - rank J (quadratic conditions)
  double sigma_max = 0.0, sigma_smallest_kept = 0.0, sigma_largest_dropped = 0.0;
  bool quadratics_vanish = false;     // every q_j is identically 0: the whole kernel is tangent
  Eigen::MatrixXd kernel;             // n x k, orthonormal
  std::vector<TangentLine> lines;     // the branches' tangent lines (when quadratics_vanish: the kernel
                                      // itself if it is one line, else none: a continuum)
};

// Inputs: system, the topology it was built from, a point x on the manifold (radians).
TangentCone tangent_cone(const ClosureSystem& system, const Topology& topology, const Eigen::VectorXd& x,
                         const TangentConeOptions& options = {});

}  // namespace rigidfold
