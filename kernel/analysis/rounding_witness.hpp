#pragma once
// "Foldable within the precision of your file": a pattern given in
// a folded state whose coordinates were rounded does not close exactly, and its flat state
// may not even be a configuration (rounded 3D sectors need not sum to 360 deg). Judged in
// exact arithmetic such a file is rigid; judged against its own precision it may fold.
//
// The witness. Sector angles measured from rounded coordinates are off by at most
//     delta_i = asin(min(1, 2 sqrt(3) u_a / |a|)) + asin(min(1, 2 sqrt(3) u_b / |b|))
// for the sector between edge vectors a and b (each end of an edge moved by at most sqrt(3) u
// by the rounding u of its coordinates, coordinate_precision.hpp; the direction of a vector
// of length L moved by d <= L turns by at most asin(d / L)). The witness keeps the measured
// fold angles of the given state and moves the sectors of each interior vertex, by
// Gauss-Newton with steps of least delta-weighted norm, until the vertex closes (residual
// <= 1e-14 rad). If every sector moved by at most its delta, the witness is a crease pattern
// within the file's precision for which the given state is an exact configuration: the
// file is consistent with it, and the kinematics of the witness (its DOF and motion from
// the given state) is the kinematics "within the input's precision". If some sector had to
// move further, the closure gap is not explained by the rounding (explained = false).
// Only the sectors change: the witness is a Topology (the sectors of its vertex stars),
// coordinates are left as read, so face placement still sees the file's geometry.
// Limit: the witness is the least change vertex by vertex, not the designer's pattern. A
// pattern that folds because of a special structure (a Miura's flat-foldable vertices)
// loses it in the witness, whose motion from the given state can then be a small closed
// loop (a 3 x 3 Miura written with 4 decimals) instead of a fold to the limit: the verdict
// is then "undecided", never a "no". Restoring the structure (projecting the sectors onto
// Kawasaki's condition first) is the next step.
//
// Units: radians; lengths in the pattern's unit.
#include <Eigen/Core>
#include <vector>

#include "kernel/pattern/coordinate_precision.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct RoundingWitness {
  CoordinatePrecision precision;
  double given_residual = 0.0;      // largest vertex closure residual at the given state (radians)
  double max_sector_bound = 0.0;    // largest delta_i (radians)
  double max_sector_change = 0.0;   // largest |witness - measured| sector (radians)
  double max_change_ratio = 0.0;    // largest |change_i| / delta_i (<= 1: explained)
  double witness_residual = 0.0;    // largest vertex closure residual of the witness there
  int worst_vertex = -1;            // vertex of max_change_ratio
  bool explained = false;           // every change within its bound and the witness closes
  Topology witness;                 // the topology with the witness sectors
};

// Inputs: a validated pattern, its topology, and the given state's per-edge fold angles
// (reference_fold_angles, radians); stated_tolerance: the user's bound on each coordinate
// (input_precision; nullopt: read off the digits).
RoundingWitness rounding_witness(const CreasePattern& pattern, const Topology& topology,
                                 const Eigen::VectorXd& given_fold_angles,
                                 std::optional<double> stated_tolerance = std::nullopt);

}  // namespace rigidfold
