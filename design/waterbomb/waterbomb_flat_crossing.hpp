#pragma once
// Which branch the loaded waterbomb path takes through the flat state.
//
// The flat state is a bifurcation point: the M/V-preserving symmetric branch and its
// all-reversed mirror meet there, and the loaded path has a corner. The branch on the far
// side (vertex below its supports, height < 0) is chosen from the tangent cone of the
// closure system (kernel/solve/tangent_cone.hpp) at x = 0, never from a closed form:
//   - system: the base's closure rows plus the equalities of the symmetric motion: the
//     creases of one motion class fold together (plain base: crease 2k = crease 0, crease
//     2k+1 = crease 1, the generator's order; split fold: every half-valley equal, every
//     half-mountain equal). Without them the flat-state cone of one vertex is a quadric
//     continuum (one quadratic condition on a many-dimensional kernel), with no discrete
//     branches to pick; with a 1-DOF symmetric motion it has isolated lines: its branches.
//     A cone without isolated lines (e.g. the split fold with its rotational symmetry only:
//     4 angles per period, one closure condition, a 3-DOF family) stops the path, saying so;
//   - every line gives two rays (branches leaving flat); each ray's first-order vertex
//     height rate dh/ds is the offset of the plane fitted through the supports' far ends
//     (first-order positions in crease 0's frame, +z the sheet's side that is up at rest);
//   - far-side rays (dh/ds < 0) are kept when every M/V crease's direction entry has its
//     letter's sign (|entry| <= Tolerances::sign_threshold: no sign, never wrong).
// Exactly one letter-keeping far-side ray: the path continues along it. None, or more than
// one: `continues` is false and `message` says why (no silent choice).
//
// Units: directions are unit vectors of per-edge fold angles (radians per unit arc length);
// height rates in the pattern's length unit per unit arc length.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::waterbomb {

struct FlatBranch {
  Eigen::VectorXd direction;     // per edge, unit
  double height_rate = 0.0;      // dh/ds: > 0 the vertex rises above its supports
  bool far_side = false;         // height_rate < 0
  bool keeps_letters = false;
  int first_wrong_crease = -1;   // the first M/V crease whose sign contradicts its letter
};

struct FlatCrossing {
  int kernel_dimension = 0;      // first-order DOF of the symmetric system at flat
  int cone_lines = 0;            // isolated tangent lines of the cone
  std::vector<FlatBranch> branches;  // two rays per line (c, then -c)
  int far_side_branches = 0;
  int letter_keeping = 0;        // far-side branches that keep the letters
  int taken = -1;                // index into branches, -1 when the path stops at flat
  bool continues = false;
  std::string message;           // why it stops (empty when it continues)
};

// Inputs: a single-vertex base whose vertex 0 is the interior centre (creases in its fan;
// only their assignments are read as letters, so a caller may flip some), the support creases
// (their far ends rest on the plane; for the split fold the half-valleys, whose ends span the
// plane through the split facets' outer-edge midpoints), and the motion classes: every fan
// crease in exactly one class, the creases of a class fold by the same angle.
// Throws std::invalid_argument for a pattern without such a vertex, a support or class crease
// not in its fan, or classes that do not partition the fan.
FlatCrossing waterbomb_flat_crossing(const CreasePattern& base, const std::vector<int>& support_edges,
                                     const std::vector<std::vector<int>>& motion_classes);

// The plain base from data/generators/waterbomb.hpp (creases 0..2n-1 in CCW order): the
// motion classes are the even and the odd creases.
FlatCrossing waterbomb_flat_crossing(const CreasePattern& base, const std::vector<int>& support_edges);

}  // namespace rigidfold::waterbomb
