#pragma once
// Split-fold waterbomb base (SFWB, seed 004 ch. 3.2.2 / 3.4.1): every fold of the n-degree
// waterbomb split into two half-folds with a split-fold facet of sector b between them, 4n
// creases in the counter-clockwise order [half-V | b | half-V | alpha | half-M | b | half-M |
// alpha] x n, alpha = pi/n - b (eq. 3.13). Symmetric motion: every half-mountain at gamma_m,
// every half-valley at gamma_v (FOLD sign). theta: angle between the centreline of a valley
// split-fold facet and the symmetry axis (as waterbomb_kinematics.hpp).
//
// Eqs (3.13)-(3.30) as printed. Validity (digest section 2.3, not in the seed): the forms hold
// for theta* <= theta <= theta_max only, where non-adjacent facets touch (f = 0 at theta*);
// below theta* eq. (3.16) reflects f through 0 and gamma_v turns non-physical. This function
// refuses theta where the acos/sqrt arguments leave their domain (InputError "theta") but
// does NOT yet locate theta* and theta_max: callers must check contact themselves.
#include "design/waterbomb/waterbomb_kinematics.hpp"

namespace rigidfold::waterbomb {

// Inputs: n >= 3, b in (0, pi/n) (radians), theta in (0, pi) (radians).
// Throws InputError naming "n", "b" or "theta".
FoldPair split_fold_angles_printed(int n, double b, double theta);

}  // namespace rigidfold::waterbomb
