#pragma once
// How much closure gap the rounding of a file's coordinates can cause at a folded state
// (no "not foldable" may rest on a residual the input's precision explains).
//
// The file's sectors alpha_i differ from the true pattern's by d_i, |d_i| <= delta_i (the
// sector bounds of rounding_witness.hpp, from coordinate_precision), and a flat pattern's
// sectors sum to 360 deg both as read and as meant, so sum d_i = 0. At a state rho where the
// true pattern closes, the file's vertex residual r = log(prod_i Rx(rho_i) Rz(alpha_i)) is, to
// first order, J_alpha d with columns Jl^-1(r) Q_i e_z (Q_i e_z: the i-th crease's normal
// axis after the folds before it). Since sum d_i = 0 the constant e_z can be taken out:
//     |r_v| <= |Jl^-1(r)| sum_i delta_i |Q_i e_z - e_z| + (sum_i delta_i)^2,
// the last term a generous allowance for the second order (delta ~ 1e-6: 1e-12 or less).
// A residual within this bound at every vertex can be the rounding alone; one beyond it
// at some vertex is not explained by it (at this state).
//
// Units: radians.
#include <Eigen/Core>
#include <vector>

#include "kernel/pattern/coordinate_precision.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// Per interior vertex (Topology::interior_vertices order), per sector of its fan: the bound
// delta_i on the sector's error caused by the rounding of the coordinates (radians).
std::vector<std::vector<double>> sector_rounding_bounds(const CreasePattern& pattern, const Topology& topology,
                                                        const CoordinatePrecision& precision);

struct RoundingResidualCheck {
  bool explained = true;       // every vertex's residual within its bound
  double worst_ratio = 0.0;    // max over vertices of |r_v| / bound_v
  int worst_vertex = -1;       // pattern vertex of worst_ratio
};

// Inputs: the pattern, its topology, per-edge fold angles rho (radians) of a state;
// stated_tolerance: the user's bound on each coordinate (input_precision; nullopt: the digits,
// or for an SVG the box of the points drawn for each vertex, vertex_boxes.hpp).
RoundingResidualCheck rounding_explains_residual(const CreasePattern& pattern, const Topology& topology,
                                                 const Eigen::VectorXd& rho,
                                                 std::optional<double> stated_tolerance = std::nullopt);

}  // namespace rigidfold
