#pragma once
// 3D loop closure of a thick SORCE vertex (verification, seed 002 digest sections 1, 4).
//
// Frame of fold j (digest section 1): z along the fold, outward from the vertex; y the
// facet normal ("up"); x = y cross z, in the plane, into the right sector alpha_j. The 2D
// fold frame of sorce_profile.hpp is its (x, y) plane, and the joint's relative transform
// (the right panel in the left panel's own coordinates) is
//   T_j = Trans(d_j - z_l e_y) Rz(gamma_j) Trans(z_r e_y)
// (a right-hand rotation about the outward fold: gamma > 0 valley). Inside panel alpha_j
// the frame of fold j + 1 is the frame of fold j turned about the normal by alpha_j, Ry(alpha_j).
// The vertex closes when
//   T_1 Ry(alpha_1) T_2 Ry(alpha_2) T_3 Ry(alpha_3) T_4 Ry(alpha_4) = I.
// The rotation part is the kernel's loop (vertex_closure.hpp) with its axes renamed
// (kernel x, y, z = this z, x, y); the offsets cancel between neighbouring folds (a panel's
// z enters one fold as z_r and the next as -z_l, along the normal that Ry keeps), so what the
// check adds is the split offsets' directions (eqs 58, 59).
//
// Closure Jacobian: the spatial twist of each joint per unit of its own angle,
//   xi_j = Ad(P_j) (dT_j/dt T_j^{-1}) / gamma_j',  P_j = prod_{k<j} T_k Ry(alpha_k),
// as (omega, v) columns of a 6x4 matrix. A rolling joint is a 1-DOF joint whose position is
// set by its own angle, so on the folding path the joint rates (gamma_j') lie in its null
// space; nullity 1 on (0, 1) means the thick vertex keeps one degree of freedom.
#include <Eigen/Core>

#include "design/sorce/sorce_vertex.hpp"

namespace rigidfold::sorce {

struct VertexClosure {
  Eigen::Matrix4d product = Eigen::Matrix4d::Identity();
  double error = 0.0;  // max |product - I| entry (rotation unitless, translation in lengths)
  Eigen::Matrix<double, 6, 4> jacobian = Eigen::Matrix<double, 6, 4>::Zero();
  Eigen::Vector4d singular_values = Eigen::Vector4d::Zero();  // descending
  int nullity = 0;              // singular values <= rank_tolerance * the largest
  double rate_residual = 0.0;   // |jacobian * (gamma_1', .., gamma_4')| / |gamma'|
};

// Inputs: the vertex, t in [0, 1], rank_tolerance (relative). Throws InputError("t") where
// some gamma_j'(t) = 0 (no per-angle twist).
VertexClosure vertex_closure(const SorceVertex& vertex, double t, double rank_tolerance = 1e-9);

}  // namespace rigidfold::sorce
