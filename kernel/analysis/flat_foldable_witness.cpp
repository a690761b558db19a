#include "kernel/analysis/flat_foldable_witness.hpp"
#include "kernel/math/angle_units.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <numbers>
#include <vector>

#include "kernel/pattern/vertex_boxes.hpp"

namespace rigidfold {
namespace {


double wrap(double a) {  // to (-pi, pi]
  a = std::remainder(a, 2 * kPi);
  return a <= -kPi ? a + 2 * kPi : a;
}

// The four neighbours of each interior vertex in counter-clockwise order.
std::vector<std::array<int, 4>> neighbours(const CreasePattern& p, const Topology& t) {
  std::vector<std::array<int, 4>> out;
  for (int v : t.interior_vertices) {
    const std::vector<int>& edges = t.stars[v].fans[0].edges;
    std::array<int, 4> n{};
    for (int i = 0; i < 4; ++i) {
      const auto& e = p.edges[edges[i]];
      n[i] = e[0] == v ? e[1] : e[0];
    }
    out.push_back(n);
  }
  return out;
}

// Kawasaki defects g_v and their Jacobian with respect to (x0, y0, x1, y1, ...).
void defects(const std::vector<Eigen::Vector3d>& x, const std::vector<int>& centre,
             const std::vector<std::array<int, 4>>& ring, Eigen::VectorXd& g, Eigen::SparseMatrix<double>* J) {
  const int m = static_cast<int>(centre.size());
  g.resize(m);
  std::vector<Eigen::Triplet<double>> entries;
  for (int r = 0; r < m; ++r) {
    const int v = centre[r];
    double sum = -kPi;
    for (int i = 0; i < 4; ++i) {
      const int w = ring[r][i];
      const Eigen::Vector2d d = (x[w] - x[v]).head<2>();
      const double sign = (i == 1 || i == 3) ? 1.0 : -1.0;  // theta_2 - theta_1 + theta_4 - theta_3
      sum += sign * std::atan2(d.y(), d.x());
      if (J) {
        // d theta / d (x_w) = (-dy, dx) / |d|^2; the centre gets the opposite.
        const Eigen::Vector2d grad = Eigen::Vector2d(-d.y(), d.x()) / d.squaredNorm() * sign;
        entries.emplace_back(r, 2 * w, grad.x());
        entries.emplace_back(r, 2 * w + 1, grad.y());
        entries.emplace_back(r, 2 * v, -grad.x());
        entries.emplace_back(r, 2 * v + 1, -grad.y());
      }
    }
    g[r] = wrap(sum);
  }
  if (J) {
    J->resize(m, 2 * static_cast<int>(x.size()));
    J->setFromTriplets(entries.begin(), entries.end());
  }
}

// Loop-gain rows: for the given mode of each interior vertex, log |w| of its four creases
// (flat_fold_multipliers) as a function of the coordinates; every crease joining two interior
// vertices ties them, tau_v / tau_u = w_u / w_v; a spanning forest of the ties fixes log |tau|,
// and each tie off the forest closes a cycle whose log |loop gain| must be 0. Rows: those
// cycle sums, C * (log |w_u,e| - log |w_v,e|) over the cycle's ties (C: +-1 per tie).
class GainRows {
 public:
  // Empty (no rows) when a tie has a zero multiplier or a cycle's gain is negative (no move of
  // the coordinates within the rounding turns -1 into +1).
  GainRows(const CreasePattern& p, const Topology& t, const std::vector<std::array<int, 4>>& ring,
           const std::vector<FlatFoldMode>& modes)
      : centre_(t.interior_vertices), ring_(ring), modes_(modes) {
    const int m = static_cast<int>(centre_.size());
    std::vector<int> model_of(p.num_vertices(), -1);
    for (int k = 0; k < m; ++k) model_of[centre_[k]] = k;
    // Ties: (model vertex, slot) on both sides.
    for (int k = 0; k < m; ++k)
      for (int i = 0; i < 4; ++i) {
        const int other = model_of[ring_[k][i]];
        if (other < 0 || other < k) continue;
        int j = 0;
        while (j < 4 && ring_[other][j] != centre_[k]) ++j;
        if (j == 4) return;  // not a simple tie: no rows
        ties_.push_back({k, i, other, j});
      }
    sign_.resize(m);
    for (int k = 0; k < m; ++k) {
      const auto w = multipliers_at(p.vertices, k);
      if (!w) return;
      for (int i = 0; i < 4; ++i) sign_[k][i] = (*w)[i] > 0 ? 1 : ((*w)[i] < 0 ? -1 : 0);
    }
    for (const Tie& tie : ties_)
      if (sign_[tie.u][tie.i] == 0 || sign_[tie.v][tie.j] == 0) return;
    // Spanning forest by breadth-first search; each tie off it is one cycle.
    std::vector<std::vector<std::pair<int, int>>> adjacent(m);  // (tie, neighbour)
    for (int e = 0; e < static_cast<int>(ties_.size()); ++e) {
      adjacent[ties_[e].u].push_back({e, ties_[e].v});
      adjacent[ties_[e].v].push_back({e, ties_[e].u});
    }
    std::vector<int> parent_tie(m, -1), depth(m, -1);
    std::vector<char> in_tree(ties_.size(), 0);
    for (int r = 0; r < m; ++r) {
      if (depth[r] >= 0) continue;
      depth[r] = 0;
      std::vector<int> queue{r};
      for (std::size_t q = 0; q < queue.size(); ++q)
        for (const auto& [e, w] : adjacent[queue[q]])
          if (depth[w] < 0) {
            depth[w] = depth[queue[q]] + 1;
            parent_tie[w] = e;
            in_tree[e] = 1;
            queue.push_back(w);
          }
    }
    // Cycle of tie e = (u, v): e itself plus the tree paths from u and v to their meeting.
    // Orientation: walking u -> v along e, then v -> ... -> u along the tree.
    for (int e = 0; e < static_cast<int>(ties_.size()); ++e) {
      if (in_tree[e]) continue;
      std::vector<std::pair<int, double>> cycle{{e, 1.0}};
      int a = ties_[e].v, b = ties_[e].u;  // walk from v back to u
      std::vector<std::pair<int, double>> tail;
      while (a != b) {
        if (depth[a] >= depth[b]) {
          const int te = parent_tie[a];
          cycle.push_back({te, ties_[te].u == a ? 1.0 : -1.0});  // leaving a along te
          a = ties_[te].u == a ? ties_[te].v : ties_[te].u;
        } else {
          const int te = parent_tie[b];
          tail.push_back({te, ties_[te].v == b ? 1.0 : -1.0});  // arriving at b along te
          b = ties_[te].u == b ? ties_[te].v : ties_[te].u;
        }
      }
      cycle.insert(cycle.end(), tail.rbegin(), tail.rend());
      cycles_.push_back(std::move(cycle));
    }
    // A negative gain cannot be moved to +1.
    for (const auto& cycle : cycles_) {
      int sign = 1;
      for (const auto& [te, dir] : cycle) {
        const Tie& tie = ties_[te];
        sign *= (sign_[tie.u][tie.i] == sign_[tie.v][tie.j]) ? 1 : -1;
      }
      if (sign < 0) {
        cycles_.clear();
        return;
      }
    }
    usable_ = !cycles_.empty();
  }

  bool usable() const { return usable_; }
  int rows() const { return static_cast<int>(cycles_.size()); }

  // Values (log |loop gain| per cycle) and, if J, their Jacobian (central differences of the
  // per-vertex log multipliers, each local to a vertex and its four neighbours).
  void evaluate(const std::vector<Eigen::Vector3d>& x, Eigen::VectorXd& values, Eigen::SparseMatrix<double>* J, double h) const {
    bool ok = true;
    const std::vector<std::array<double, 4>> lw = log_multipliers(x, ok);
    values.resize(rows());
    for (int c = 0; c < rows(); ++c) {
      double sum = 0;
      for (const auto& [te, dir] : cycles_[c]) sum += dir * tie_log_ratio(lw, ties_[te]);
      values[c] = ok ? sum : INFINITY;
    }
    if (!J) return;
    // d log|w_k| / d coordinate, for the 10 coordinates of vertex k and its ring.
    const int m = static_cast<int>(centre_.size());
    std::vector<std::array<std::array<double, 10>, 4>> d(m);
    std::vector<Eigen::Vector3d> y = x;
    for (int k = 0; k < m; ++k) {
      const std::array<int, 5> who{centre_[k], ring_[k][0], ring_[k][1], ring_[k][2], ring_[k][3]};
      for (int a = 0; a < 5; ++a)
        for (int axis = 0; axis < 2; ++axis) {
          const double keep = y[who[a]][axis];
          y[who[a]][axis] = keep + h;
          const std::array<double, 4> plus = vertex_log_multipliers(y, k, ok);
          y[who[a]][axis] = keep - h;
          const std::array<double, 4> minus = vertex_log_multipliers(y, k, ok);
          y[who[a]][axis] = keep;
          for (int i = 0; i < 4; ++i) d[k][i][2 * a + axis] = (plus[i] - minus[i]) / (2 * h);
        }
    }
    std::vector<Eigen::Triplet<double>> entries;
    for (int c = 0; c < rows(); ++c)
      for (const auto& [te, dir] : cycles_[c]) {
        const Tie& tie = ties_[te];
        for (const auto& [k, i, sign] : {std::tuple<int, int, double>{tie.u, tie.i, dir}, {tie.v, tie.j, -dir}}) {
          const std::array<int, 5> who{centre_[k], ring_[k][0], ring_[k][1], ring_[k][2], ring_[k][3]};
          for (int a = 0; a < 5; ++a)
            for (int axis = 0; axis < 2; ++axis) entries.emplace_back(c, 2 * who[a] + axis, sign * d[k][i][2 * a + axis]);
        }
      }
    J->resize(rows(), 2 * static_cast<int>(x.size()));
    J->setFromTriplets(entries.begin(), entries.end());  // duplicates are summed
  }

 private:
  struct Tie {
    int u, i, v, j;  // model vertex u's slot i and model vertex v's slot j are one crease
  };
  static double tie_log_ratio(const std::vector<std::array<double, 4>>& lw, const Tie& t) { return lw[t.u][t.i] - lw[t.v][t.j]; }

  // The multipliers of model vertex k's mode from the coordinates x; nullopt when its sectors
  // are not a vertex (a sector outside (0, pi) or far off Kawasaki).
  std::optional<std::array<double, 4>> multipliers_at(const std::vector<Eigen::Vector3d>& x, int k) const {
    std::array<double, 4> theta{}, sectors{};
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector2d dv = (x[ring_[k][i]] - x[centre_[k]]).head<2>();
      theta[i] = std::atan2(dv.y(), dv.x());
    }
    for (int i = 0; i < 4; ++i) {
      double a = std::fmod(theta[(i + 1) % 4] - theta[i], 2 * kPi);
      if (a <= 0) a += 2 * kPi;
      sectors[i] = a;
    }
    try {
      // Off Kawasaki by the rounding, the multipliers' formula extends smoothly.
      return flat_fold_multipliers(sectors, modes_[k], 1e-2).direction;
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
  }

  std::array<double, 4> vertex_log_multipliers(const std::vector<Eigen::Vector3d>& x, int k, bool& ok) const {
    std::array<double, 4> out{};
    const auto w = multipliers_at(x, k);
    for (int i = 0; i < 4; ++i) {
      out[i] = w && (*w)[i] != 0 ? std::log(std::abs((*w)[i])) : 0.0;
      ok = ok && w && (*w)[i] != 0;
    }
    return out;
  }

  std::vector<std::array<double, 4>> log_multipliers(const std::vector<Eigen::Vector3d>& x, bool& ok) const {
    ok = true;
    std::vector<std::array<double, 4>> lw(centre_.size());
    for (std::size_t k = 0; k < centre_.size(); ++k) lw[k] = vertex_log_multipliers(x, static_cast<int>(k), ok);
    return lw;
  }

  const std::vector<int>& centre_;
  const std::vector<std::array<int, 4>>& ring_;
  const std::vector<FlatFoldMode>& modes_;
  std::vector<Tie> ties_;
  std::vector<std::vector<std::pair<int, double>>> cycles_;  // (tie, +-1)
  std::vector<std::array<int, 4>> sign_;
  bool usable_ = false;
};

}  // namespace

std::optional<FlatFoldableWitness> flat_foldable_witness(const CreasePattern& pattern, const Topology& topology,
                                                         double kawasaki_tolerance, const std::vector<FlatFoldMode>* gain_modes,
                                                         std::optional<double> stated_tolerance) {
  if (topology.interior_vertices.empty()) return std::nullopt;
  for (const Eigen::Vector3d& v : pattern.vertices)
    if (v.z() != 0.0) return std::nullopt;
  for (int v : topology.interior_vertices)
    if (topology.stars[v].fans[0].edges.size() != 4) return std::nullopt;
  FlatFoldableWitness w;
  const std::vector<int>& centre = topology.interior_vertices;
  const std::vector<std::array<int, 4>> ring = neighbours(pattern, topology);
  Eigen::VectorXd g;
  defects(pattern.vertices, centre, ring, g, nullptr);
  for (int r = 0; r < g.size(); ++r)
    if (std::abs(g[r]) > w.max_kawasaki_defect) {
      w.max_kawasaki_defect = std::abs(g[r]);
      w.worst_defect_vertex = centre[r];
    }
  const bool with_gains = gain_modes && gain_modes->size() == centre.size();
  if (w.max_kawasaki_defect <= kawasaki_tolerance && !with_gains) return std::nullopt;  // the exact model applies
  std::optional<GainRows> gains;
  if (with_gains) {
    gains.emplace(pattern, topology, ring, *gain_modes);
    if (!gains->usable()) return std::nullopt;
    w.loop_gain_rows = gains->rows();
  }
  double extent = 0;
  for (const Eigen::Vector3d& v : pattern.vertices) extent = std::max(extent, v.cwiseAbs().maxCoeff());
  const double fd_step = 1e-7 * std::max(extent, 1e-300);
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
      defects(x, centre, ring, g, &J);
      if (gains) {
        // Kawasaki rows, then the loop-gain rows (log |gain| of each independent cycle).
        Eigen::VectorXd gg;
        Eigen::SparseMatrix<double> Jg;
        gains->evaluate(x, gg, &Jg, fd_step);
        const bool done = g.lpNorm<Eigen::Infinity>() <= 1e-14 && gg.lpNorm<Eigen::Infinity>() <= 1e-13;
        w.max_log_gain = gg.lpNorm<Eigen::Infinity>();
        if (done) break;
        Eigen::VectorXd both(g.size() + gg.size());
        both << g, gg;
        g = both;
        Eigen::SparseMatrix<double> stacked(J.rows() + Jg.rows(), J.cols());
        std::vector<Eigen::Triplet<double>> t;
        for (int c = 0; c < J.outerSize(); ++c)
          for (Eigen::SparseMatrix<double>::InnerIterator it(J, c); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
        for (int c = 0; c < Jg.outerSize(); ++c)
          for (Eigen::SparseMatrix<double>::InnerIterator it(Jg, c); it; ++it) t.emplace_back(J.rows() + it.row(), it.col(), it.value());
        stacked.setFromTriplets(t.begin(), t.end());
        J = std::move(stacked);
      } else if (g.lpNorm<Eigen::Infinity>() <= 1e-14) {
        break;
      }
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
    if (gains) {  // a solve that did not reach the gain rows is no witness
      Eigen::VectorXd gg;
      gains->evaluate(x, gg, nullptr, fd_step);
      if (!(gg.lpNorm<Eigen::Infinity>() <= 1e-12)) largest = INFINITY;
    }
    if (best.empty() || largest < best_ratio) {  // the first round is kept even when no round is within bounds
      best_ratio = largest;
      best = x;
      best_iterations = iterations;
    }
    if (largest <= 0.5 || !std::isfinite(largest)) break;
    for (int c = 0; c < n; ++c) weight[c] /= std::max(ratio[c] / largest, 0.05);
  }
  if (gains && !std::isfinite(best_ratio)) return std::nullopt;  // no solve closed the loop gains
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
