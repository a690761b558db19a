#pragma once
// A thick-panel pattern made from a flat crease pattern and the height of every hinge axis:
// the multi-vertex form of the thick models, run through the zero-thickness core's
// ClosureSystem (one SE(3) hole closure per thick vertex).
//
// Geometry at the flat state. Panel p is a slab between z = bottom_p and z = bottom_p +
// thickness_p. The hinge of a crease is a line above the crease line at the height where
// it is placed: on the top face, the bottom face or the mid-plane of a panel
// (hinge_height). Hinge lines of one vertex are horizontal and all pass through the vertical
// line over the vertex, so their common normals are vertical, the DH offsets d (seed R_i) are
// 0 and the link length between hinges i and i+1 is |h_i - h_{i+1}| (the seed's panel
// "thickness" a_{i(i+1)}), the twist their angle seen from above (the sector alpha_i, or
// pi - alpha_i, 2 pi - alpha_i where the common normal turns down). The hinge axes of a
// vertex no longer meet, so the vertex is a spatial linkage, not a spherical one.
//
// The sheet (thick_sheet_from_hinge_heights): every vertex of the flat pattern is cut off
// (truncated) at `truncation` times the length of each of its edges; face f becomes the
// polygon through the cut points, each side lifted to the height of its edge, so the hinge
// edge of crease e is the segment of its hinge line between the two cut points (a non-planar
// polygon wherever two hinges of a face differ in height). A truncated interior vertex leaves
// a hole bounded by its cut edges, and ClosureSystem(close_holes) closes each of them in SE(3):
// no interior vertex remains, only the loops of the thick vertices.
//
// Units: heights and lengths in pattern units; fold angles in radians, FOLD sign, measured
// from the flat state (the sheet's reference_fold_angles are subtracted by ClosureSystem).
#include <Eigen/Core>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

enum class HingePlacement { kTop, kBottom, kMid };

// Height of a hinge placed on a panel whose slab is [bottom, bottom + thickness].
double hinge_height(double panel_bottom, double panel_thickness, HingePlacement placement);

struct ThickHeightSheet {
  CreasePattern pattern;             // 3D; edges 0 .. E-1 are the flat pattern's edges, same order and assignments
  Topology topology;
  ClosureOptions options;            // close_holes = true
  std::vector<int> vertex_of_hole;   // flat-pattern vertex of each ClosureSystem hole loop (find_hole_loops order; -1: a loop round no single vertex)
  std::vector<int> flat_face_of_face;  // flat-pattern face of each sheet face (a face with a boundary side leads)
  Eigen::VectorXd reference_edge_angles;  // reference_fold_angles of the sheet (per sheet edge)
  int num_cut_edges = 0;                  // sheet edges after the flat pattern's (boundary of the truncations)

  // Fold angles from the flat state, one per flat-pattern edge <-> the sheet's edge vector
  // (one per sheet edge, cut edges included) as ClosureSystem sees it: reference angle added.
  Eigen::VectorXd sheet_edge_angles(const Eigen::VectorXd& fold_angles) const;
  Eigen::VectorXd fold_angles(const Eigen::VectorXd& sheet_edge_angles) const;
};

// Inputs: a flat pattern with faces (complete_and_validate'd) and its topology; one height
// per edge (pattern units; only hinges' heights matter, boundary edges may take any value);
// truncation in (0, 0.5).
// Throws std::invalid_argument for a size mismatch, a truncation out of range or a non-finite height.
ThickHeightSheet thick_sheet_from_hinge_heights(const CreasePattern& flat, const Topology& topology,
                                                const std::vector<double>& edge_heights, double truncation = 0.1);

}  // namespace rigidfold
