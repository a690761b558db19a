#pragma once
// Rest fold angles of the crease springs (crease_energy.hpp), from a folded FOLD frame.
// (Rest angles given directly are just a per-edge vector: make_crease_springs checks them.)
#include <Eigen/Core>

#include "kernel/pattern/crease_pattern.hpp"

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

}  // namespace rigidfold
