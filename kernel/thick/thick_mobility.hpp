#pragma once
// Where thickness breaks motion: a thick pattern with hinges on panel
// faces (hinge_heights.hpp) checked like any other, with the vertices that lock named.
//
// At a closed state x of the thick sheet's ClosureSystem (one SE(3) loop per thick vertex):
//   - pattern DOF = n - rank J(x) (jacobian_rank, its stated tolerance). At a regular point
//     DOF 0 is a proof that the pattern is rigid there: the closure map is injective to first
//     order, so x is an isolated solution. (Unlike the zero-thickness flat state, the flat
//     state of a thick pattern is often regular: the smallest kept singular value is
//     reported so the gap can be judged.)
//   - per vertex, the DOF of its loop alone: 6 rows, the columns of its creases. A vertex
//     whose loop alone has DOF 0 is locked by itself (a generic spatial 4R/5R/6R loop): the
//     whole pattern cannot move its creases;
//   - per vertex, the largest residual of its loop over given zero-thickness states: the
//     vertices whose thick loop does not follow the zero-thickness motion. A vertex can be
//     mobile alone and still off the motion (the seed's mu = 1/2 waterbomb); the pattern
//     then loses mobility where such vertices share creases.
//
// Units: fold angles in radians (FOLD sign, from the flat state, one per flat-pattern
// edge); residuals as ClosureSystem's hole rows (radians, and lengths over the sheet's length scale).
#include <Eigen/Core>
#include <vector>

#include "kernel/solve/rank.hpp"
#include "kernel/thick/hinge_heights.hpp"

namespace rigidfold {

struct ThickVertexMobility {
  int vertex = -1;            // flat-pattern vertex
  int hole = -1;              // its loop in ClosureSystem (find_hole_loops order)
  int creases = 0;            // free creases of its loop
  int dof_alone = 0;          // creases - rank of its 6 rows (same tolerance as the pattern's)
  double off_motion = 0.0;    // largest |residual| of its rows over the zero-thickness states (0 if none given)
};

struct ThickMobilityReport {
  int dof = 0;                            // of the whole pattern at the state
  RankResult rank;                        // the pattern's rank result (singular values, cut)
  double state_residual = 0.0;            // ||r||_inf at the state
  std::vector<ThickVertexMobility> vertices;
  std::vector<int> locked_vertices;       // vertices whose loop alone has DOF 0
  std::vector<int> off_motion_vertices;   // vertices with off_motion > closure_tolerance
};

// Inputs: the sheet; a closed state (fold angles from flat, per flat edge; e.g. all 0 for the
// flat state); zero-thickness states to compare with (may be empty); closure_tolerance for the
// state and the off-motion test; rank options.
// Throws std::invalid_argument if the state does not close within closure_tolerance.
ThickMobilityReport thick_mobility(const ThickHeightSheet& sheet, const Eigen::VectorXd& state,
                                   const std::vector<Eigen::VectorXd>& zero_thickness_states,
                                   double closure_tolerance = 1e-10, const RankOptions& rank_options = {});

}  // namespace rigidfold
