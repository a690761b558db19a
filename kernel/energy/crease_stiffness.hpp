#pragma once
// Torsional stiffness of the creases: the k of each crease spring (crease_energy.hpp).
//
// A crease made as a small-length flexural pivot (seed 004, eqs 2.9-2.11) is a thin strip
// bent over its free length l:   k = E * I / l,  I = b * h^3 / 12,  so  k = E b h^3 / (12 l).
// Seed 004 Table 2.1 (metallic glass, E = 93 GPa, b = 50 mm, h = 0.02032 mm,
// l = 0.714 mm) gives k = 0.00455 N m/rad.
#include <Eigen/Core>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// Inputs (SI, any consistent set works): youngs_modulus E [Pa], width b along the crease
//   [m], thickness h [m], free flexure length l across the crease [m].
// Output: k [N m / rad] (energy per radian squared).
// Throws InputError (place "youngs_modulus", "width", "thickness" or "length") unless every
// input is finite and > 0, and if the result is not finite.
double flexure_stiffness(double youngs_modulus, double width, double thickness, double length);

// Stiffness per crease letter (N m / rad, >= 0). B, C, F and J edges get no spring.
struct StiffnessByAssignment {
  double mountain = 1.0;
  double valley = 1.0;
  double unassigned = 1.0;
};

// One stiffness per edge of `pattern` (size num_edges()), from the edge's letter.
// Throws InputError (place "stiffness.mountain" / ".valley" / ".unassigned") for a negative
// or non-finite value.
Eigen::VectorXd stiffness_by_assignment(const CreasePattern& pattern, const StiffnessByAssignment& k);

}  // namespace rigidfold
