#pragma once
// Force-deflection of the symmetric waterbomb base by virtual work (seed 004 eq. 3.9; 2.14
// for n = 4): a vertical force F at the vertex, frictionless vertical supports at the outer
// ends of the valley creases (distance r from the vertex along the crease).
//
//   h = r cos(theta)                 vertex height above the support plane
//   delta = r (cos theta0 - cos theta)   push displacement from the rest state
//   F = dV/d(delta) = V'(theta) / (r sin theta)    F > 0 pushes the vertex toward the plane
//
// At the flat state (theta = pi/2) the path has a corner, so F jumps: F(pi/2-) is the largest
// push before snap-through under force control, F(pi/2+) the pull at which it returns.
// Units: r in any length unit; F in (energy unit of k) / (that length unit).
// Closed form on the symmetric path only; the general model's reaction force (the Lagrange
// multiplier of a height constraint on the unsymmetric problem) is not implemented yet.
#include <vector>

#include "design/waterbomb/waterbomb_energy.hpp"

namespace rigidfold::waterbomb {

struct ForcePoint {
  double theta = 0.0;  // radians
  double height = 0.0;  // h = r cos theta
  double deflection = 0.0;  // delta = r (cos theta0 - cos theta)
  double force = 0.0;
};

// F at theta (side -1 / +1 picks the one-sided value at theta = pi/2). theta0 (radians) is
// the rest angle for the deflection. Throws InputError("r") unless r is finite and > 0,
// InputError("theta") at theta = 0 or pi where sin theta = 0 (and outside the valid range).
ForcePoint waterbomb_force(const WaterbombSprings& s, double theta0, double r, double theta, int side = 0);

}  // namespace rigidfold::waterbomb
