#include "data/generators/diamond_arch.hpp"
#include "kernel/math/angle_units.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "data/generators/generator_common.hpp"
#include "kernel/thick/panel_compatibility.hpp"
#include "kernel/thick/vertex_height_steps.hpp"

namespace rigidfold::generators {

namespace {


int apex_top(int n, int j) { return n + 2 + j; }
int apex_bottom(int n, int j) { return n + 2 + (n + 1) + j; }
// Edge of diagonal k (0: c1, 1: c2, 2: c4, 3: c5) of interior vertex i (1..n).
int diagonal_edge(int n, int i, int k) { return (n + 1) + 4 * (i - 1) + k; }

}  // namespace

CreasePattern diamond_arch(const DiamondArchParams& params) {
  require(params.vertices >= 1 && params.vertices <= 1000, "vertices", "must be in 1 .. 1000");
  require(std::isfinite(params.a) && params.a > 0 && params.a <= 0.25 * kPi, "a", "must be in (0, pi/4] (0 .. 45 deg)");
  require(std::isfinite(params.length) && params.length > 0, "length", "must be > 0");
  const int n = params.vertices;
  const double L = params.length, h = 0.5 * L * std::tan(params.a);
  CreasePattern p;
  p.coords_2d = true;
  for (int i = 0; i <= n + 1; ++i) p.vertices.emplace_back(L * i, 0.0, 0.0);
  for (int j = 0; j <= n; ++j) p.vertices.emplace_back(L * (j + 0.5), h, 0.0);
  for (int j = 0; j <= n; ++j) p.vertices.emplace_back(L * (j + 0.5), -h, 0.0);
  auto edge = [&](int a, int b, Assignment letter) {
    p.edges.push_back({a, b});
    p.assignments.push_back(letter);
  };
  for (int j = 0; j <= n; ++j) edge(j, j + 1, Assignment::Valley);
  for (int i = 1; i <= n; ++i) {
    edge(i, apex_top(n, i), Assignment::Mountain);         // c1
    edge(i, apex_top(n, i - 1), Assignment::Mountain);     // c2
    edge(i, apex_bottom(n, i - 1), Assignment::Mountain);  // c4
    edge(i, apex_bottom(n, i), Assignment::Mountain);      // c5
  }
  for (int j = 0; j < n; ++j) edge(apex_top(n, j), apex_top(n, j + 1), Assignment::Boundary);
  for (int j = 0; j < n; ++j) edge(apex_bottom(n, j), apex_bottom(n, j + 1), Assignment::Boundary);
  edge(0, apex_top(n, 0), Assignment::Boundary);
  edge(0, apex_bottom(n, 0), Assignment::Boundary);
  edge(n + 1, apex_top(n, n), Assignment::Boundary);
  edge(n + 1, apex_bottom(n, n), Assignment::Boundary);
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  nlohmann::ordered_json g;
  g["kind"] = "diamond_arch";
  g["vertices"] = n;
  g["a_deg"] = deg_rounded(params.a);
  g["length"] = L;
  return finish_pattern(std::move(p), "Diamond arch (" + std::to_string(n) + " six-crease diamond vertices)",
                        "six-crease vertices a, 180 - 2a, a, a, 180 - 2a, a with a = " + std::to_string(deg_rounded(params.a)) + " deg",
                        g);
}

DiamondArchThick diamond_arch_thick(const CreasePattern& pattern, const Topology& topology, const DiamondArchParams& params,
                                    double t1, double t2) {
  const int n = params.vertices;
  DiamondArchThick out;
  out.model = diamond_vertex(params.a, t1, t2);
  out.model_start.assign(pattern.num_vertices(), -1);
  out.steps.assign(pattern.num_vertices(), {});
  // Height step across each model sector: the link length, signed as the Bricard twists
  // (4-40) turn - 2pi - a, a, a, 2pi - a, pi + 2a, a against the sectors a, pi - 2a, a, a,
  // pi - 2a, a: the common normal goes down across sectors 0, 3, 4 and up across 1, 2, 5.
  const double sign[6] = {-1, 1, 1, -1, -1, 1};
  std::vector<PanelThicknessClaim> claims;
  for (int i = 1; i <= n; ++i) {
    const int v = diamond_arch_valley_vertex(i);
    const Fan& fan = topology.stars.at(v).fans.at(0);
    // Model crease 0: c0 (to V_{i+1}) at odd i, c3 (to V_{i-1}) at even i.
    const int crease0 = (i % 2 == 1) ? diamond_arch_valley_edge(i) : diamond_arch_valley_edge(i - 1);
    int start = -1;
    for (int k = 0; k < static_cast<int>(fan.edges.size()); ++k)
      if (fan.edges[k] == crease0) start = k;
    if (start < 0 || fan.edges.size() != 6)
      throw std::invalid_argument("diamond_arch_thick: vertex " + std::to_string(v) + " is not a six-crease vertex on its valley crease");
    const std::vector<PanelThicknessClaim> c = vertex_panel_claims_at(out.model, topology, v, start);
    claims.insert(claims.end(), c.begin(), c.end());
    out.model_start[v] = start;
    out.steps[v].assign(6, 0.0);
    for (int m = 0; m < 6; ++m) out.steps[v][(start + m) % 6] = sign[m] * out.model.thick.loops[0].joints[m].link.length;
  }
  out.edge_heights = hinge_heights_from_steps(pattern, topology, out.steps);
  out.panel_thickness = agreed_panel_thickness(pattern.num_faces(), claims);
  return out;
}

Eigen::VectorXd diamond_arch_symmetric_state(const CreasePattern& pattern, const DiamondArchParams& params, double rho_valley) {
  const int n = params.vertices;
  // Model creases 0..5 = c0..c5 (the motion is the same turned by pi: rho0 = rho3, the diagonals alike).
  const std::vector<double> rho = diamond_zero_thickness(params.a, rho_valley);
  Eigen::VectorXd fold = Eigen::VectorXd::Zero(pattern.num_edges());
  for (int j = 0; j <= n; ++j) fold[diamond_arch_valley_edge(j)] = rho[0];
  for (int i = 1; i <= n; ++i) {
    fold[diagonal_edge(n, i, 0)] = rho[1];
    fold[diagonal_edge(n, i, 1)] = rho[2];
    fold[diagonal_edge(n, i, 2)] = rho[4];
    fold[diagonal_edge(n, i, 3)] = rho[5];
  }
  return fold;
}

}  // namespace rigidfold::generators
