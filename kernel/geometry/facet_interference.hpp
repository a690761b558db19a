#pragma once
// Global facet interference of a folded state: pairs of faces that pass through each other
// (docs/DESIGN.md, "Foldability verdict": local = a fold passing +-pi, global = faces
// intersecting; a BVH over the faces).
//
// Broad phase: FCL's dynamic AABB tree (Debian libfcl-dev), one object per face.
// Narrow phase (here, strict on purpose): two faces interfere when an edge of a triangle of
// one PIERCES the interior of a triangle of the other: its endpoints lie strictly on both
// sides of the triangle's plane (beyond tolerance) and the crossing point is strictly inside
// the triangle (every barycentric coordinate > tolerance). Consequences, chosen so that
// contact is not interference:
//   - faces meeting along a shared crease or at a shared vertex do not count;
//   - coplanar contact does not count (the layers of a flat-folded state touch, zero
//     thickness);
//   - any proper crossing of two non-coplanar faces counts (the intersection segment of two
//     triangles always ends on an edge of one of them).
// Two faces sharing a crease meet only on it whatever the fold angle, so a fold passing +-pi
// is invisible here: that is the LOCAL check (a fold angle beyond +-pi), done by the callers.
// Faces are triangulated as fans from their first vertex: exact for convex faces (all
// generated and bundled patterns); a non-convex face may be over-reported.
//
// Inputs: the pattern (faces, vertices_coords as the reference), folded vertex positions
//   (one per vertex; FoldedGeometry::vertices), tolerance relative to the folded bounding-
//   box diagonal. Output: interfering face pairs (a < b), sorted, and the number of face
//   pairs the broad phase passed to the narrow phase.
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

struct FacetInterference {
  std::vector<std::pair<int, int>> face_pairs;  // interfering faces, a < b, sorted
  long long candidate_pairs = 0;                // AABB-overlapping pairs tested exactly
};

FacetInterference find_facet_interference(const CreasePattern& pattern, const std::vector<Eigen::Vector3d>& positions,
                                          double relative_tolerance = 1e-9);

}  // namespace rigidfold
