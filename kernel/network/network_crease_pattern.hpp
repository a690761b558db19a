#pragma once
// An assembly of four spherical 4R linkages (seed 003 §2.3, Fig 2-12) as a flat crease
// pattern: each linkage a degree-4 vertex, each joint shared by two linkages a crease between
// their vertices (the sides of the central panel), the other joints outer creases to the
// sheet's boundary.
//
// Conditions (checked in this order; the first that fails is an InputError naming the place
// "<source>: linkages[k]..." or "<source>: joints" and the reason, nothing is built):
//   - four linkages of four joints; every network joint in one or two linkages; each linkage
//     shares exactly two joints, with two different linkages, and those two joints are
//     neighbours in its loop, so that the shared joints form one cycle A -> ... -> A (the
//     central panel);
//   - (2-33) flat paper: every twist in (0, pi) and the twists of each linkage sum to 2 pi
//     (to 1e-9 rad);
//   - (2-32) flat central panel: the twists between the two shared joints of the four
//     linkages (the panel's interior angles) sum to 2 pi (to 1e-9 rad);
//   - one fold angle per crease: a vertex whose loop runs clockwise around the panel is laid
//     out with its joints reversed, which negates its joint angles (the loop reversed and
//     conjugated by a half-turn about x); a shared joint must then enter both linkages with
//     o_A sign_A = o_B sign_B and o_A offset_A = o_B offset_B (o = +1 as given, -1 reversed):
//     the rotation case (2-23, signs +1, all counter-clockwise) and the two-fold case (2-15,
//     signs -1 between mirrored neighbours) both pass.
// Layout (seen from +z): the central panel is the convex quadrilateral with those interior
// angles whose side lengths maximise the shortest side (largest side 1); each vertex's creases
// follow counter-clockwise with its sectors; outer creases have length 1, shortened to half
// the distance at which they would meet the neighbouring vertex's outer crease across a side;
// the boundary joins the outer creases' ends. complete_and_validate derives the faces and
// checks the sheet (overlaps are an InputError).
// Letters and fold angles: at the closed configuration q (radians, network joints), the
// crease of joint i of linkage k folds by rho = -o_k t_i (linkage_network.hpp: rho = -theta
// for a counter-clockwise vertex); V where rho > 0, M where rho < 0, F where |rho| <= 1e-12.
// The pattern's own vertex loops (ClosureSystem) at those fold angles must close to
// `tolerance`, else NoAnswerError.
//
// Inputs:  network, closed configuration q (size num_joints), source (for messages),
//          tolerance (radians).
// Outputs: the pattern (vertices in the unit of the largest central side; edges_foldAngle
//          set), the closure residual of its vertex loops (radians), and which network joint
//          each crease is.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/network/linkage_network.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

struct NetworkCreasePattern {
  CreasePattern pattern;
  double residual = 0.0;                // max vertex loop residual at the fold angles (radians)
  std::vector<int> edge_joint;          // network joint of each edge (-1 for boundary edges)
  std::vector<std::string> vertex_linkage;  // linkage name of each interior vertex (vertices 0..3)
  std::vector<int> orientation;         // per linkage: +1 laid out as given, -1 reversed
  double central_angle_sum = 0.0;       // (2-32), radians
  // The M/V letter of each crease (edges with a joint), in edge order: "MVVM...".
  std::string crease_letters() const;
  // The creases (edges with a joint).
  int num_creases() const;
};

NetworkCreasePattern network_crease_pattern(const LinkageNetwork& network, const Eigen::VectorXd& q,
                                            const std::string& source, double tolerance = 1e-12);

}  // namespace rigidfold
