#pragma once
// Local flat-foldability conditions per interior vertex (Kawasaki and Maekawa).
//
// Only folding creases count: sectors separated by F or J edges (rigid joins, e.g. the
// triangulation edges of Origami Simulator files) are merged first.
//   Kawasaki: the vertex is developable (sectors sum to 2pi) and the alternating sum of its
//             sectors is 0 (even degree).
//   Maekawa:  |#M - #V| = 2; undetermined while any crease is U.
// Angles in radians.
#include <optional>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct VertexFlatFoldability {
  int vertex = -1;
  int degree = 0;               // folding creases (M, V, U) around the vertex
  double sector_sum = 0;        // radians
  double developability_defect = 0;  // sector_sum - 2pi
  std::optional<double> kawasaki_residual;  // alternating sum (radians); none for odd degree
  bool kawasaki = false;        // developable and alternating sum 0 (within tolerance)
  int mountains = 0, valleys = 0, unassigned = 0;
  std::optional<bool> maekawa;  // none when some crease is U
};

// One entry per interior vertex, in vertex order. tolerance: radians.
std::vector<VertexFlatFoldability> flat_foldability(const CreasePattern& pattern, const Topology& topology,
                                                    double tolerance = 1e-9);

}  // namespace rigidfold
