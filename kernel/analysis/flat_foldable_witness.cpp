#include "kernel/analysis/flat_foldable_witness.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <numbers>
#include <vector>

namespace rigidfold {
namespace {

constexpr double kPi = std::numbers::pi;

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

}  // namespace

std::optional<FlatFoldableWitness> flat_foldable_witness(const CreasePattern& pattern, const Topology& topology,
                                                         double kawasaki_tolerance) {
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
  if (w.max_kawasaki_defect <= kawasaki_tolerance) return std::nullopt;  // the exact model applies
  w.precision = coordinate_precision(pattern);
  if (!w.precision.rounded) return std::nullopt;

  const int n = 2 * pattern.num_vertices();
  Eigen::VectorXd rounding(n);
  for (int i = 0; i < pattern.num_vertices(); ++i) rounding[2 * i] = rounding[2 * i + 1] = w.precision.vertex_rounding[i];
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
      if (g.lpNorm<Eigen::Infinity>() <= 1e-14) break;
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
      for (int k = 0; k < 2; ++k) {
        const double move = std::abs(x[i][k] - pattern.vertices[i][k]);
        ratio[2 * i + k] = rounding[2 * i + k] > 0 ? move / rounding[2 * i + k] : (move > 0 ? INFINITY : 0.0);
      }
    const double largest = ratio.maxCoeff();
    if (largest < best_ratio) {
      best_ratio = largest;
      best = x;
      best_iterations = iterations;
    }
    if (largest <= 0.5 || !std::isfinite(largest)) break;
    for (int c = 0; c < n; ++c) weight[c] /= std::max(ratio[c] / largest, 0.05);
  }
  const std::vector<Eigen::Vector3d>& x = best;
  w.iterations = best_iterations;
  for (int i = 0; i < pattern.num_vertices(); ++i) {
    const double move = (x[i] - pattern.vertices[i]).cwiseAbs().maxCoeff();
    const double ratio = w.precision.vertex_rounding[i] > 0 ? move / w.precision.vertex_rounding[i] : (move > 0 ? INFINITY : 0);
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
