#pragma once
// The loop-closure constraint system of a whole crease pattern: unknowns, residual and the
// exact sparse Jacobian (docs/DESIGN.md, "The kinematic core").
//
// Unknowns x: the fold angles (radians, FOLD sign: > 0 valley, < 0 mountain) of the FREE
//   creases, i.e. the hinge edges (two faces, see Topology::edge_is_hinge) assigned M, V or
//   U that are not listed as fixed. Unknown k is edge free_edges()[k], in increasing edge
//   order. Other edges enter the equations as constants:
//     - F and J hinges are held at 0: the two faces form one rigid panel;
//     - fixed (driven) creases take the value given in ClosureOptions::fixed;
//     - B and C edges are not hinges and appear in no equation.
//
// Rows: 3 per interior vertex (Topology::interior_vertices, in that order), rows 3k..3k+2
//   for the k-th one: r_v = log(prod_i Rx(rho_i) Rz(alpha_i)) over the vertex's fan in its
//   counter-clockwise order (vertex_closure_residual), radians. Then one row per equality
//   constraint rho_a - s * rho_b (radians), s = +1 or -1 (symmetry). Then, only with
//   ClosureOptions::close_holes, 6 rows per hole (hole_closure.hpp, find_hole_loops order):
//   the SE(3) closure of a loop of faces around the hole, rotation log (radians) then
//   translation / length scale (the reference bounding-box diagonal; dimensionless). In
//   these rows a crease turns by rho - rho_ref (reference_fold_angles of the pattern's own
//   coordinates, so a 3D reference such as a tube is its own zero); F/J hinges keep their
//   reference angle there.
//
// Limits: handles (genus > 0) are not supported; the constructor throws std::runtime_error
//   for them, and for holes unless close_holes is set.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "kernel/closure/hole_closure.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// rho[edge_a] = sign * rho[edge_b]; sign is +1 or -1. Both edges must be free or fixed
// hinges (a fixed or rigid edge enters the row as a constant).
struct CreaseEquality {
  int edge_a = -1;
  int edge_b = -1;
  double sign = 1.0;
};

struct ClosureOptions {
  // (edge, fold angle in radians): foldable hinge creases held at a given value.
  std::vector<std::pair<int, double>> fixed;
  // Extra rows rho_a - sign * rho_b = 0.
  std::vector<CreaseEquality> equalities;
  // Add the 6 SE(3) rows per hole (otherwise a sheet with holes is rejected).
  bool close_holes = false;
};

class ClosureSystem {
 public:
  // Inputs: pattern and its topology (build_topology(pattern)); options as above.
  // Throws std::invalid_argument for a bad fixed/equality edge (out of range, not a
  // foldable hinge, sign not +-1, fixed twice) and std::runtime_error("... holes not
  // supported yet") if some component has genus > 0, or holes without close_holes.
  ClosureSystem(const CreasePattern& pattern, const Topology& topology, const ClosureOptions& options = {});

  int num_unknowns() const { return static_cast<int>(free_edges_.size()); }
  int num_vertices() const { return static_cast<int>(vertices_.size()); }  // interior vertices with rows
  int num_rows() const { return hole_row_begin() + 6 * num_holes(); }
  int num_holes() const { return static_cast<int>(holes_.size()); }  // hole loops with rows
  // First row of the hole blocks (rows hole_row_begin() + 6k .. +5 for hole k).
  int hole_row_begin() const { return 3 * num_vertices() + static_cast<int>(equalities_.size()); }
  const HoleLoop& hole_loop(int k) const { return holes_[k]; }
  double length_scale() const { return length_scale_; }
  int num_edges() const { return num_edges_; }

  // Edge of unknown k; unknown of edge e (-1 if e is not a free crease).
  int edge_of_unknown(int k) const { return free_edges_[k]; }
  int unknown_of_edge(int e) const { return unknown_of_edge_[e]; }
  const std::vector<int>& free_edges() const { return free_edges_; }
  // Interior vertex of row block k (rows 3k..3k+2).
  int vertex_of_block(int k) const { return vertices_[k].vertex; }

  // Changes the value of a fixed crease (radians). Throws std::invalid_argument if the
  // edge was not declared fixed.
  void set_fixed_value(int edge, double value);
  double fixed_value(int edge) const;  // 0 for F/J hinges and non-hinges, the value for fixed creases

  // Per-edge fold angles (size num_edges()) -> unknowns (the free entries).
  Eigen::VectorXd unknowns_from_edges(const Eigen::VectorXd& edge_angles) const;
  // Unknowns -> per-edge fold angles: free edges from x, fixed creases their value, the
  // rest 0.
  Eigen::VectorXd edges_from_unknowns(const Eigen::VectorXd& x) const;

  // Residual r(x) (size num_rows(), radians).
  Eigen::VectorXd residual(const Eigen::VectorXd& x) const;
  // Residual and exact Jacobian dr/dx (num_rows() x num_unknowns(), column-major,
  // compressed). The sparsity pattern depends only on the system, not on x (entries that
  // happen to be 0 are stored), so a factorisation's symbolic analysis can be reused.
  // Cost O(sum of vertex degrees).
  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& residual, Eigen::SparseMatrix<double>& jacobian) const;

 private:
  struct VertexRow {
    int vertex = -1;
    std::vector<int> edges;       // fan edges, CCW
    std::vector<double> sectors;  // radians
  };
  int num_edges_ = 0;
  std::vector<int> free_edges_;
  std::vector<int> unknown_of_edge_;
  std::vector<double> constant_angle_;  // per edge: value used when the edge is not free
  std::vector<bool> is_fixed_;
  std::vector<VertexRow> vertices_;
  std::vector<CreaseEquality> equalities_;
  CreasePattern hole_geometry_;             // vertices, edges, faces of the pattern (hole rows only)
  std::vector<HoleLoop> holes_;
  std::vector<double> reference_angle_;     // per edge (hole rows only)
  std::vector<bool> is_rigid_hinge_;        // F/J hinge: keeps its reference angle in hole rows
  double length_scale_ = 1.0;

  // Relative angles theta of a hole loop's steps.
  void gather_hole(const HoleLoop& loop, const Eigen::VectorXd& x, std::vector<double>& theta) const;

  // Fixed CSC pattern of the Jacobian (built once by the constructor) and, for every entry
  // evaluate() produces (vertex fans, then equalities, then hole loops, in that order), the
  // position of its value in that pattern. evaluate() then fills values in place: O(nnz),
  // no sorting or allocation once the caller's matrix has the pattern.
  std::vector<int> jac_outer_, jac_inner_;
  std::vector<int> jac_slot_;
  void build_jacobian_pattern();

  // Per-vertex fold angles gathered from x.
  void gather(const VertexRow& row, const Eigen::VectorXd& x, std::vector<double>& angles) const;
  double angle_of_edge(int e, const Eigen::VectorXd& x) const;
};

// J(x) as a dense matrix (num_rows() x num_unknowns()): for the small-pattern analyses that
// need SVDs and determinants (tangent cones, bifurcations, branch exploration).
Eigen::MatrixXd dense_jacobian(const ClosureSystem& system, const Eigen::VectorXd& x);

}  // namespace rigidfold
