#pragma once
// The waterbomb base under displacement control on the general model (issue 14 item 3):
// at each prescribed vertex height h = r cos(theta) the loaded equilibrium of the full
// 2n-crease vertex (kernel/energy/vertex_height_control.hpp: supports at the valley ends, no
// symmetry imposed), its reaction force (the Lagrange multipliers) beside the virtual-work
// closed form (waterbomb_force.hpp), and its stability. With the height held, the symmetric
// motion has no freedom left, so a negative eigenvalue of the reduced Hessian is an
// asymmetric mode: the loaded symmetric state buckles (symmetry breaking) there.
// r is the valley crease length of the generated base (cos(pi/n) for radius 1); forces are
// in (energy unit of k) per length unit.
#include <vector>

#include "design/waterbomb/waterbomb_energy.hpp"

namespace rigidfold::waterbomb {

struct LoadedPoint {
  double theta = 0.0;             // radians (the symmetric start's; the solution's height is r cos theta)
  double height = 0.0;
  double deflection = 0.0;        // r (cos theta0 - cos theta)
  double force = 0.0;             // general model: -sum of the support multipliers
  double force_closed_form = 0.0; // eq. 3.9
  double fold_angle_gap = 0.0;    // |general - symmetric closed form|_inf (radians)
  double min_eigenvalue = 0.0;    // reduced Hessian of the Lagrangian
  bool converged = false;
  bool stable = false;
};

struct LoadedPath {
  std::vector<LoadedPoint> points;
  // theta (radians) where the smallest eigenvalue crosses 0 between consecutive points,
  // bisected to 1e-10 rad: where the loaded symmetric state gains or loses stability.
  std::vector<double> stability_changes;
};

// Inputs: n >= 3, theta0, k_m, k_v as waterbomb_bistability; thetas (radians) in
// (0, theta_limit(n)), none at pi/2 (the flat state is singular). Throws InputError for bad
// input; points that do not converge are returned with converged = false.
LoadedPath waterbomb_loaded_path(int n, double theta0, double k_m, double k_v, const std::vector<double>& thetas);

}  // namespace rigidfold::waterbomb
