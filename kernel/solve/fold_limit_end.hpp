#pragma once
// The end of a traced branch at a fold limit: the configuration where a crease is exactly at
// +-pi (its two faces close on each other: local facet interference, or the fully folded
// state). The one implementation every tracer uses (branch explorer, given-state mobility,
// trace_motion).
//
// Method: start from the linear interpolation x_before + fraction * (x_after - x_before)
// (the crossing PathWatch reports), put the crease's unknown at +-pi (the sign of x_after),
// and Newton-project with that unknown held (minimum-norm steps). Creases that land beyond
// +-pi (they reach it at the same point, e.g. by symmetry) are then held at +-pi as well and
// the point projected again, at most twice. The result is accepted
// when the projection converges (||r||_inf <= tolerance), no crease is beyond +-pi, and it
// lands within max_distance
// (inf-norm, radians) of the start: near a singular end a projection can land on another
// branch, which is no end of this one.
//
// Inputs: the closure system; the unknown vectors of the last two accepted points; the
//   crease (pattern edge index, must be a free unknown); fraction in [0, 1].
// Output: the unknowns of the end point, or nothing (the caller then ends the branch at
//   x_before and says the end was not solved).
// Cost: one Newton projection (a few sparse factorisations).
#include <Eigen/Core>
#include <optional>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

struct FoldLimitEnd {
  Eigen::VectorXd x;       // unknowns at the end
  double residual = 0.0;   // ||r||_inf there (radians)
};

std::optional<FoldLimitEnd> solve_fold_limit_end(const ClosureSystem& system, const Eigen::VectorXd& x_before,
                                                 const Eigen::VectorXd& x_after, int crease, double fraction,
                                                 double tolerance = 1e-12, double max_distance = 0.1);

}  // namespace rigidfold
