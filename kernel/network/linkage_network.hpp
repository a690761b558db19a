#pragma once
// A network of spherical linkages given by their twists (seed 003 ch. 2), not by coordinates.
//
// Each linkage is one closed spherical nR loop (n >= 3) with joints 0..n-1 in loop order and
// twists alpha_0..alpha_{n-1}, alpha_i the link between joint i and joint i+1 (the seed's
// alpha_{(i+1)(i+2)}). It closes when
//     Rx(t_0) Rz(alpha_0) Rx(t_1) Rz(alpha_1) ... Rx(t_{n-1}) Rz(alpha_{n-1}) = I,
// the kernel's vertex loop (kernel/vertex/vertex_closure.hpp), t_i the joint angle (radians).
// This is the same solution set as the seed's DH loop prod Rz(theta_i) Rx(alpha_{i(i+1)}) = I
// with t_i = theta_i (spherical_4r.hpp explains the half-turn that swaps x and z), so the
// seed's twists and joint angles are used as printed. Twists may be any real (pi - alpha,
// -alpha, -pi + alpha, sums != 2 pi): a non-developable "vertex" is legal.
//
// Joints are the network's unknowns q_j (radians). A linkage's joint i refers to one network
// joint with a sign and an offset: t_i = sign * q_j + offset. Two linkages that name the same
// network joint share that revolute axis (the seed's coaxial joints, e.g. (2-23)
// theta_2^a = theta_2^b); sign -1 expresses the seed's (2-15) theta_2^a = -theta_2^b.
// Origami reading (docs/DESIGN.md): the seed's theta is mountain-positive, so the fold angle of
// the crease of joint j is rho = -q_j (both loops are invariant under t -> -t).
#include <string>
#include <vector>

namespace rigidfold {

struct NetworkJointRef {
  int joint = -1;       // network joint index
  double sign = 1.0;    // +1 or -1
  double offset = 0.0;  // radians
};

struct NetworkLinkage {
  std::string name;
  std::vector<double> twists;            // radians, size n >= 3
  std::vector<NetworkJointRef> joints;   // size n, loop order
};

struct LinkageNetwork {
  std::vector<std::string> joint_names;  // one per network joint
  std::vector<NetworkLinkage> linkages;
  int num_joints() const { return static_cast<int>(joint_names.size()); }
  int num_linkages() const { return static_cast<int>(linkages.size()); }
  // Index of a joint by name, -1 if absent.
  int joint_index(const std::string& name) const;
};

// Checks the invariants above: every linkage has n >= 3 finite twists and n joint refs, each
// ref's joint in range, sign +-1, offset finite, no network joint twice in one linkage; every
// network joint used by some linkage. Throws std::invalid_argument naming the linkage/joint.
void validate_network(const LinkageNetwork& network);

// Joint angles of linkage k at network joints q (size num_joints(), radians).
std::vector<double> linkage_joint_angles(const NetworkLinkage& linkage, const std::vector<double>& q);

}  // namespace rigidfold
