#pragma once
// Bistability of a symmetric waterbomb base (seed 004 ch. 2.4, 3.3): the equilibria of the
// spring energy along the symmetric path (closed form, waterbomb_energy.hpp), each checked
// before it is returned:
//   - the fold angles close the vertex loop of the generated base (closure residual, rad);
//   - dV/dtheta = 0 on the path (slope residual, energy / rad);
//   - the state is an equilibrium of the UNRESTRICTED problem on the generated 2n-crease
//     pattern (kernel/energy/constrained_equilibrium.hpp: stationarity |N^T g|) and its
//     stability there is the smallest eigenvalue of the reduced Hessian of the Lagrangian
//     (2n - 3 tangent directions, no symmetry imposed).
// The flat state (theta = pi/2) is a cusp of V and a singular point of the closure manifold:
// it is reported with its one-sided slopes, not analysed by the kernel.
#include <vector>

#include "design/waterbomb/waterbomb_energy.hpp"

namespace rigidfold::waterbomb {

struct CheckedEquilibrium {
  PathEquilibrium path;
  double closure_residual = 0.0;       // radians
  double stationarity_residual = 0.0;  // unrestricted |N^T g|_inf (energy / rad); 0 for the cusp
  double min_reduced_eigenvalue = 0.0; // unrestricted reduced Hessian (energy / rad^2); NaN for the cusp
  bool stable_unrestricted = false;    // positive definite reduced Hessian
};

struct WaterbombBistability {
  WaterbombSprings springs;
  double theta0 = 0.0;                         // radians
  std::vector<CheckedEquilibrium> equilibria;  // increasing theta
  // Path minima that are also unrestricted minima, not on a contact limit.
  std::vector<CheckedEquilibrium> stable_states() const;
  // From each stable state, the energy to climb to the flat cusp maximum along the symmetric
  // path (empty when the flat state is no cusp maximum). An unsymmetric path between the
  // states may cross lower: not searched here.
  struct Barrier {
    double from_theta = 0.0;  // the stable state's theta (radians)
    double height = 0.0;      // cusp energy - its energy
  };
  std::vector<Barrier> symmetric_path_barriers() const;
};

// Inputs: n >= 3, theta0 (radians, in [0, theta_limit(n)]), k_m, k_v >= 0 (not both 0;
//   energy / rad^2). Throws InputError naming "n", "theta0", "k_m" or "k_v" for bad input
//   and NoAnswerError (with the residual) if an equilibrium fails its check: closure
//   > 1e-12 rad, path slope or unrestricted stationarity > 1e-10 x the stiffness scale.
WaterbombBistability waterbomb_bistability(int n, double theta0, double k_m, double k_v);

}  // namespace rigidfold::waterbomb
