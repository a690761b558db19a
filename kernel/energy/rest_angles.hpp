#pragma once
// Rest fold angles of the crease springs (crease_energy.hpp), from a folded FOLD frame.
// (Rest angles given directly are just a per-edge vector: make_crease_springs checks them.)
#include <Eigen/Core>

#include <string>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// The rest state stored as a frame of `pattern`'s FOLD file (pattern.extra["file_frames"]),
// e.g. one written by with_folded_frame (kernel/geometry/folded_output.hpp).
// Inputs: frame = index into file_frames, or -1 for the first frame whose frame_classes
//   contains "foldedForm".
// Output: one rest angle per edge (radians, FOLD sign), taken from the frame's
//   edges_foldAngle (degrees) when it has one, otherwise measured from its vertices_coords
//   (3D, same vertex and edge numbering as the key frame; reference_fold_angles). Edges
//   that are not hinges get 0.
// Throws InputError naming the place ("file_frames", "file_frames[i].edges_foldAngle[e]",
//   ".vertices_coords[v]") for a missing frame, a wrong count or a non-finite or
//   out-of-range value.
Eigen::VectorXd rest_angles_from_frame(const CreasePattern& pattern, int frame = -1);

// A rest state read from a file (the CLI's --rest): a ".json" of fold angles as for
// `rigidfold fold --angles` (kernel/geometry/fold_angles_input.hpp), or a ".fold" of the same
// pattern (same vertex and edge counts and edges_vertices) whose edges_foldAngle, else whose
// 3D coordinates, give the angles. Output: one angle per edge, radians.
// Throws InputError naming the file and the place (another extension, a different pattern,
// a FOLD with neither fold angles nor 3D coordinates).
Eigen::VectorXd read_rest_state(const std::string& path, const CreasePattern& pattern, const Topology& topology);

}  // namespace rigidfold
