#pragma once
// The connected pieces of a sheet (faces joined across creases, topology.hpp) as patterns of
// their own, with the index each vertex, edge and face had in the whole. The pieces move
// independently of each other (no loop-closure constraint spans two of them), so a sheet of
// several pieces is checked piece by piece (check_foldability).
//
// Inputs: a valid pattern and its topology. A vertex where pieces touch (several fans) is
// copied into each of them; an edge belongs to the piece of its faces; a vertex or edge with no
// face (not produced by complete_and_validate) is left out.
// Outputs: one PatternComponent per Topology::components entry, in that order; each pattern
// keeps the whole's length_exponent, coords_2d and faces_derived, not its extra keys.
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct PatternComponent {
  CreasePattern pattern;
  std::vector<int> vertex_of, edge_of, face_of;  // index in the whole of each local index
};

std::vector<PatternComponent> split_components(const CreasePattern& pattern, const Topology& topology);

}  // namespace rigidfold
