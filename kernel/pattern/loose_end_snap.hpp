#pragma once
// Loose line ends snapped to the vertex they were drawn toward.
//
// A line that stops a little short of (or beside) the point it was meant to reach ends on no
// other line: in the arrangement its end is a vertex of degree 1, and the piece up to the next
// vertex is dangling (it divides no face, so it cannot fold). Origami Simulator merges points
// closer than its vertex tolerance (`vertTol`, 3 user units in js/globals.js) before it splits
// lines, so such a line still meets its vertex there; Origami Simulator's own hypar.svg has one
// (a magenta line ending 2.95 px from the corner it was drawn to).
//
// Rule: a degree-1 vertex v of the arrangement whose dangling piece is longer than `snap`
// (a shorter piece is an overshoot past a line it already met, removed as before) moves to the
// nearest other vertex within `snap`, or else to the nearest point of a line within `snap`
// that does not end at v. A vertex already chosen as a target does not move itself. The
// segment ends drawn at v (within `merge_tolerance` of it) are moved, so the caller rebuilds
// the arrangement from the moved segments.
//
// Inputs: the segments and the arrangement built from them; `snap` and `merge_tolerance` in
//         the segments' length unit (snap <= 0: nothing is snapped).
// Output: the number of ends moved (segments changed in place) and the largest move; when
//         loose ends x (vertices + edges) would exceed `max_pairs`, nothing is moved and
//         `skipped_too_many` says so (the caller warns).
#include <cstdint>
#include <vector>

#include "kernel/pattern/planar_arrangement.hpp"

namespace rigidfold {

struct LooseEndSnap {
  int ends_snapped = 0;       // degree-1 vertices moved
  int onto_lines = 0;         // of which onto a line (not a vertex)
  double max_distance = 0;    // largest move, segment units
  int source_example = -1;    // source index of a segment whose end moved (for messages)
  bool skipped_too_many = false;
};

LooseEndSnap snap_loose_ends(std::vector<LabelledSegment>& segments, const PlanarArrangement& arrangement, double snap,
                             double merge_tolerance, std::int64_t max_pairs);

}  // namespace rigidfold
