#pragma once
// Spring energy of the symmetric waterbomb base along its 1-DOF path and its equilibria
// (seed 004 eqs 3.8, 2.12-2.13; bistability procedure of ch. 2.4 / 3.3.2).
//
//   V(theta) = (n/2) [k_m (gamma_m - gamma_m0)^2 + k_v (gamma_v - gamma_v0)^2]
//
// the crease-spring energy sum 1/2 k (rho - rhobar)^2 of the 2n creases at the symmetric
// state (kernel/energy/crease_energy.hpp gives the same number on the generated pattern).
// Units: angles radians; k in energy / rad^2 (N m / rad); V in the unit of k times rad^2.
#include <vector>

#include "design/waterbomb/waterbomb_kinematics.hpp"

namespace rigidfold::waterbomb {

struct WaterbombSprings {
  int n = 4;
  double k_m = 1.0;       // stiffness of each mountain crease (>= 0)
  double k_v = 1.0;       // stiffness of each valley crease (>= 0)
  FoldPair rest;          // rest fold angles (gamma_m0, gamma_v0), radians
};

// Springs whose rest state is the path point theta0 (radians). Throws InputError naming
// "n", "theta0" (outside [0, theta_limit(n)] or not finite) or "k_m" / "k_v" (negative,
// not finite, or both zero).
WaterbombSprings springs_at_rest_theta(int n, double theta0, double k_m, double k_v);

double waterbomb_energy(const WaterbombSprings& s, double theta);
// dV/dtheta; at theta = pi/2 the one-sided value (side -1 below, +1 above).
double waterbomb_energy_slope(const WaterbombSprings& s, double theta, int side = 0);

enum class EquilibriumKind { kMinimum, kMaximum, kCuspMaximum, kCuspMinimum };
// "minimum", "maximum", "cusp maximum (flat state)", "cusp minimum (flat state)".
const char* to_string(EquilibriumKind kind);

struct PathEquilibrium {
  EquilibriumKind kind = EquilibriumKind::kMinimum;
  double theta = 0.0;          // radians
  FoldPair angles;             // (gamma_m, gamma_v) at theta, radians
  double energy = 0.0;
  // |dV/dtheta| at theta (energy / rad): the equilibrium condition's residual; for a
  // cusp (the flat state) the two one-sided slopes are reported instead in slope_below/above.
  double slope_residual = 0.0;
  double slope_below = 0.0, slope_above = 0.0;
  bool at_validity_limit = false;  // a minimum sitting on a contact limit (theta = 0 or theta_limit)
};

// Every equilibrium of V on [0, theta_limit(n)], in increasing theta: smooth minima and
// maxima (roots of dV/dtheta, bracketed on a grid of 2 x 512 intervals and bisected to
// adjacent doubles), the flat state theta = pi/2 (a cusp), and minima on the validity
// limits (flagged: contact, not a free equilibrium).
std::vector<PathEquilibrium> waterbomb_path_equilibria(const WaterbombSprings& s);

}  // namespace rigidfold::waterbomb
