#pragma once
// Writing a folded state: as a FOLD frame appended to the crease pattern, and as OBJ.
#include <Eigen/Core>
#include <string>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// The pattern (key frame, unchanged) plus one file_frames entry
// {frame_classes: ["foldedForm"], frame_parent: 0, frame_inherit: true,
//  vertices_coords: folded 3D, edges_foldAngle: degrees}. fold_angles in radians.
CreasePattern with_folded_frame(const CreasePattern& pattern, const FoldedGeometry& folded,
                                const Eigen::VectorXd& fold_angles, const std::string& title);

// Wavefront OBJ text of the folded faces (1-based indices, one polygon per face).
std::string folded_obj(const CreasePattern& pattern, const FoldedGeometry& folded);

}  // namespace rigidfold
