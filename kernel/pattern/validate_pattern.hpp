#pragma once
// Structural and geometric validation of a crease pattern, and completion of what a
// FOLD file may omit (faces, assignments).
//
// complete_and_validate: checks indices, duplicate/self/zero-length edges, NaN/inf
// coordinates, face cycles (each side an edge, at least 3 distinct vertices), manifold
// edges (at most 2 faces), consistent face orientation, and for patterns lying in a plane:
// crossing edges, vertices lying on edges, and overlapping faces. Derives faces from the
// planar embedding when none are given, and fills missing assignments (B on the boundary,
// U inside). First normalises the coordinates by a power of two when the pattern is very
// large or very small (length_scale.hpp), so a pattern of side 1e-300 or 1e300 gets the
// checks it gets at side 1. Throws InputError("<source>: <json path>", reason) on the first problem.
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

void complete_and_validate(CreasePattern& pattern, const std::string& source);

// Faces of a plane straight-line graph: the bounded cycles of its planar embedding,
// counter-clockwise seen from +z (coordinates taken as x, y). Cycles bounded only by
// B/C edges inside another face's region are holes and are not returned.
// Throws InputError on dangling edges (an edge with the same face on both sides).
std::vector<std::vector<int>> derive_planar_faces(const CreasePattern& pattern, const std::string& source);

}  // namespace rigidfold
