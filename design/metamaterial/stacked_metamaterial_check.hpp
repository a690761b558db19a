#pragma once
// Stacked metamaterials 1-4 of seed 003 §3.2.3 (Figs 3-10 ... 3-12) as geometry, checked
// against the element closed forms (3-24, 3-25, 3-27) and the Poisson's ratios (3-28).
//
// The layer sheets are data/generators/stacked_metamaterial.hpp's (reconstruction: see there).
// The layer and its reverse-M-V twin are traced SEPARATELY by the kernel's general solver
// (continue_one_dof: pseudo-arclength continuation + Newton on the loop closure, no closed
// form) from the analytic motion's state at 0.1 deg of fold, projected (trace_motion's own
// start lands on another branch of these sheets), landing on equal steps of the seed's A2B2
// crease (phi_edge) up to `to_deg`. At every traced state:
//   - closure residual of both layers (<= kStackResidual);
//   - the stack: layer 0 is the traced layer; layer k + 1 is the other layer, placed by the
//     proper rigid motion (Umeyama, no scaling) that best maps its bonding vertices onto layer
//     k's (top-level nodes between layers 0-1, 2-3, ...; level-0 nodes between 1-2, 3-4, ...);
//     the bond gap is the largest distance between paired bonding vertices (<= kStackBond),
//     and every placed layer must lie on its side of the bond (no vertex more than kStackBond
//     below the bonding plane);
//   - W, L, H of the stack measured from the placed vertices: W = |node(ni, 0) - node(0, 0)|,
//     L = |node(0, nj) - node(0, 0)| of layer 0, H = height range of all layers along the
//     normal of W x L; the layer's W, L, H and their derivatives along the traced tangent (the
//     null vector of the closure Jacobian, faces' velocities from folded_velocity), the
//     Poisson's ratios nu_in = -(dL/L)/(dW/W), nu_out = -(dH/H)/(dW/W) by implicit
//     differentiation;
//   - closed forms: phi = pi - |rho| of phi_edge; metamaterials 1-3: (cells_W W_e, cells_L L_e,
//     layers H_e) of corrugated_element(e, phi); metamaterial 4: element 3 at theta = pi - |rho|
//     of theta_edge (corrugated_element3_at_theta). Differences: dimensions absolute (units of
//     l), ratios relative to max(1, |closed|); each must be <= kStackTolerance.
//   - metamaterial 4 only: the relation between phi and theta. RECONSTRUCTION FINDING: the
//     printed (3-26) tan(theta/2) = k tan(phi/2), k = cos((beta+alpha)/2)/cos((beta-alpha)/2),
//     does not hold on this sheet for any crease taken as A2B2; its inverse
//     tan(phi/2) = |k| tan(theta/2) holds with A2B2 the j-crease of the peak column (and with
//     theta, (3-27) holds). Both differences are reported; the inverse's must be <= tolerance.
// The height maximum: where the traced layer's dH/ds changes sign between two steps, the
// closed form's maximum (dH/dphi = 0, or dH/dtheta = 0 for 4) is located inside that bracket
// (TOMS 748); phi_II is its phi (for 4 through the inverse relation); the stack's maximum
// height is layers x H_e there.
// Every failed check throws NoAnswerError naming the worst value (nothing is returned that
// failed).
//
// Inputs:  generator parameters (metamaterial 1..4, alpha, beta radians, l > 0); options.
// Outputs: StackedMetamaterialCheck (angles radians, lengths in the unit of l).
// Throws InputError with place "metamaterial", "alpha", "beta", "l" (the generator's),
// "layers", "steps" or "to_deg"; NoAnswerError when a trace or a check fails.
#include <vector>

#include "data/generators/stacked_metamaterial.hpp"

namespace rigidfold::metamaterial {

inline constexpr double kStackTolerance = 1e-9;   // traced vs closed form
inline constexpr double kStackResidual = 1e-12;   // closure residual (rad)
inline constexpr double kStackBond = 1e-10;       // bonding vertices' distance (units of l)

struct StackedMetamaterialOptions {
  // 2..16: each layer is placed on the previous one, so a placement's rotation error grows
  // with the stack (64 layers at 400 steps to 170 deg: 2.7e-9 on H).
  int layers = 4;
  int steps = 24;        // 8..200 traced steps
  double to_deg = 170;   // final |fold| of the driving crease A2B2, degrees in (10, 175)
};

struct StackedMetamaterialState {
  double phi = 0, theta = 0;               // radians (theta: metamaterial 4, else = phi)
  double W = 0, L = 0, H = 0;              // stack, measured
  double W_closed = 0, L_closed = 0, H_closed = 0;
  double nu_in = 0, nu_out = 0;            // traced
  double nu_in_closed = 0, nu_out_closed = 0;
  double bond_gap = 0;                     // largest over the stack's bonds
};

struct StackedMetamaterialCheck {
  generators::StackedMetamaterialParams params;
  StackedMetamaterialOptions options;
  int creases = 0;                         // interior creases of one layer
  int bonding_vertices = 0;                // per bond
  std::vector<StackedMetamaterialState> states;
  double max_residual = 0;                 // both layers (rad)
  double max_bond_gap = 0;                 // units of l
  double max_dimension_difference = 0;    // W, L, H of the stack (units of l)
  double max_ratio_difference = 0;        // nu_in, nu_out (relative)
  double max_relation_difference = 0;     // metamaterial 4: inverse (3-26), rad; else 0
  double printed_relation_difference = 0; // metamaterial 4: printed (3-26), rad; else 0
  bool has_maximum = false;                // dH changes sign on the traced path
  double phi_II = 0;                       // radians (closed form, in the traced bracket)
  double theta_II = 0;                     // metamaterial 4; else = phi_II
  double height_max = 0;                   // stack, closed form at phi_II
  bool negative_3d_before = true;          // nu_in < 0 and nu_out < 0 at every state with phi < phi_II
  bool in_negative_out_positive_after = true;  // nu_in < 0, nu_out > 0 at every state with phi > phi_II
  double seconds = 0;
};

StackedMetamaterialCheck stacked_metamaterial_check(const generators::StackedMetamaterialParams& params,
                                                    const StackedMetamaterialOptions& options = {});

}  // namespace rigidfold::metamaterial
