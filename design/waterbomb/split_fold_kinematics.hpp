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
// below theta* eq. (3.16) reflects f through 0 and gamma_v turns non-physical.
// split_fold_range locates both limits; split_fold_angles refuses theta outside them.
#include "design/waterbomb/waterbomb_kinematics.hpp"

namespace rigidfold::waterbomb {

// Inputs: n >= 3, b in (0, pi/n) (radians), theta in (0, pi) (radians).
// Throws InputError naming "n", "b" or "theta".
FoldPair split_fold_angles_printed(int n, double b, double theta);

// Contact limits of the split-fold model (radians):
//   theta_min = theta*: the argument of eq. (3.16) reaches 1 (f = 0, non-adjacent facets
//     touch), found as its maximum on (0, pi/2) by golden section (error ~1e-8 rad: the
//     argument is 1 - O((theta - theta*)^2) there), returned 1e-7 rad above it so that the
//     forms give the physical branch there (the printed gamma_v jumps below theta*);
//   theta_max: the mirror contact on the far side, where gamma_v = -gamma_m(theta*) (the path
//     is symmetric about gamma_v = -gamma_m), by bisection; gamma_v rises monotonically
//     from flat there.
// Where the printed forms break down before a contact (b large against alpha: an acos
// argument leaves [-1, 1], or eq. (3.21)'s atan jumps and gamma_v turns back), found by
// walking from flat on a 4096-point grid (gamma_m must fall below flat, gamma_v rise above)
// and bisecting to 1e-12 rad, the range ends there instead and *_is_contact is false.
struct SplitFoldRange {
  double theta_min = 0.0;
  double theta_max = 0.0;
  bool lower_is_contact = true;  // theta_min is theta* (f = 0)
  bool upper_is_contact = true;  // theta_max is the mirror contact
};
SplitFoldRange split_fold_range(int n, double b);

// The printed forms, refusing theta outside split_fold_range (InputError "theta", with the
// range in degrees).
FoldPair split_fold_angles(int n, double b, double theta);

}  // namespace rigidfold::waterbomb
