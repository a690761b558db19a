#pragma once
// A thick vertex as a sheet with a hole, so that the zero-thickness core's own machinery
// (ClosureSystem with close_holes, newton_project, jacobian_rank, continue_one_dof, which
// all take a ClosureSystem) runs on it unchanged.
//
// Why this is the same problem: a ClosureSystem closes the loop of faces around a hole with
// M = prod_i exp(Delta_i xi_i) = I in SE(3) (hole_closure.hpp), xi_i the hinge lines of the
// reference geometry and Delta_i the change of fold angle. Placing the panels of a thick
// loop at one closed state theta* of its DH chain (thick_pattern.hpp) gives hinge lines
// whose product of exponentials is exactly the DH product relative to theta*:
//     prod_i T_i(theta*_i + Delta_i) = I   <=>   prod_i exp(Delta_i xi_i) = I.
// Each panel (the link after joint i) becomes one face, a quadrilateral (planar only when
// the two hinge axes meet) with one side on hinge i and one on hinge i+1; outer and inner
// sides are boundary, so the sheet is an annulus: no interior vertex, one hole, 6 rows.
//
// Inputs: a ThickPattern with exactly one loop whose joints are on distinct creases, and
// crease fold angles (radians) at which that loop closes (checked).
// Output: the sheet (pattern + topology, edges 0..n-1 the hinges of joints 0..n-1, then the
// boundary), the ClosureSystem options, and the affine map between the ClosureSystem's
// unknowns (per-edge fold angles) and the thick pattern's crease fold angles:
//     x_edge(crease c) = reference_edge_angle + factor * (rho_c - rho*_c),  factor = +-1.
// Units: radians; lengths in the thick pattern's units.
#include <Eigen/Core>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_pattern.hpp"

namespace rigidfold {

struct ThickSheet {
  CreasePattern pattern;
  Topology topology;
  ClosureOptions options;                 // close_holes = true
  std::vector<int> edge_of_crease;        // hinge edge of each crease
  std::vector<double> factor;             // per crease, +1 or -1
  Eigen::VectorXd reference_edge_angles;  // reference_fold_angles of the sheet (per edge)
  Eigen::VectorXd reference_creases;      // rho* (per crease), the state the sheet was built at

  // Per-edge fold angles (the ClosureSystem's edge vector) <-> crease fold angles.
  Eigen::VectorXd edge_angles_from_creases(const Eigen::VectorXd& crease_angles) const;
  Eigen::VectorXd creases_from_edge_angles(const Eigen::VectorXd& edge_angles) const;
};

// Builds the sheet. closure_tolerance: largest accepted |residual| of the thick loop at
// closed_creases (rows of ThickClosureSystem). Throws std::invalid_argument for a pattern
// with other than one loop, a crease used twice, or a state that does not close.
ThickSheet thick_sheet_from_loop(const ThickPattern& pattern, const Eigen::VectorXd& closed_creases,
                                 double closure_tolerance = 1e-10);

}  // namespace rigidfold
