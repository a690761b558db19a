#include "kernel/analysis/flat_fold_constraints.hpp"

#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "kernel/math/angle_units.hpp"

namespace rigidfold {
namespace {

double wrap(double a) {  // to (-pi, pi]
  a = std::remainder(a, 2 * kPi);
  return a <= -kPi ? a + 2 * kPi : a;
}

double positive_angle(double a) {  // to (0, 2 pi]
  a = std::fmod(a, 2 * kPi);
  return a <= 0 ? a + 2 * kPi : a;
}

// A gradient over the ten coordinates of a vertex and its ring: (x, y) of the centre, then of
// neighbours 0..3.
using LocalGradient = Eigen::Matrix<double, 10, 1>;

// The directions of a vertex's four creases, and their gradients.
struct Directions {
  std::array<double, 4> theta{};
  std::array<LocalGradient, 4> grad;
};

Directions directions(const std::vector<Eigen::Vector3d>& x, int centre, const std::array<int, 4>& ring) {
  Directions out;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d d = (x[ring[i]] - x[centre]).head<2>();
    out.theta[i] = std::atan2(d.y(), d.x());
    const Eigen::Vector2d g = Eigen::Vector2d(-d.y(), d.x()) / d.squaredNorm();
    out.grad[i].setZero();
    out.grad[i].segment<2>(2 + 2 * i) = g;
    out.grad[i].segment<2>(0) = -g;
  }
  return out;
}

// log |w_i| of the vertex's mode and their gradients.
struct LogMultipliers {
  std::array<double, 4> value{};
  std::array<LocalGradient, 4> grad;
  bool finite = true;  // false where a multiplier is 0
};

LogMultipliers log_multipliers(const Directions& dir, FlatFoldMode mode) {
  const double a0 = positive_angle(dir.theta[1] - dir.theta[0]);
  const double a1 = positive_angle(dir.theta[2] - dir.theta[1]);
  const LocalGradient grad_a0 = dir.grad[1] - dir.grad[0];
  const LocalGradient grad_a1 = dir.grad[2] - dir.grad[1];
  const double d = 0.5 * (a1 - a0), s = 0.5 * (a1 + a0);
  const LocalGradient grad_d = 0.5 * (grad_a1 - grad_a0), grad_s = 0.5 * (grad_a1 + grad_a0);
  // Creases 0 and 2 depend on d, creases 1 and 3 on s.
  const bool sine = mode == FlatFoldMode::kEqual13;
  const double fd = sine ? std::sin(d) : std::cos(d), fs = sine ? std::sin(s) : std::cos(s);
  // d log|sin u| / du = cot u, d log|cos u| / du = -tan u.
  const double cd = sine ? std::cos(d) / fd : -std::sin(d) / fd;
  const double cs = sine ? std::cos(s) / fs : -std::sin(s) / fs;
  LogMultipliers out;
  out.finite = fd != 0.0 && fs != 0.0;
  for (int i = 0; i < 4; ++i) {
    const bool even = i % 2 == 0;
    out.value[i] = std::log(std::abs(even ? fd : fs));
    out.grad[i] = even ? LocalGradient(cd * grad_d) : LocalGradient(cs * grad_s);
  }
  return out;
}

}  // namespace

std::array<double, 4> mode_multipliers(double alpha_0, double alpha_1, FlatFoldMode mode) {
  const double d = 0.5 * (alpha_1 - alpha_0), s = 0.5 * (alpha_1 + alpha_0);
  if (mode == FlatFoldMode::kEqual13) return {std::sin(d), -std::sin(s), -std::sin(d), -std::sin(s)};
  return {std::cos(d), -std::cos(s), std::cos(d), std::cos(s)};
}

FlatFoldConstraints::FlatFoldConstraints(const CreasePattern& pattern, const Topology& topology, std::vector<FlatFoldMode> modes)
    : centre_(topology.interior_vertices), modes_(std::move(modes)) {
  for (int v : centre_) {
    const std::vector<int>& edges = topology.stars[v].fans[0].edges;
    if (edges.size() != 4)
      throw std::invalid_argument("vertex " + std::to_string(v) + " has " + std::to_string(edges.size()) +
                                  " creases: the flat-fold conditions are those of degree-4 vertices");
    std::array<int, 4> n{};
    for (int i = 0; i < 4; ++i) {
      const auto& e = pattern.edges[edges[i]];
      n[i] = e[0] == v ? e[1] : e[0];
    }
    ring_.push_back(n);
  }
  if (modes_.empty()) {
    why_no_gains_ = "no vertex modes given";
    return;
  }
  if (modes_.size() != centre_.size()) throw std::invalid_argument("FlatFoldConstraints: one mode per interior vertex");
  build_cycles(pattern);
}

void FlatFoldConstraints::build_cycles(const CreasePattern& pattern) {
  const std::vector<Eigen::Vector3d>& x0 = pattern.vertices;
  const int m = kawasaki_rows();
  std::vector<int> model_of(x0.size(), -1);
  for (int k = 0; k < m; ++k) model_of[centre_[k]] = k;
  for (int k = 0; k < m; ++k)
    for (int i = 0; i < 4; ++i) {
      const int other = model_of[ring_[k][i]];
      if (other < 0 || other < k) continue;
      int j = 0;
      while (j < 4 && ring_[other][j] != centre_[k]) ++j;
      if (j == 4 || other == k) {
        why_no_gains_ = "vertices " + std::to_string(centre_[k]) + " and " + std::to_string(ring_[k][i]) + " are joined by more than a crease";
        return;
      }
      ties_.push_back({k, i, other, j});
    }
  std::vector<std::array<int, 4>> sign(m);
  for (int k = 0; k < m; ++k) {
    const Directions dir = directions(x0, centre_[k], ring_[k]);
    const auto w = mode_multipliers(positive_angle(dir.theta[1] - dir.theta[0]), positive_angle(dir.theta[2] - dir.theta[1]), modes_[k]);
    for (int i = 0; i < 4; ++i) sign[k][i] = w[i] > 0 ? 1 : (w[i] < 0 ? -1 : 0);
  }
  for (const Tie& tie : ties_)
    if (sign[tie.u][tie.i] == 0 || sign[tie.v][tie.j] == 0) {
      why_no_gains_ = "the crease joining vertices " + std::to_string(centre_[tie.u]) + " and " + std::to_string(centre_[tie.v]) +
                      " stays flat in the modes given (a zero multiplier)";
      return;
    }
  if (!face_cycles(pattern, model_of)) fundamental_cycles();
  for (std::size_t c = 0; c < cycles_.size(); ++c) {
    int cycle_sign = 1;
    for (const auto& [te, orientation] : cycles_[c]) cycle_sign *= sign[ties_[te].u][ties_[te].i] == sign[ties_[te].v][ties_[te].j] ? 1 : -1;
    if (cycle_sign < 0) {
      const std::vector<int> around = cycle_vertices(static_cast<int>(c));
      cycles_.clear();
      why_no_gains_ = "the cycle of ties around vertices";
      for (int v : around) why_no_gains_ += " " + std::to_string(v);
      why_no_gains_ += " has a negative loop gain in the modes given";
      return;
    }
  }
  gains_usable_ = true;
  if (cycles_.empty()) why_no_gains_ = "the ties close no cycle";
}

bool FlatFoldConstraints::face_cycles(const CreasePattern& pattern, const std::vector<int>& model_of) {
  // The faces whose corners are all interior vertices: on a disk they are the bounded faces of
  // the tie graph, so they form a basis of its cycles; checked by counting (E - V + C).
  std::map<std::pair<int, int>, int> tie_of;  // (model u, model v), u < v -> tie
  for (int e = 0; e < static_cast<int>(ties_.size()); ++e)
    tie_of[{std::min(ties_[e].u, ties_[e].v), std::max(ties_[e].u, ties_[e].v)}] = e;
  for (const std::vector<int>& face : pattern.faces) {
    std::vector<std::pair<int, double>> cycle;
    for (std::size_t i = 0; i < face.size(); ++i) {
      const int a = model_of[face[i]], b = model_of[face[(i + 1) % face.size()]];
      if (a < 0 || b < 0) break;
      const auto it = tie_of.find({std::min(a, b), std::max(a, b)});
      if (it == tie_of.end()) break;
      cycle.push_back({it->second, ties_[it->second].u == a ? 1.0 : -1.0});
    }
    if (cycle.size() == face.size()) cycles_.push_back(std::move(cycle));
  }
  // Components of the tie graph, for the count.
  std::vector<int> root(kawasaki_rows());
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  int components = kawasaki_rows();
  for (const Tie& t : ties_)
    if (find(t.u) != find(t.v)) {
      root[find(t.u)] = find(t.v);
      --components;
    }
  if (static_cast<int>(cycles_.size()) == static_cast<int>(ties_.size()) - kawasaki_rows() + components) return true;
  cycles_.clear();
  return false;
}

void FlatFoldConstraints::fundamental_cycles() {
  const int m = kawasaki_rows();
  // Spanning forest by breadth-first search; each tie off it closes one cycle.
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
  // Cycle of tie e = (u, v): e itself, walked u -> v, then the tree paths back from v to u.
  for (int e = 0; e < static_cast<int>(ties_.size()); ++e) {
    if (in_tree[e]) continue;
    std::vector<std::pair<int, double>> cycle{{e, 1.0}};
    int a = ties_[e].v, b = ties_[e].u;
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
}

std::vector<int> FlatFoldConstraints::cycle_vertices(int c) const {
  std::vector<int> out;
  for (const auto& [te, orientation] : cycles_.at(c)) out.push_back(centre_[orientation > 0 ? ties_[te].u : ties_[te].v]);
  return out;
}

void FlatFoldConstraints::evaluate(const std::vector<Eigen::Vector3d>& x, Eigen::VectorXd& values, Eigen::SparseMatrix<double>* J) const {
  const int m = kawasaki_rows();
  values.resize(rows());
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<LogMultipliers> lw(gain_rows() > 0 ? m : 0);
  auto scatter = [&](int row, int k, const LocalGradient& g, double factor) {
    const std::array<int, 5> who{centre_[k], ring_[k][0], ring_[k][1], ring_[k][2], ring_[k][3]};
    for (int a = 0; a < 5; ++a)
      for (int axis = 0; axis < 2; ++axis) entries.emplace_back(row, 2 * who[a] + axis, factor * g[2 * a + axis]);
  };
  for (int k = 0; k < m; ++k) {
    const Directions dir = directions(x, centre_[k], ring_[k]);
    values[k] = wrap(dir.theta[1] - dir.theta[0] + dir.theta[3] - dir.theta[2] - kPi);
    if (J) scatter(k, k, dir.grad[1] - dir.grad[0] + dir.grad[3] - dir.grad[2], 1.0);
    if (!lw.empty()) lw[k] = log_multipliers(dir, modes_[k]);
  }
  for (int c = 0; c < gain_rows(); ++c) {
    double sum = 0;
    bool finite = true;
    for (const auto& [te, orientation] : cycles_[c]) {
      const Tie& t = ties_[te];
      sum += orientation * (lw[t.u].value[t.i] - lw[t.v].value[t.j]);
      finite = finite && lw[t.u].finite && lw[t.v].finite;
      if (J) {
        scatter(m + c, t.u, lw[t.u].grad[t.i], orientation);
        scatter(m + c, t.v, lw[t.v].grad[t.j], -orientation);
      }
    }
    values[m + c] = finite ? sum : INFINITY;
  }
  if (J) {
    J->resize(rows(), 2 * static_cast<int>(x.size()));
    J->setFromTriplets(entries.begin(), entries.end());  // duplicates are summed
  }
}

}  // namespace rigidfold
