#pragma once
// One revolute joint and the link after it, in Denavit-Hartenberg form (seed 003 eq. 1-2):
//
//     T_i(theta_i) = Rz(theta_i) * Tz(offset_i) * Tx(length_i) * Rx(twist_i)
//
// Frame i has its z axis on joint axis i. T_i maps frame i+1 coordinates into frame i:
// turn by the joint angle theta_i about z_i, slide by the offset d_i (seed: R_i) along z_i,
// walk the common normal of length a_{i(i+1)} along the new x axis, then twist by
// alpha_{i(i+1)} about it, which puts z on joint axis i+1.
//
// A spherical linkage (a zero-thickness vertex) has every length and offset 0; T_i is then
// Rz(theta_i) Rx(alpha_i), the seed's form of the kernel's vertex loop (see
// kernel/vertex/spherical_4r.hpp for the x/z swap that relates the two).
//
// Units: angles in radians, length and offset in pattern units.
#include <Eigen/Geometry>

namespace rigidfold {

struct DhLink {
  double length = 0.0;  // a_{i(i+1)}: common-normal length from axis i to axis i+1 (pattern units)
  double offset = 0.0;  // d_i (seed R_i): slide along axis i between the two common normals (pattern units)
  double twist = 0.0;   // alpha_{i(i+1)}: angle from axis i to axis i+1 about the common normal (radians)
};

// The rigid motion T_i(theta) above. Input: joint angle theta (radians), the link.
Eigen::Isometry3d dh_transform(double joint_angle, const DhLink& link);

}  // namespace rigidfold
