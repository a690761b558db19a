#pragma once
// SORCE panels for viewing: the panels' poses P_f(t) (sorce_pattern.hpp) as a multi-frame
// FOLD and as a pose table.
//
// FOLD: the panels' mid-planes as an "exploded" pattern - every face with its own copies of
// its corners (a panel offset along its normal no longer shares its corners with its
// neighbours) and one edge per face side, carrying the original edge's letter - as the key
// frame (flat, t = 0), then one file_frames entry per pose time (frame_classes foldedForm,
// vertices_coords = P_f(t) applied to the face's corners, edges_foldAngle = the crease's fold
// angle at t in degrees, "rigidfold:sorce_t": t). Coordinates in the file's length units.
// Pose table (CSV): one row per (t, face): t, face, the rotation's 9 entries row by row, the
// translation's 3 (file units), 17 significant digits.
//
// Units: poses in the pattern's internal units (as PatternSorce gives them); fold angles
// radians in, degrees in the FOLD.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::sorce {

struct PoseFrames {
  std::vector<double> times;                           // t of each frame
  std::vector<std::vector<Eigen::Isometry3d>> poses;   // poses[i][f]
  std::vector<Eigen::VectorXd> fold_angles;            // per frame, per edge of the pattern (radians)
};

// The exploded pattern with one frame per time. Throws InputError("poses") when the sizes
// disagree with the pattern (faces, edges) or each other.
CreasePattern exploded_frames(const CreasePattern& pattern, const PoseFrames& frames);

std::string pose_table_csv(const CreasePattern& pattern, const PoseFrames& frames);

}  // namespace rigidfold::sorce
