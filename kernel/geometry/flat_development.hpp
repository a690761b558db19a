#pragma once
// flat_development: a crease pattern given by 3D coordinates (a folded form) laid out in the
// plane, the crease pattern it was folded from.
//
// Every face is unfolded along a spanning tree of the face graph to fold angle 0
// (place_faces with all fold angles 0 from the reference fold angles), then the plane of the
// sheet is turned onto z = 0: the first vertex of face 0 at the origin, its first edge along
// +x, and the sheet's faces counter-clockwise seen from +z (the Newell normal of the
// unfolded sheet becomes +z). Lengths are the pattern's; the result's length_exponent is
// the input's, so the file's units are kept. Edges, letters, fold angles, faces and extra
// keys are copied unchanged; coords_2d is set.
//
// A 2D pattern, or a 3D one whose z are all 0, is returned as it is (no rounding added).
//
// Refused (InputError naming `source` and the reason), where no flat crease pattern exists:
//   - a sheet with holes (a tube): its boundary loops cannot all lie flat without a cut;
//   - more than one piece: each piece unfolds in its own plane and no layout relates them;
//   - vertices that are not developable (sector sums != 2 pi): the unfolded faces disagree
//     at the hinges closing the loops by more than kDevelopmentTolerance of the pattern
//     size (the unfolded position would be an arbitrary choice among the faces');
//   - a development that overlaps itself (edges crossing or touching after unfolding).
// kDevelopmentTolerance = 1e-9: coordinates written with 17 digits unfold to within ~1e-15;
// a file rounded to 9 digits or fewer is refused rather than silently moved.
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

inline constexpr double kDevelopmentTolerance = 1e-9;

struct FlatDevelopment {
  CreasePattern pattern;          // z = 0, coords_2d = true
  bool unfolded = false;          // false: the input was already flat
  double relative_mismatch = 0;   // of the unfolding (0 when the input was flat)
};

FlatDevelopment flat_development(const CreasePattern& pattern, const std::string& source);

}  // namespace rigidfold
