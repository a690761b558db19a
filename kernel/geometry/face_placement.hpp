#pragma once
// Folded geometry from fold angles: every face is placed by a rigid motion found along a
// spanning tree of the face graph (faces joined across hinges). Across a tree edge e the
// child face turns about e by (rho_e - rho_ref_e) relative to its parent, with the FOLD
// sign (valley > 0 lifts the face on the left of v0 -> v1 toward its normal side).
// Hinges not in the tree are where the closure error shows: the two faces disagree there.
//
// Inputs:  pattern and topology; fold angles, one per edge (radians; non-hinge entries
//          ignored); reference fold angles of the pattern's own coordinates
//          (reference_fold_angles; zero for a flat sheet).
// Outputs: one rigid motion per face; folded vertex positions; the closure mismatch.
//          Lengths in the pattern's units. The root face of each component stays fixed.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct FoldedGeometry {
  std::vector<Eigen::Isometry3d> face_motions;  // reference -> folded, per face
  std::vector<Eigen::Vector3d> vertices;        // folded positions (from the first face placed that holds the vertex)
  // Closure mismatch: over non-tree hinges, the largest distance between where the two
  // faces put the vertices of the child face (length units; NaN if a fold angle is NaN); and
  // its hinge (-1 if none).
  double max_mismatch = 0.0;
  int worst_edge = -1;
  int non_tree_hinges = 0;
  double pattern_size = 1.0;  // diagonal of the reference bounding box
  double relative_mismatch() const { return max_mismatch / pattern_size; }
};

// Rigid motion turning the face on side `side` of edge e (0: left of v0 -> v1) by `angle`
// (radians) about the crease line, with the FOLD sign: valley > 0 lifts the left face.
Eigen::Isometry3d hinge_motion(const CreasePattern& pattern, int edge, int side, double angle);

// with_vertices = false leaves `vertices` empty (for callers that only need the motions and
// the mismatch, such as a certificate check).
FoldedGeometry place_faces(const CreasePattern& pattern, const Topology& topology, const Eigen::VectorXd& fold_angles,
                           const Eigen::VectorXd& reference_angles, bool with_vertices = true);

}  // namespace rigidfold
