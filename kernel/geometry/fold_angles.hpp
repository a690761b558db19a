#pragma once
// Fold angles of a crease pattern's reference geometry, and the fold-angle vector used by
// the kinematics (one entry per edge, radians, FOLD sign: valley > 0, mountain < 0).
#include <Eigen/Core>
#include <string>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// Fold angle of every hinge edge in the reference coordinates, measured from the face
// normals: the rotation about the edge (v0 -> v1) taking the right face's normal to the
// left face's. 0 for a flat sheet. Where the faces lie flat on each other (|rho| = pi) the
// geometry cannot tell valley from mountain: the file's edges_foldAngle decides, else the
// assignment (V: +pi, M: -pi). Non-hinge edges get 0.
Eigen::VectorXd reference_fold_angles(const CreasePattern& pattern, const Topology& topology);

// One fold angle per edge (radians) from optional angles, missing entries taken as 0.
Eigen::VectorXd fold_angle_vector(const std::vector<std::optional<double>>& angles);

// The file's edges_foldAngle (radians) with null/missing entries taken as 0.
Eigen::VectorXd stored_fold_angles(const CreasePattern& pattern);

}  // namespace rigidfold
