#pragma once
// Pattern hinge heights from per-vertex height steps (hinge_heights.hpp): each thick vertex
// model asks that, going counter-clockwise round the vertex, the hinge height changes by a
// given signed step across each sector (+-a_i, the DH link lengths; the steps sum to 0).
// The heights of a pattern are these per-vertex profiles shifted so that every crease shared
// by two vertices gets one height: the shifts are fixed along a spanning forest of the vertex
// graph, and every other shared crease is then a check (a cycle of vertices must come back
// to the height it left; the thick analogue of a loop gain of 1).
//
// Units: heights in pattern units.
#include <stdexcept>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// Thrown when two vertices' shifted profiles disagree on a shared crease.
struct HingeHeightConflict : std::invalid_argument {
  HingeHeightConflict(int edge, int vertex_a, int vertex_b, const std::string& message)
      : std::invalid_argument(message), edge(edge), vertex_a(vertex_a), vertex_b(vertex_b) {}
  int edge, vertex_a, vertex_b;
};

// Inputs: a flat pattern and its topology; steps[v] for every interior vertex v (others:
// empty): one signed step per sector of topology.stars[v].fans[0], step i from fan edge i to
// fan edge i+1 (pattern units); tolerance for the checks (pattern units).
// Output: one height per edge (0 for edges at no interior vertex).
// Throws std::invalid_argument naming the vertex when its steps are missing, of the wrong
// count or do not sum to 0 (within tolerance); HingeHeightConflict naming the crease and the
// two vertices when shifted profiles disagree.
std::vector<double> hinge_heights_from_steps(const CreasePattern& flat, const Topology& topology,
                                             const std::vector<std::vector<double>>& steps, double tolerance = 1e-12);

}  // namespace rigidfold
