#include "kernel/thick/bennett_heights.hpp"

#include <cmath>
#include <deque>
#include <numbers>
#include <sstream>

#include "kernel/closure/closure_system.hpp"
#include "kernel/thick/hinge_heights.hpp"

namespace rigidfold {
namespace {

constexpr double kPi = std::numbers::pi;

// Staircase heights (relative, per fan crease) starting at crease `start`.
std::vector<double> staircase(const std::vector<double>& sectors, int start, double thickness) {
  std::vector<double> h(4, 0.0);
  const double sign[4] = {+1, +1, -1, -1};
  double level = 0.0;
  for (int step = 0; step < 3; ++step) {
    const int sector = (start + step) % 4;
    level += sign[step] * thickness * std::sin(sectors[sector]);
    h[(start + step + 1) % 4] = level;
  }
  return h;
}

// One vertex alone: a flat pattern with the vertex's sectors, its crease heights h, and
// the closure residual of its thick sheet at fold angles rho (fan order).
double single_vertex_gap(const std::vector<double>& sectors, const std::vector<double>& h, const std::vector<double>& rho) {
  CreasePattern p;
  p.vertices.push_back(Eigen::Vector3d::Zero());
  double direction = 0.0;
  for (int i = 0; i < 4; ++i) {
    p.vertices.emplace_back(std::cos(direction), std::sin(direction), 0.0);
    direction += sectors[i];
  }
  for (int i = 0; i < 4; ++i) {
    p.edges.push_back({0, i + 1});
    p.assignments.push_back(Assignment::Unassigned);
  }
  for (int i = 0; i < 4; ++i) {
    p.edges.push_back({i + 1, (i + 1) % 4 + 1});
    p.assignments.push_back(Assignment::Boundary);
    p.faces.push_back({0, i + 1, (i + 1) % 4 + 1});
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  std::vector<double> heights(p.num_edges(), 0.0);
  for (int i = 0; i < 4; ++i) heights[i] = h[i];
  const ThickHeightSheet sheet = thick_sheet_from_hinge_heights(p, build_topology(p, "bennett vertex"), heights);
  const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
  Eigen::VectorXd fold = Eigen::VectorXd::Zero(p.num_edges());
  for (int i = 0; i < 4; ++i) fold[i] = rho[i];
  return system.residual(system.unknowns_from_edges(sheet.sheet_edge_angles(fold))).cwiseAbs().maxCoeff();
}

}  // namespace

std::vector<double> bennett_hinge_heights(const CreasePattern& flat, const Topology& topology,
                                          const Eigen::VectorXd& folded_state, double thickness) {
  if (!(thickness > 0)) throw std::invalid_argument("bennett heights: thickness must be > 0");
  if (folded_state.size() != flat.num_edges()) throw std::invalid_argument("bennett heights: one fold angle per edge expected");
  const int nv = flat.num_vertices();
  // Relative heights per interior vertex, keyed by edge.
  std::vector<std::vector<std::pair<int, double>>> relative(nv);
  for (int v : topology.interior_vertices) {
    const Fan& fan = topology.stars[v].fans[0];
    const std::string where = "bennett heights: vertex " + std::to_string(v);
    if (fan.edges.size() != 4) throw std::invalid_argument(where + " has degree " + std::to_string(fan.edges.size()) + ", not 4");
    if (std::abs(fan.sectors[0] + fan.sectors[2] - kPi) > 1e-9 || std::abs(fan.sectors[1] + fan.sectors[3] - kPi) > 1e-9)
      throw std::invalid_argument(where + " is not flat-foldable (Kawasaki)");
    std::vector<double> rho(4);
    for (int i = 0; i < 4; ++i) rho[i] = folded_state[fan.edges[i]];
    int chosen = -1;
    double best = 1e300;
    for (int start = 0; start < 4; ++start) {
      const double gap = single_vertex_gap(fan.sectors, staircase(fan.sectors, start, thickness), rho);
      if (gap < best) {
        best = gap;
        chosen = start;
      }
    }
    if (!(best <= 1e-10)) {
      std::ostringstream message;
      message << where << ": no hinge order closes its Bennett at the given state (least residual " << best << ")";
      throw std::invalid_argument(message.str());
    }
    const std::vector<double> h = staircase(fan.sectors, chosen, thickness);
    for (int i = 0; i < 4; ++i) relative[v].emplace_back(fan.edges[i], h[i]);
  }
  // Shift each vertex's staircase along a spanning forest of the vertex graph (vertices
  // joined by shared creases), then check every shared crease.
  std::vector<std::vector<int>> vertices_of_edge(flat.num_edges());
  for (int v : topology.interior_vertices)
    for (const auto& [e, h] : relative[v]) vertices_of_edge[e].push_back(v);
  auto relative_height = [&](int v, int e) {
    for (const auto& [edge, h] : relative[v])
      if (edge == e) return h;
    return 0.0;
  };
  std::vector<double> shift(nv, 0.0);
  std::vector<bool> placed(nv, false);
  for (int root : topology.interior_vertices) {
    if (placed[root]) continue;
    placed[root] = true;
    std::deque<int> queue{root};
    while (!queue.empty()) {
      const int u = queue.front();
      queue.pop_front();
      for (const auto& [e, h] : relative[u])
        for (int w : vertices_of_edge[e])
          if (!placed[w]) {
            shift[w] = shift[u] + h - relative_height(w, e);
            placed[w] = true;
            queue.push_back(w);
          }
    }
  }
  std::vector<double> heights(flat.num_edges(), 0.0);
  for (int e = 0; e < flat.num_edges(); ++e) {
    const auto& at = vertices_of_edge[e];
    if (at.empty()) continue;
    heights[e] = shift[at[0]] + relative_height(at[0], e);
    for (std::size_t k = 1; k < at.size(); ++k) {
      const double other = shift[at[k]] + relative_height(at[k], e);
      if (std::abs(other - heights[e]) > 1e-12 * thickness) {
        std::ostringstream message;
        message << "bennett heights: crease " << e << " would sit at height " << heights[e] << " for vertex " << at[0]
                << " and " << other << " for vertex " << at[k] << " (thickness " << thickness << ")";
        throw HingeHeightConflict(e, at[0], at[k], message.str());
      }
    }
  }
  return heights;
}

}  // namespace rigidfold
