#pragma once
// The three basic elements of the double-corrugated metamaterials of seed 003 §3.2.3
// (eqs. 3-24 ... 3-28, Fig. 3-11): width W, length L and height H along the 1-DOF motion, and
// the in-plane and out-of-plane Poisson's ratios. Metamaterial 1 of Fig. 3-10 is built of
// element 1, metamaterial 2 of element 2, metamaterial 3 of elements 1 and 2 (its dimension
// curves are those of element 2), metamaterial 4 of element 3.
//
// Inputs: the sector angles alpha, beta (radians, in (0, pi)) of the elements' vertices, the
// common crease length l (> 0), and the input phi: the DIHEDRAL angle of crease A2B2 (radians;
// pi = flat, decreasing as the element folds; phi = pi - |rho| in the docs/DESIGN.md fold angle rho).
// Outputs: W, L, H in the unit of l; their derivatives d/dphi (exact, forward-mode automatic
// differentiation with ceres::Jet through the same formulas); nu_in = -(dL/L)/(dW/W),
// nu_out = -(dH/H)/(dW/W) (3-28).
//
// Geometry as the formulas read (checked against an independent vector construction in
// tests/metamaterial/corrugated_elements_test.cpp):
//   Element 1 (3-24): vertex A2 with creases A2A1, A2B2, A2A3 of length l; the sector between
//     A2A1 and A2B2 is pi - beta, between A2B2 and A2A3 is alpha, the dihedral at A2B2 is phi.
//     The base plane holds A1, A2, A3. W = |A1A3|; H = height of B2 over the base plane;
//     L = twice the projection of A2B2 onto the bisector of angle A1A2A3.
//     (3-24b) takes angle B2PB2' = pi - D with D the dihedral at A2A1 (spherical cosine rule),
//     so that PB2' = l sin(beta) cos(B2PB2') is B2's offset from line A1A2 on the side away
//     from A3; (3-24c) arctan(PB2'/PA2) is evaluated as atan2 (the same for beta < pi/2, and
//     continuous through beta = pi/2 where PA2 = l cos(beta) = 0), and L is the magnitude of
//     the resulting signed projection (the printed arctan, not atan2, flips its sign for
//     beta > pi/2; either way the dimension is |...|).
//   Element 2 (3-25): element 1 and its mirror image: same W, H and L doubled.
//   Element 3 (3-26, 3-27): vertex B5 with creases B5A5 (sector beta to B5B4), B5C5 (sector
//     alpha to B5B4) and dihedral theta at B4B5, theta from phi by (3-26); L = |A5C5|,
//     H = 2 x the height of B4 over the plane A5B5C5, W = 4 x the projection of B5B4 onto the
//     bisector of angle A5B5C5. Seed error: (3-27c) prints "W = B1B5 = 2 B5B4' = 4 B5B4' cos ...";
//     the middle term is garbled, W = |4 B5B4' cos(B1B5B4')| is used (the chain's signed
//     projection is negative for some alpha, beta; the dimension is its magnitude).
//     With alpha + beta = pi, (3-26) pins theta at 0: element 3 is locked (dimensions 0/0).
#include <vector>

namespace rigidfold::metamaterial {

enum class CorrugatedElement { kElement1 = 1, kElement2 = 2, kElement3 = 3 };

struct CorrugatedElementParams {
  double alpha = 1.0;  // radians, in (0, pi)
  double beta = 1.2;   // radians, in (0, pi)
  double l = 1.0;      // crease length (> 0)
};

struct CorrugatedElementState {
  double phi = 0.0;    // input dihedral of A2B2 (radians)
  double theta = 0.0;  // element 3: dihedral of B4B5 by (3-26); elements 1, 2: equal to phi
  double W = 0.0, L = 0.0, H = 0.0;
  double dW = 0.0, dL = 0.0, dH = 0.0;  // d/dphi
  double nu_in = 0.0, nu_out = 0.0;     // (3-28)
};

// The element at dihedral phi in (0, pi). Throws std::invalid_argument for alpha, beta
// outside (0, pi), l <= 0 or phi outside [0, pi].
CorrugatedElementState corrugated_element(CorrugatedElement element, const CorrugatedElementParams& params,
                                          double phi);

// Element 3 by (3-27) alone, at the dihedral theta of B4B5 (radians, [0, pi]) instead of phi:
// phi is NaN, the derivatives are d/dtheta (the Poisson's ratios do not depend on the
// parameter). For the stacked metamaterial 4 (design/metamaterial/stacked_metamaterial_check.hpp),
// whose reconstruction satisfies (3-27) but relates theta and phi by the inverse of (3-26).
// Throws std::invalid_argument as corrugated_element, or for theta outside [0, pi].
CorrugatedElementState corrugated_element3_at_theta(const CorrugatedElementParams& params, double theta);

// (3-26): theta = 2 arctan(tan(phi/2) cos((beta + alpha)/2) / cos((beta - alpha)/2)).
double element3_theta(const CorrugatedElementParams& params, double phi);

// The height maximum over phi in (lo, hi) (dH/dphi = 0, TOMS 748 on the exact derivative);
// requires lo < hi, dH/dphi > 0 at lo and < 0 at hi. Throws std::invalid_argument if not.
struct CorrugatedHeightMaximum {
  double phi = 0.0;
  double height = 0.0;
};
CorrugatedHeightMaximum corrugated_height_maximum(CorrugatedElement element, const CorrugatedElementParams& params,
                                                  double lo, double hi);

}  // namespace rigidfold::metamaterial
