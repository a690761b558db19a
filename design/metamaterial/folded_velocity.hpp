#pragma once
// Folded vertex positions AND their exact velocities along a direction of fold-angle change:
// forward kinematics of the faces with its first derivative (the kernel's place_faces gives
// positions only; this is the missing derivative, written here rather than in kernel/).
//
// Faces are placed along a breadth-first spanning tree of the face graph (faces joined across
// hinges) from `root_face`, which stays at its reference position. Across a tree hinge e with
// endpoints v0 -> v1, the child face turns relative to its parent by beta_e = rho_e - rho_ref_e
// about the folded crease line, right-handed about v0 -> v1 when the child is the face on the
// LEFT of v0 -> v1 (a valley, rho > 0, lifts the left face toward the normal side, as
// kernel/geometry/face_placement.hpp), and by -beta_e when it is on the right.
// Velocities: a face f moves with the twist (omega_f, v_f), dX/ds = omega_f x X + v_f for a
// point X fixed on f; across hinge e, omega_child = omega_parent + beta_e' d and
// v_child = v_parent + beta_e' (P0 x d), d the folded unit axis, P0 its folded start point,
// beta_e' = +-rho_dot_e. On the closure manifold, with rho_dot a tangent of the path (a null
// vector of the closure Jacobian), the result is the derivative of the folded shape along
// the path, whatever spanning tree is used (up to a rigid motion fixed by the root).
//
// Inputs:  pattern, topology; rho and rho_dot per edge (radians, radians per unit path
//          parameter; non-hinge entries ignored); reference angles (reference_fold_angles,
//          zero for a flat sheet); root face.
// Outputs: per vertex, position (pattern length units) and velocity (length per unit path
//          parameter), from the first face placed that holds the vertex; per face its motion.
// Throws std::invalid_argument for a size mismatch or a root face out of range.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::metamaterial {

struct FoldedVelocity {
  std::vector<Eigen::Vector3d> positions;   // per vertex (NaN if no placed face holds it)
  std::vector<Eigen::Vector3d> velocities;  // per vertex
  std::vector<Eigen::Isometry3d> face_motions;  // reference -> folded
  std::vector<Eigen::Vector3d> face_omega, face_v;  // twist of each face
};

FoldedVelocity folded_velocity(const CreasePattern& pattern, const Topology& topology, const Eigen::VectorXd& rho,
                               const Eigen::VectorXd& rho_dot, const Eigen::VectorXd& reference_angles,
                               int root_face = 0);

}  // namespace rigidfold::metamaterial
