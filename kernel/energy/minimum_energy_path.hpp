#pragma once
// Minimum-energy path and barrier between two stable states of a crease-spring pattern, on
// the loop-closure manifold, no symmetry imposed (the barriers both ways, for
// waterbomb bistability).
//
// Method.
//   1. String method with a climbing image (E, Ren & Vanden-Eijnden 2007; Henkelman et al.
//      2000 for the climbing image). The images are vectors of free fold angles x kept ON
//      the manifold r(x) = 0: each one is moved by the energy gradient projected on the
//      manifold's tangent space (the null space N of J = dr/dx, as in
//      constrained_equilibrium.hpp), f = -N N^T g, then put back on the manifold by the
//      corrector (newton_project, 1e-12 rad). The string starts as the straight segment from
//      x_a to x_b and, where the flat state (free fold angles 0) closes, a second time as the
//      two segments x_a -> flat -> x_b (a start far off the manifold can be thrown onto another
//      of its sheets by the corrector); the found path with the lower top is returned. Its
//      interior images moved by a small pseudo-random offset (seeded, the same
//      on every platform) and projected: a symmetric pattern between symmetric states would
//      otherwise keep a symmetric string forever, even where its top is a cusp (the flat
//      state of a waterbomb) that an unsymmetric path avoids. After each step the images are redistributed at equal arc
//      length along the polyline (fold-angle space, radians) and projected again. Once the
//      perpendicular force is small the highest interior image climbs: its force along the
//      path tangent tau is reversed, f = -P g + 2 (tau . P g) tau, and the two halves of the
//      string are redistributed separately so it stays an image.
//   2. Refinement: Newton on the stationarity of the Lagrangian (g + J^T lambda = 0,
//      r = 0) from the climbing image, in tangent coordinates: p = -N H_r^-1 N^T g with
//      H_r = N^T (diag k + sum lambda_k Hess r_k) N the reduced Hessian (full Newton: it
//      converges to a saddle as to a minimum), then projected onto the manifold.
//   3. Verification (analyse_equilibrium): closure <= 1e-12 rad, reduced gradient
//      |N^T g|_inf <= equilibrium.stationarity_tolerance * max(k_max * 1 rad, |g|_inf), and
//      the reduced Hessian has exactly one eigenvalue < -stability_tolerance * k_max and all
//      others > +stability_tolerance * k_max (an index-1 saddle, non-degenerate). Then the
//      two descents from the saddle along +-its negative eigenvector (find_equilibrium from
//      x_s +- descent_offset v, projected) must reach x_a and x_b (within
//      same_state_tolerance), one each: the saddle lies between THESE two states.
//   An image with a fold angle beyond +-pi ends the search ("not found"): the string has left
//   the range of fold angles.
//   4. When 2-3 fail and the climbing image is near the flat state (all free fold angles 0):
//      the flat state as a singular top. Checks: it closes (1e-12 rad), J has lower rank
//      there than at x_a (a singular point, where the string method's top is a cusp, not a
//      saddle: a flat-foldable vertex, e.g. the waterbomb base, whose two states lie on
//      opposite nappes of its tangent cone, so a path near flat must pass through it); the
//      string with its climbing image pinned at flat relaxes to string_tolerance; the energy
//      rises strictly along it from each end to flat. Then top = kSingularPoint and the
//      barriers are E_flat - E_a and E_flat - E_b. Whether a path far from flat is lower is
//      not decided.
//   A barrier is reported only when every check passed (found == true); otherwise `message`
//   says which one failed and the barrier fields are NaN.
//
// Inputs: system, topology (the one the system was built from), springs (one entry per
//   edge); x_a, x_b: free fold angles (radians, system order) of two stable states (on the
//   manifold; each is projected first).
// Outputs: MinimumEnergyPath below. Units: radians; energy in the stiffness unit times rad^2.
// Cost: per string iteration, one dense SVD of J and up to two Newton projections per image
//   (O(images * rows * unknowns^2)); the string stops after max_iterations iterations, or
//   earlier when its force has not halved for stall_iterations; two starts where flat closes.
//   Meant for the patterns the stable-state search takes (kMaxSpringStateFreeCreases); on the
//   8-crease waterbomb base one pair takes ~0.1-0.3 s in Release.
// Limits: a search, not a proof. The string finds A minimum-energy path (the one the
//   straight start leads to), not necessarily the lowest of all; a path whose top is a
//   singular point of the manifold (e.g. the flat state of a flat-foldable vertex, where the
//   energy has a cusp, not a saddle) has no index-1 saddle: "not found", with the reason.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct MinimumEnergyPathOptions {
  int images = 17;                  // string images including both ends (>= 5)
  // Offset of the start's interior images (radians, each component uniform in +-this, times
  // sin(pi s) at arc fraction s so the ends stay); 0: the plain straight segment.
  double initial_perturbation = 0.05;
  std::uint64_t seed = 1;
  int max_iterations = 3000;        // string iterations at most
  // String step: dt = step_fraction / (largest reduced-Hessian eigenvalue at the two ends),
  // each image's move capped at max_image_step (radians, inf-norm).
  double step_fraction = 0.5;
  double max_image_step = 0.05;
  // The string is converged when every interior image's force (perpendicular part; the
  // climbing image's whole force) is <= string_tolerance * k_max (energy / rad). Loose on
  // purpose: the Newton refinement does the rest.
  double string_tolerance = 1e-5;
  // The highest image starts climbing when the perpendicular force is <= climb_tolerance * k_max.
  double climb_tolerance = 1e-2;
  // Once climbing, the string stops (not converged) when its force has not halved for this
  // many iterations: a climbing image on a cusp oscillates forever.
  int stall_iterations = 150;
  int newton_iterations = 50;       // refinement steps at most
  double max_newton_step = 0.1;     // radians, inf-norm
  double descent_offset = 1e-3;     // radians: the descents start this far from the saddle
  // A climbing image within this distance of the flat state (radians, inf-norm) that fails
  // the saddle checks is tried as a singular top (step 4 of the header).
  double singular_top_radius = 0.2;
  double same_state_tolerance = 1e-6;  // radians (inf-norm over edges): a descent reached x_a / x_b
  EquilibriumOptions equilibrium;   // closure, stationarity, rank and stability tolerances
};

// What the top of a found path is.
enum class PathTop {
  kNone,           // not found
  kSaddle,         // an index-1 saddle, checked as in step 3 of the header
  kSingularPoint,  // the flat state, a singular point of the manifold where the energy has a cusp
};
const char* to_string(PathTop top);  // "none", "index-1 saddle", "singular point (flat state, cusp)"

struct PathImage {
  Eigen::VectorXd edge_angles;  // per edge (radians)
  double energy = 0.0;
};

struct MinimumEnergyPath {
  bool found = false;          // every check of the header passed (for `top`)
  PathTop top = PathTop::kNone;
  std::string message;         // why not found ("" when found)
  std::string start;           // "straight" or "through the flat state": the start of the path returned
  bool string_converged = false;
  int string_iterations = 0;
  double string_force = 0.0;   // the largest image force at the end (energy / rad)
  std::vector<PathImage> images;  // the string, x_a first, x_b last
  int climbing_image = -1;     // index into images
  int newton_iterations = 0;
  // The refined point, analysed (converged = stationary and closed). Filled whenever the
  // refinement ran, also when a check failed. For a singular top: the flat state analysed
  // (not stationary: the energy has a cusp there, converged is false).
  Equilibrium saddle;
  int negative_eigenvalues = -1;  // of the reduced Hessian at the saddle, below -threshold
  bool connects = false;       // the two descents reach x_a and x_b
  // The stable states (edge angles) the descents from an index-1 saddle reached, converged
  // ones only (0-2 entries): where a saddle that fails `connects` leads instead.
  std::vector<Eigen::VectorXd> descent_ends;
  double energy_a = 0.0, energy_b = 0.0;
  double barrier_from_a = 0.0;  // E_saddle - E_a (NaN unless found)
  double barrier_from_b = 0.0;  // E_saddle - E_b (NaN unless found)
};

// Throws std::invalid_argument for sizes that do not match the system or options out of
// range (images < 5, non-positive steps or tolerances). Never throws for non-convergence.
MinimumEnergyPath minimum_energy_path(const ClosureSystem& system, const Topology& topology, const CreaseSprings& springs,
                                      const Eigen::VectorXd& x_a, const Eigen::VectorXd& x_b,
                                      const MinimumEnergyPathOptions& options = {});

}  // namespace rigidfold
