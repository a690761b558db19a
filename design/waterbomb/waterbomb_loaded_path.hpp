#pragma once
// The waterbomb base under displacement control on the general model:
// at each prescribed vertex height h = r cos(theta) the loaded equilibrium of the full
// 2n-crease vertex (kernel/energy/vertex_height_control.hpp: supports at the valley ends, no
// symmetry imposed), its reaction force (the Lagrange multipliers) beside the virtual-work
// closed form (waterbomb_force.hpp), and its stability. With the height held, the symmetric
// motion has no freedom left, so a negative eigenvalue of the reduced Hessian is an
// asymmetric mode: the loaded symmetric state buckles (symmetry breaking) there.
// r is the valley crease length of the generated base (cos(pi/n) for radius 1); forces are
// in (energy unit of k) per length unit.
//
// Through the flat state: samples on the near side (theta < pi/2, vertex above its supports)
// start from the symmetric closed form at their theta. The far side is reached by
// continuation from the flat state along the one branch of its tangent cone that keeps the
// M/V letters (waterbomb_flat_crossing.hpp): the first start is that ray to first order, the
// next ones a secant predictor in t = acos(h / r) (the height's angle, smooth up to the limit
// where h itself flattens), with hidden steps of at most kMaxHeightStep * r in height and
// kMaxAngleStep in t between samples. No such branch (or more than one): the far-side samples are returned
// unconverged and `stopped_at_flat` says why. The closed form is compared, never used, there.
#include <string>
#include <vector>

#include "design/waterbomb/waterbomb_energy.hpp"
#include "design/waterbomb/waterbomb_flat_crossing.hpp"

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
  // Only when some theta > pi/2: the flat state's cone and the branch taken.
  bool crosses_flat = false;
  FlatCrossing flat_crossing;
  bool stopped_at_flat = false;
  std::string stop_message;  // why the far side has no points (flat crossing or a failed continuation step)
};

struct LoadedPathOptions {
  // Creases (edge indices of the generated base) whose M/V letter is read reversed when the
  // branch through flat is chosen (the springs keep the base's letters): to ask what happens
  // when no cone branch keeps the letters.
  std::vector<int> flipped_letters;
  static constexpr double kMaxHeightStep = 0.1;  // far-side continuation step, times r
  static constexpr double kMaxAngleStep = 0.1;   // and in t = acos(h / r), radians
};

// Inputs: n >= 3, theta0, k_m, k_v as waterbomb_bistability; thetas (radians) in
// (0, theta_limit(n)), none at pi/2 (the flat state is singular). Throws InputError for bad
// input; points that do not converge are returned with converged = false.
// Throws InputError("flipped_letters") for an index that is not one of the 2n creases.
LoadedPath waterbomb_loaded_path(int n, double theta0, double k_m, double k_v, const std::vector<double>& thetas,
                                 const LoadedPathOptions& options = {});

}  // namespace rigidfold::waterbomb
