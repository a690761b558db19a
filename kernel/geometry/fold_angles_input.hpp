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

// The same from either a JSON file as above or, for a path ending in .fold, a FOLD file of the
// same pattern (the same edges_vertices, edge by edge; e.g. Origami Simulator's export) whose
// edges_foldAngle gives the angles (null: the pattern's own). The same checks per angle.
Eigen::VectorXd read_fold_angles_input(const std::string& path, const CreasePattern& pattern, const Topology& topology);

}  // namespace rigidfold
