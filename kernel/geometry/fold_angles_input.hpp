#pragma once
// Per-edge fold angles given by the user as JSON (rigidfold fold --angles, rigidfold energy
// --rest): {"<edge index>": degrees, ...} or an array with one entry (a number or null) per
// edge. Edges not given keep the pattern's edges_foldAngle (0 where it has none).
// Checked: each value a finite number of degrees in [-180, 180]; an edge that is no hinge
// between two faces, or is assigned F or J, cannot take a non-zero angle.
// Output radians (FOLD sign: valley > 0). Throws InputError naming the file and the key or
// array index.
#include <Eigen/Core>
#include <string>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

Eigen::VectorXd read_fold_angles_json(const std::string& path, const CreasePattern& pattern, const Topology& topology);

}  // namespace rigidfold
