#include "kernel/analysis/flat_foldable_witness.hpp"
#include "kernel/math/angle_units.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <optional>
#include <numbers>
#include <vector>

#include "kernel/analysis/flat_fold_constraints.hpp"
#include "kernel/pattern/vertex_boxes.hpp"

namespace rigidfold {

std::optional<FlatFoldableWitness> flat_foldable_witness(const CreasePattern& pattern, const Topology& topology,
                                                         double kawasaki_tolerance, const std::vector<FlatFoldMode>* gain_modes,
                                                         std::optional<double> stated_tolerance) {
  if (topology.interior_vertices.empty()) return std::nullopt;
  for (const Eigen::Vector3d& v : pattern.vertices)
    if (v.z() != 0.0) return std::nullopt;
  for (int v : topology.interior_vertices)
    if (topology.stars[v].fans[0].edges.size() != 4) return std::nullopt;
  FlatFoldableWitness w;
  const bool with_gains = gain_modes && gain_modes->size() == topology.interior_vertices.size();
  const FlatFoldConstraints constraints(pattern, topology, with_gains ? *gain_modes : std::vector<FlatFoldMode>{});
  const int kawasaki_rows = constraints.kawasaki_rows();
  Eigen::VectorXd g;
  constraints.evaluate(pattern.vertices, g, nullptr);
  for (int r = 0; r < kawasaki_rows; ++r)
    if (std::abs(g[r]) > w.max_kawasaki_defect) {
      w.max_kawasaki_defect = std::abs(g[r]);
      w.worst_defect_vertex = constraints.centres()[r];
    }
  if (w.max_kawasaki_defect <= kawasaki_tolerance && !with_gains) return std::nullopt;  // the exact model applies
  if (with_gains) {
    if (!constraints.gains_usable() || constraints.gain_rows() == 0) return std::nullopt;
    w.loop_gain_rows = constraints.gain_rows();
  }
  const int n = 2 * pattern.num_vertices();
  // How far each coordinate may move: down[c] below it, up[c] above it.
  Eigen::VectorXd down(n), up(n);
  const CreasePattern::PositionBounds& bounds = pattern.position_bounds;
  if (!stated_tolerance && bounds.covers(pattern.num_vertices())) {
    // The reader knows the box of each vertex (an SVG's drawn points and their rounding).
    w.drawn_point_bounds = true;
    w.precision.decimal_places = bounds.decimal_places;
    w.precision.significant_digits = bounds.significant_digits;
    w.precision.rounded = true;
    w.precision.vertex_rounding.assign(pattern.vertices.size(), 0.0);
    for (int i = 0; i < pattern.num_vertices(); ++i)
      for (int k = 0; k < 2; ++k) {
        down[2 * i + k] = std::max(pattern.vertices[i][k] - bounds.lo[i][k], 0.0);
        up[2 * i + k] = std::max(bounds.hi[i][k] - pattern.vertices[i][k], 0.0);
        w.precision.vertex_rounding[i] = std::max({w.precision.vertex_rounding[i], down[2 * i + k], up[2 * i + k]});
      }
    w.precision.max_rounding = w.precision.vertex_rounding.empty() ? 0.0
                               : *std::max_element(w.precision.vertex_rounding.begin(), w.precision.vertex_rounding.end());
    if (!std::isfinite(w.precision.max_rounding)) return std::nullopt;  // a crossing with no usable bound
  } else {
    w.precision = input_precision(pattern, stated_tolerance);
    if (!w.precision.rounded) return std::nullopt;
    for (int i = 0; i < pattern.num_vertices(); ++i)
      down[2 * i] = down[2 * i + 1] = up[2 * i] = up[2 * i + 1] = w.precision.vertex_rounding[i];
  }
  const Eigen::VectorXd rounding = down.cwiseMax(up);
  // The same boxes, from the same sources in the same order (vertex_boxes.hpp).
  VertexBoxes boxes = vertex_boxes(pattern, stated_tolerance);
  w.box_lo = std::move(boxes.lo);
  w.box_hi = std::move(boxes.hi);
  // |move| / allowed move in its direction (infinite where nothing is allowed).
  auto move_ratio = [&](int c, double move) {
    const double allowed = move >= 0 ? up[c] : down[c];
    return allowed > 0 ? std::abs(move) / allowed : (move != 0 ? INFINITY : 0.0);
  };
  // The least u-weighted 2-norm move can still take one coordinate past its rounding while
  // others barely move; a few rounds of reweighting (coordinates that moved far get dearer,
  // each round solved afresh from the file's coordinates) spread the move toward the least
  // largest ratio. The best round is kept.
  Eigen::VectorXd weight = rounding.cwiseAbs2();  // u_c^2 per coordinate
  std::vector<Eigen::Vector3d> best;
  double best_ratio = INFINITY;
  int best_iterations = 0;
  for (int round = 0; round < 12; ++round) {
    std::vector<Eigen::Vector3d> x = pattern.vertices;
    Eigen::SparseMatrix<double> J;
    int iterations = 0;
    for (; iterations < 30; ++iterations) {
      // Kawasaki rows, then the loop-gain rows (log |gain| of each independent cycle) if any.
      constraints.evaluate(x, g, &J);
      const double kawasaki = g.head(kawasaki_rows).lpNorm<Eigen::Infinity>();
      const double gain = g.tail(g.size() - kawasaki_rows).lpNorm<Eigen::Infinity>();
      if (with_gains) w.max_log_gain = gain;
      if (kawasaki <= 1e-14 && gain <= 1e-13) break;
      const Eigen::SparseMatrix<double> JW = J * weight.asDiagonal();
      const Eigen::SparseMatrix<double> normal = JW * J.transpose();
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
      if (ldlt.info() != Eigen::Success) break;
      const Eigen::VectorXd y = ldlt.solve(-g);
      if (ldlt.info() != Eigen::Success || !y.allFinite()) break;
      const Eigen::VectorXd dx = JW.transpose() * y;
      for (int i = 0; i < pattern.num_vertices(); ++i) {
        x[i].x() += dx[2 * i];
        x[i].y() += dx[2 * i + 1];
      }
    }
    Eigen::VectorXd ratio(n);
    for (int i = 0; i < pattern.num_vertices(); ++i)
      for (int k = 0; k < 2; ++k) ratio[2 * i + k] = move_ratio(2 * i + k, x[i][k] - pattern.vertices[i][k]);
    double largest = ratio.maxCoeff();
    if (with_gains) {  // a solve that did not reach the gain rows is no witness
      Eigen::VectorXd values;
      constraints.evaluate(x, values, nullptr);
      if (!(values.tail(values.size() - kawasaki_rows).lpNorm<Eigen::Infinity>() <= 1e-12)) largest = INFINITY;
    }
    if (best.empty() || largest < best_ratio) {  // the first round is kept even when no round is within bounds
      best_ratio = largest;
      best = x;
      best_iterations = iterations;
    }
    if (largest <= 0.5 || !std::isfinite(largest)) break;
    for (int c = 0; c < n; ++c) weight[c] /= std::max(ratio[c] / largest, 0.05);
  }
  if (with_gains && !std::isfinite(best_ratio)) return std::nullopt;  // no solve closed the loop gains
  const std::vector<Eigen::Vector3d>& x = best;
  w.iterations = best_iterations;
  for (int i = 0; i < pattern.num_vertices(); ++i) {
    const double move = (x[i] - pattern.vertices[i]).cwiseAbs().maxCoeff();
    const double ratio = std::max(move_ratio(2 * i, x[i].x() - pattern.vertices[i].x()), move_ratio(2 * i + 1, x[i].y() - pattern.vertices[i].y()));
    w.max_move = std::max(w.max_move, move);
    if (ratio > w.max_move_ratio) {
      w.max_move_ratio = ratio;
      w.worst_move_vertex = i;
    }
  }
  w.witness = pattern;
  w.witness.vertices = x;
  // The check, independent of g: the witness's own sectors, from its own topology.
  w.witness_topology = build_topology(w.witness, "rounding witness");
  for (int v : w.witness_topology.interior_vertices) {
    const std::vector<double>& s = w.witness_topology.stars[v].fans[0].sectors;
    if (s.size() != 4) {
      w.witness_kawasaki = INFINITY;
      break;
    }
    w.witness_kawasaki = std::max(w.witness_kawasaki, std::abs(s[0] + s[2] - kPi));
  }
  w.explained = w.max_move_ratio <= 1.0 && w.witness_kawasaki <= kawasaki_tolerance &&
                w.witness_topology.interior_vertices == topology.interior_vertices;
  return w;
}

}  // namespace rigidfold
