#include "kernel/thick/vertex_height_steps.hpp"

#include <cmath>
#include <deque>
#include <sstream>

namespace rigidfold {

std::vector<double> hinge_heights_from_steps(const CreasePattern& flat, const Topology& topology,
                                             const std::vector<std::vector<double>>& steps, double tolerance) {
  const int nv = flat.num_vertices();
  if (static_cast<int>(steps.size()) != nv) throw std::invalid_argument("hinge heights: expected steps for every vertex");
  // Height of each fan crease relative to the vertex's first crease.
  std::vector<std::vector<std::pair<int, double>>> relative(nv);
  for (int v : topology.interior_vertices) {
    const Fan& fan = topology.stars[v].fans[0];
    const std::vector<double>& s = steps[v];
    const std::string where = "hinge heights: vertex " + std::to_string(v);
    if (s.size() != fan.edges.size())
      throw std::invalid_argument(where + ": " + std::to_string(s.size()) + " steps for " + std::to_string(fan.edges.size()) + " sectors");
    double level = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      relative[v].emplace_back(fan.edges[i], level);
      level += s[i];
    }
    if (std::abs(level) > tolerance) {
      std::ostringstream message;
      message << where << ": the steps do not come back round (sum " << level << ")";
      throw std::invalid_argument(message.str());
    }
  }
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
      if (std::abs(other - heights[e]) > tolerance) {
        std::ostringstream message;
        message << "hinge heights: crease " << e << " would sit at height " << heights[e] << " for vertex " << at[0] << " and "
                << other << " for vertex " << at[k];
        throw HingeHeightConflict(e, at[0], at[k], message.str());
      }
    }
  }
  return heights;
}

}  // namespace rigidfold
