#pragma once
// The waterbomb base's energy and force-deflection curves, sampled for plotting (the
// figures of seed 004 Figs 2.9-2.11 and 3.x). Each sample pairs the closed forms on the
// symmetric 1-DOF path (waterbomb_energy.hpp, waterbomb_force.hpp) with the general model's
// loaded equilibrium at the same vertex height (waterbomb_loaded_path.hpp: the full 2n-crease
// vertex, no symmetry imposed, reaction force from the Lagrange multipliers).
// A sample is `checked` only when the general model converged, lands on the symmetric closed
// form (fold angles within kFoldAngleAgreement) and its force agrees with eq. 3.9 (within
// kForceAgreement relative to max(1, |F|)); unchecked samples keep only their theta.
// Units: angles radians; energy in the unit of k times rad^2; lengths in the generated base's
// units (radius 1, valley crease length r = cos(pi/n)); force in energy unit per length unit.
#include <string>
#include <vector>

#include "design/waterbomb/waterbomb_energy.hpp"
#include "design/waterbomb/waterbomb_loaded_path.hpp"

namespace rigidfold::waterbomb {

struct CurveSample {
  double theta = 0.0;        // radians, the symmetric path parameter
  FoldPair angles;           // (gamma_m, gamma_v), radians
  double energy = 0.0;       // V(theta)
  double height = 0.0;       // vertex height r cos theta
  double deflection = 0.0;   // r (cos theta0 - cos theta)
  double force = 0.0;        // general model's reaction force (push > 0)
  double force_closed_form = 0.0;
  double min_eigenvalue = 0.0;  // reduced Hessian of the loaded equilibrium
  bool stable = false;          // under displacement control
  bool checked = false;
};

struct WaterbombCurve {
  std::vector<CurveSample> samples;  // increasing theta, the flat state excluded
  int unchecked = 0;                 // samples whose checks failed (numbers not to be shown)
  // The flat state's tangent cone and the branch the general model continued along
  // (waterbomb_loaded_path.hpp); stopped_at_flat: the far-side samples are unchecked, why.
  FlatCrossing flat_crossing;
  bool stopped_at_flat = false;
  std::string stop_message;
  static constexpr double kFoldAngleAgreement = 1e-9;  // radians
  static constexpr double kForceAgreement = 1e-9;      // relative
};

// `samples` >= 3 points evenly spaced over (0, theta_limit(n)), each end kept 1e-3 of the
// range inside and the flat state pi/2 nudged by the same amount to the side it is on.
// Throws InputError for bad n, theta0, stiffness (as waterbomb_bistability) or
// InputError("samples") outside [3, 2001].
// options: passed to waterbomb_loaded_path (letters read reversed at the flat crossing).
WaterbombCurve waterbomb_curve(int n, double theta0, double k_m, double k_v, int samples,
                               const LoadedPathOptions& options = {});

}  // namespace rigidfold::waterbomb
