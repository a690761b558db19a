#pragma once
// Forward kinematics of a Miura string in closed form (string_vertex.hpp per vertex).
//
// Driven crease and transmission (mode Transmitted, the rigid motion of the connected
// strip; one degree of freedom): the actuated crease is the lead-in spinal crease s_0 =
// crease c of vertex 0, folded to rho = 2 theta_0. Spinal crease s_{i+1} is crease a of
// vertex i and crease c of vertex i+1, so its fold angle is shared: rho_a(i) = 2 theta_{i+1}.
// For a Miura vertex theta_out = -theta exactly, hence theta_i = (-1)^i theta_0: the
// one actuation is transmitted with alternating sign and equal magnitude.
//
// Mode Independent: theta_i given per vertex (the kinematic model of the string papers,
// each vertex set on its own). Only theta_{i+1} = -theta_i is a rigid motion of the one
// connected sheet; otherwise the shared spinal creases disagree by
// shared_crease_mismatch (radians; the folded FOLD frame then takes each spinal crease's
// angle from its downstream vertex, and face placement shows the gap). Such a string must
// be built from separate one-vertex modules.
//
// World frame: by default the pattern's own (face 0, the top lead-in face, fixed as in
// place_faces): S at the origin, frame C_0 = Rx(-theta_0) so that the top lead-in face
// stays in the xy-plane. A StringPose puts the spine anywhere (design targets).
#include <Eigen/Core>
#include <vector>

#include "design/strings/miura_string.hpp"
#include "design/strings/string_vertex.hpp"
#include "kernel/geometry/face_placement.hpp"

namespace rigidfold::design {

enum class ThetaMode { Transmitted, Independent };

// Start of the spine in world coordinates: point S and the frame C_0 of crease s_0
// (columns x, y, z: x along the spine, see string_vertex.hpp).
struct StringPose {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
};

// The pose in which the pattern's face 0 stays where build_string_pattern put it.
StringPose pattern_pose(double theta0);

struct StringState {
  ThetaMode mode = ThetaMode::Transmitted;
  std::vector<double> theta;                   // per vertex (radians)
  std::vector<StringVertexState> vertices;     // closed form per vertex
  std::vector<Eigen::Matrix3d> frames;         // N + 1: frame of spinal crease s_k in world
  std::vector<Eigen::Vector3d> spine;          // N + 2 points: S, V_0..V_{N-1}, E (world)
  Eigen::VectorXd edge_fold_angles;            // per edge of build_string_pattern (radians; boundary 0)
  double shared_crease_mismatch = 0;           // max over s_1..s_{N-1} of |rho_a(i-1) - rho_c(i)| (radians)
  double min_theta_margin = 0;                 // min over vertices of theta_limit - |theta| (radians)
  int limiting_vertex = -1;                    // where that minimum is reached
};

// Transmitted mode: theta0 drives crease s_0 (radians, |theta0| < every vertex's limit).
// Throws std::invalid_argument for an invalid string or |theta_i| >= theta_limit_i.
StringState string_forward(const MiuraString& s, double theta0, const StringPose& pose);
StringState string_forward(const MiuraString& s, double theta0);  // pattern_pose(theta0)

// Independent mode: one theta per vertex (radians).
StringState string_forward_independent(const MiuraString& s, const std::vector<double>& theta, const StringPose& pose);
StringState string_forward_independent(const MiuraString& s, const std::vector<double>& theta);

// Folded geometry of the pattern (build_string_pattern(s, state.edge_fold_angles)) by the
// kernel's face placement with the closed-form fold angles.
FoldedGeometry fold_string_pattern(const CreasePattern& pattern, const StringState& state);

}  // namespace rigidfold::design
