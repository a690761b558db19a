#pragma once
// SE(3) loop closure around a hole of a sheet (docs/DESIGN.md, "The kinematic core": one closure of
// 6 equations per hole around a loop of faces).
//
// Vertex closures cover every loop of faces around a vertex. A component with b boundary
// loops (genus 0) has b - 1 further independent loops: one around each hole. For each
// boundary loop of a component except its first one, find_hole_loops walks the faces along
// that boundary (the same walk as build_topology: along a face's sides, crossing hinges
// around the head vertex until the next unjoined side), which gives a closed cycle of faces
// f_0 -> f_1 -> ... -> f_0 joined across hinges, homologous to the boundary loop.
//
// Motion across step i (hinge e_i, into the face on side s_i of e_i, 0 = left of v0 -> v1):
//   T_i = rotation by theta_i about the line through v0 of e_i with unit direction
//         sigma_i d_i (d_i = v1 - v0 normalised, sigma_i = +1 for s_i = 0, -1 for s_i = 1),
//   theta_i = rho_{e_i} - rho_ref_{e_i} (fold angle relative to the reference geometry),
// exactly as kernel/geometry/face_placement.cpp places a child face. The loop closes when
//   M(theta) = T_0 T_1 ... T_{m-1} = I   in SE(3).
// Residual (6 rows): r[0..2] = so3_log(R_M) (radians); r[3..5] = (M c - c) / L, c = centroid
// of f_0 in the reference, L = length scale (dimensionless, so that all rows are comparable).
// Jacobian (exact, product of exponentials): dM/dtheta_i = [xi_i'] M with the spatial twist
// xi_i' = (w_i, a_i x w_i), w_i = R_{P_i} sigma_i d_i, a_i = P_i v0_i, P_i = T_0 ... T_{i-1};
//   d r_rot / d theta_i = Jl^{-1}(r_rot) w_i,  d r_trans / d theta_i = w_i x (M c - a_i) / L.
// Smooth while |r_rot| < pi.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct HoleStep {
  int edge = -1;  // hinge crossed
  int side = 0;   // side of `edge` of the face entered (0: left of v0 -> v1, 1: right)
};

struct HoleLoop {
  int component = -1;
  int boundary_loop = -1;        // index into Topology::boundary_loops of the walk's order (see above)
  int base_face = -1;            // f_0
  std::vector<int> faces;        // f_0, f_1, ..., f_{m-1} (f_i entered by steps[i-1])
  std::vector<HoleStep> steps;   // m steps; the last one re-enters f_0
};

// One loop per hole of every component (components with genus > 0 get only their hole
// loops: handles are not covered). Loops with no hinge crossing are dropped (nothing to close).
std::vector<HoleLoop> find_hole_loops(const CreasePattern& pattern, const Topology& topology);

// Residual and exact 6 x m Jacobian of one loop.
// Inputs: pattern (reference coordinates), the loop, theta (m relative fold angles, radians,
//   one per step, in step order), length_scale L > 0.
// Outputs: residual (6), jacobian (6 x m, resized).
void hole_closure_jacobian(const CreasePattern& pattern, const HoleLoop& loop, std::span<const double> theta,
                           double length_scale, Eigen::Matrix<double, 6, 1>& residual,
                           Eigen::Matrix<double, 6, Eigen::Dynamic>& jacobian);

Eigen::Matrix<double, 6, 1> hole_closure_residual(const CreasePattern& pattern, const HoleLoop& loop,
                                                  std::span<const double> theta, double length_scale);

}  // namespace rigidfold
