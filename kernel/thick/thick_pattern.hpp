#pragma once
// A thick-panel pattern as a set of closed spatial linkages (seed 003 ch. 4): every thick
// vertex is one loop of revolute joints, one joint per crease around it, with the
// Denavit-Hartenberg link that follows each joint (dh_link.hpp). Panel thickness and hinge
// placement are what put lengths and offsets into the links: hinges on the top or bottom
// face of a panel of thickness t sit t apart, and that distance is the link length a
// between two joint axes.
//
// Creases are the unknowns, shared between the loops of the vertices they join. Inside a
// loop the DH joint angle of a joint on crease c is an affine function of the crease's fold
// angle rho_c (kernel convention: radians, > 0 valley, < 0 mountain, 0 flat):
//
//     theta_joint = angle_offset + angle_sign * rho_c
//
// which is how the seed's per-joint maps (4-8), (4-27), (4-49), (4-59) enter (they write
// theta = offset +- dihedral, and the dihedral is pi - |rho|).
//
// Loop closure: prod_i T_i(theta_i) = I (seed eq. 1-1), joints in loop order.
#include <string>
#include <vector>

#include "kernel/thick/dh_link.hpp"

namespace rigidfold {

struct ThickJoint {
  int crease = -1;            // index of the crease (0 .. num_creases - 1)
  double angle_sign = 1.0;    // +1 or -1
  double angle_offset = 0.0;  // radians
  DhLink link;                // the link from this joint to the next joint of the loop
};

struct ThickLoop {
  std::string name;                // e.g. "vertex 0 (Bennett)"; used in messages
  std::vector<ThickJoint> joints;  // in loop order; the last link returns to the first joint
};

struct ThickPattern {
  int num_creases = 0;
  std::vector<ThickLoop> loops;
};

// DH joint angle (radians) of a joint for a crease fold angle rho (radians).
inline double joint_angle(const ThickJoint& joint, double rho) {
  return joint.angle_offset + joint.angle_sign * rho;
}

}  // namespace rigidfold
