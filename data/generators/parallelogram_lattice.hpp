#pragma once
// A planar quad mesh whose panels are parallelograms: node (i, j) sits at
//     origin + u[0] + ... + u[i-1] + v[0] + ... + v[j-1],
// so every "i-edge" (i, j) -> (i+1, j) equals u[i] and every "j-edge" (i, j) -> (i, j+1)
// equals v[j]. Panel (i, j) has corners (i, j), (i+1, j), (i+1, j+1), (i, j+1).
//
// The Miura-ori (u constant, v zig-zagging) and the double-corrugated pattern of seed 003
// §3.2 (u and v both zig-zagging) are such meshes.
//
// Inputs:  u (ni vectors), v (nj vectors), lengths in any unit; every panel must be
//          counter-clockwise (cross(u[i], v[j]) > 0), which is checked.
// Output:  ParallelogramLattice with the crease pattern (vertices z = 0, edges, faces CCW,
//          assignments B on the outer boundary and U inside, no fold angles) and the index
//          maps below. The pattern is not validated here (the generators do that last).
#include <Eigen/Core>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::generators {

struct ParallelogramLattice {
  CreasePattern pattern;
  int ni = 0, nj = 0;  // panels along i and along j

  // Vertex of node (i, j), 0 <= i <= ni, 0 <= j <= nj.
  int node(int i, int j) const { return j * (ni + 1) + i; }
  // Edge node(i, j) -> node(i+1, j), 0 <= i < ni, 0 <= j <= nj.
  int i_edge(int i, int j) const { return j * ni + i; }
  // Edge node(i, j) -> node(i, j+1), 0 <= i <= ni, 0 <= j < nj.
  int j_edge(int i, int j) const { return ni * (nj + 1) + j * (ni + 1) + i; }
  bool interior_node(int i, int j) const { return i > 0 && i < ni && j > 0 && j < nj; }
};

ParallelogramLattice parallelogram_lattice(const std::vector<Eigen::Vector2d>& u, const std::vector<Eigen::Vector2d>& v,
                                           const Eigen::Vector2d& origin = Eigen::Vector2d::Zero());

// Unit vector at angle theta (radians) from +x, counter-clockwise.
Eigen::Vector2d unit_vector(double theta);

}  // namespace rigidfold::generators
