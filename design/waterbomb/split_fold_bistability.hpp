#pragma once
// Bistability of the split-fold waterbomb base (SFWB, seed 004 ch. 3.2.2 / 3.4): the
// equilibria of the spring energy along the symmetric split-fold path and its energy and
// force-deflection curves, each number confirmed on the general 4n-crease model before it is
// returned.
//
//   V(theta) = n [k_m (gamma_m - gamma_m0)^2 + k_v (gamma_v - gamma_v0)^2]     (eq. 3.31)
//
// the crease-spring energy sum 1/2 k (rho - rhobar)^2 of the 2n half-mountains and 2n
// half-valleys, with (gamma_m, gamma_v)(theta) the printed forms (split_fold_kinematics.hpp)
// on their contact-limited range [theta*, theta_max], and the rest state the path point theta0.
//
// The seed's derivatives (3.33)-(3.49) are not implemented, so the equilibria are not roots
// of a closed-form slope. Instead:
//   - V is sampled on the printed forms (2 x 256 intervals each side of flat) to bracket its
//     interior extrema;
//   - each bracket is refined on the general model: the vertex held at height h = r cos theta
//     above the plane through the half-valley ends (kernel/energy/vertex_height_control.hpp, no
//     symmetry imposed; r = cos(b/2), the vertex-to-support distance of the unit-crease base
//     along a valley split-facet centreline, so the supports are the outer-edge midpoints of
//     the seed), whose reaction force F(theta) is continuous inside one side of flat; its root
//     (TOMS 748 to adjacent doubles) is a free equilibrium, a maximum as well as a minimum;
//   - at the root, the unloaded equilibrium conditions on the unrestricted 4n-crease problem
//     (kernel/energy/constrained_equilibrium.hpp): stationarity |N^T g| and the smallest
//     reduced-Hessian eigenvalue (stability, 4n - 3 directions);
//   - the state must be symmetric (all half-valleys equal, all half-mountains equal, to
//     kSymmetryTolerance) and lie on the printed path: theta read back from gamma_m, the printed
//     gamma_v there within kPathAgreement.
// The flat state (theta = pi/2, every fold 0) is a cusp of V and a singular point of the
// closure manifold: reported with its one-sided slopes dV/dtheta taken from the general model's
// force 1e-4 rad either side (1e-3 or 1e-2 rad where the height control does not converge that
// close), not analysed by the kernel.
// Minima on the contact limits theta*, theta_max are flagged (contact, not free equilibria).
// Units: angles radians; k energy / rad^2; V in the unit of k times rad^2; lengths in the
// unit-crease base's units; force in energy / length, F > 0 pushing the vertex toward the supports.
#include <string>
#include <vector>

#include "design/waterbomb/split_fold_kinematics.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_curve.hpp"
#include "design/waterbomb/waterbomb_flat_crossing.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::waterbomb {

// The split-fold base as one interior vertex with 4n unit creases in the order
// [half-V | b | half-V | alpha | half-M | b | half-M | alpha] x n (edges 0..4n-1: crease i,
// valley when i % 4 < 2), boundary chords (edges 4n..8n-1) and 4n triangular faces.
// Throws InputError("b") / ("n") as split_fold_angles_printed.
CreasePattern split_fold_base(int n, double b);

struct SplitFoldSprings {
  int n = 4;
  double b = 0.0;            // split-facet sector (radians)
  double k_m = 1.0, k_v = 1.0;  // per half-fold (energy / rad^2)
  FoldPair rest;             // rest (gamma_m0, gamma_v0), radians
  SplitFoldRange range;      // contact limits (radians)
};

// Springs whose rest state is the path point theta0 (radians, in [theta*, theta_max]).
// Throws InputError naming "n", "b", "theta0", "k_m" or "k_v".
SplitFoldSprings split_fold_springs(int n, double b, double theta0, double k_m, double k_v);

// V(theta) on the printed forms; the flat state pi/2 gives n (k_m gm0^2 + k_v gv0^2) exactly.
// Throws InputError("theta") outside the contact limits.
double split_fold_energy(const SplitFoldSprings& s, double theta);

struct SplitFoldBistability {
  SplitFoldSprings springs;
  double theta0 = 0.0;
  double support_distance = 0.0;                // r = cos(b/2)
  std::vector<CheckedEquilibrium> equilibria;   // increasing theta
  // Extrema of the printed V within one grid interval of a contact limit (where gamma_v has a
  // square-root onset, e.g. a maximum just above theta*) that the general model could not
  // confirm: not equilibria of this result, listed so that they are not silently dropped.
  struct Unconfirmed {
    double theta_lo = 0.0, theta_hi = 0.0;  // the bracket (radians)
    EquilibriumKind kind = EquilibriumKind::kMaximum;
    std::string why;
  };
  std::vector<Unconfirmed> unconfirmed_near_contact;
  std::vector<CheckedEquilibrium> stable_states() const;
  std::vector<WaterbombBistability::Barrier> symmetric_path_barriers() const;
  static constexpr double kSymmetryTolerance = 1e-9;  // radians
  static constexpr double kPathAgreement = 1e-9;      // radians (printed forms vs general state)
};

// Throws InputError for bad input (as split_fold_springs) and NoAnswerError (with the
// residual) when an equilibrium is not confirmed: the general model does not converge, the
// state is not symmetric or not on the printed path, or its unloaded stationarity exceeds
// 1e-10 x max(k_m, k_v).
SplitFoldBistability split_fold_bistability(int n, double b, double theta0, double k_m, double k_v);

// Energy and force-deflection samples (design/waterbomb/waterbomb_curve.hpp's CurveSample):
// `samples` thetas evenly over [theta*, theta_max] (ends kept 1e-2 of the range inside, where
// the printed forms turn singular; flat nudged by the same to its side). Each: the general model's loaded equilibrium at h = r cos
// theta (near side started on the printed path; far side by continuation from flat, see
// SplitFoldCurveOptions) (force = its reaction, stability = its reduced Hessian), checked when converged,
// symmetric and on the printed path (kPathAgreement); force_closed_form is dV/dh of the printed
// energy by central differences with two Richardson levels (steps 1e-3, 5e-4, 2.5e-4 rad), and a
// sample is checked only when the two forces agree within kForceAgreement x max(1, |F|).
// Switching force of the split fold under force control (as waterbomb_switching.hpp for the
// plain base): the largest push on [theta0, pi/2) along the symmetric path. There is no
// closed-form slope, so the push is the general model's reaction force: sampled on 64 points
// over [theta0, pi/2 - d], the largest refined by golden section to 1e-9 rad; when it is the
// last sample (the maximum sits at the flat corner), the one-sided limit F(pi/2-) is
// extrapolated linearly from the forces d and 2d before flat, d = 1e-4 rad (error O(d^2)), or
// 1e-3 / 1e-2 rad where the height control does not converge that close to flat.
// Checked: the general force equals dV/dh of the printed energy (two Richardson levels) within
// kForceAgreement x max(1, |F|) where the maximum is, or 1e-2 rad before flat when the maximum
// is closer to flat (there the printed forms lose digits and a difference quotient is noise).
// Needs theta0 < pi/2 - 2e-4.
// Throws InputError (as split_fold_springs; "theta0" at or past flat) and NoAnswerError when
// the general model does not converge or the check fails.
struct SplitFoldSwitching {
  double force = 0.0;
  double theta = 0.0;     // radians
  bool at_flat = false;
  double closed_form_gap = 0.0;  // |F - dV/dh of the printed energy| at the checked theta (0 if theta0 is past it)
};
SplitFoldSwitching split_fold_switching_force(int n, double b, double theta0, double k_m, double k_v);

// The mountain stiffness k_m (k_v fixed, > 0) whose split-fold switching force is `target` (> 0):
// at every theta the push is linear in k_m with a mountain term >= 0 before flat (as
// waterbomb_switching.hpp), so the switching force grows with k_m: bracketed (k_m = 0, then
// k_v x 4^j) and solved by TOMS 748 to 1e-13 relative, then checked: its switching force within
// 1e-9 x target. Throws InputError ("target", "k_v", and as split_fold_switching_force) and
// NoAnswerError when k_m = 0 already switches above the target or no k_m up to 1e12 k_v reaches it.
double split_fold_mountain_stiffness_for_switching_force(int n, double b, double theta0, double k_v, double target);

// The split fold's symmetric motion as motion classes of split_fold_base's creases (for
// waterbomb_flat_crossing): every half-valley (crease i, i % 4 < 2) one class, every
// half-mountain the other, i.e. the rotational symmetry C_n together with the mirror through
// each split facet's centreline (C_n alone leaves 4 angles per period and a 3-DOF family).
std::vector<std::vector<int>> split_fold_motion_classes(int n);

// Far side of flat (theta > pi/2) the curve is reached by continuation from the flat state
// along the one branch of its tangent cone that keeps the M/V letters
// (waterbomb_flat_crossing.hpp with split_fold_motion_classes, supports the half-valleys): the
// first start is that ray to first order, the next a secant predictor in theta, with hidden
// steps of at most kMaxHeightStep * r in height and kMaxAngleStep in theta between samples
// (flat_branch_continuation.hpp, shared with the plain base's loaded path). The printed forms are compared
// there (the checks above), never used as a start. No such branch, or more than one: the
// far-side samples are unchecked and stopped_at_flat says why.
struct SplitFoldCurveOptions {
  // Creases (0..4n-1) whose M/V letter is read reversed when the branch through flat is chosen
  // (the springs keep the base's letters): to ask what happens when no branch keeps them.
  std::vector<int> flipped_letters;
  static constexpr double kMaxHeightStep = 0.1;  // far-side continuation step, times r
  static constexpr double kMaxAngleStep = 0.1;   // and in theta, radians
};

struct SplitFoldCurve {
  std::vector<CurveSample> samples;
  int unchecked = 0;
  bool crosses_flat = false;     // some sample lies past flat: flat_crossing is filled
  FlatCrossing flat_crossing;
  bool stopped_at_flat = false;
  std::string stop_message;      // why far-side samples have no solution (flat crossing or a failed step)
  static constexpr double kForceAgreement = 1e-6;  // relative: the difference quotient's own error
};
// Throws InputError("flipped_letters") for an index that is not one of the 4n creases.
SplitFoldCurve split_fold_curve(int n, double b, double theta0, double k_m, double k_v, int samples,
                                const SplitFoldCurveOptions& options = {});

}  // namespace rigidfold::waterbomb
