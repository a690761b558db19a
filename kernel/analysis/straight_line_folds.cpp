#include "kernel/analysis/straight_line_folds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernel/closure/vertex_residuals.hpp"
#include "kernel/pattern/assignment.hpp"

namespace rigidfold {
namespace {

// A hinge crease that can fold at all (F and J hinges are rigid joins; B and C are no hinges).
bool foldable(const CreasePattern& p, const Topology& t, int e) {
  const Assignment a = p.assignments[e];
  return t.edge_is_hinge[e] &&
         (a == Assignment::Mountain || a == Assignment::Valley || a == Assignment::Unassigned);
}

// opposite[v]: pairs (edge, edge across v on a straight line) at interior vertex v: the
// sectors between them sum to pi on both sides (within `tol`).
std::vector<std::vector<std::pair<int, int>>> opposite_creases(const Topology& t, int num_vertices, double tol) {
  std::vector<std::vector<std::pair<int, int>>> opp(num_vertices);
  for (int v : t.interior_vertices) {
    const Fan& f = t.stars[v].fans[0];
    const int n = static_cast<int>(f.edges.size());
    double total = 0;
    for (double s : f.sectors) total += s;
    for (int i = 0; i < n; ++i) {
      double sum = 0;
      for (int k = 0; k < n - 1; ++k) {
        sum += f.sectors[(i + k) % n];
        if (sum > std::numbers::pi + tol) break;
        if (std::abs(sum - std::numbers::pi) <= tol && std::abs(total - sum - std::numbers::pi) <= tol) {
          opp[v].emplace_back(f.edges[i], f.edges[(i + k + 1) % n]);
          break;
        }
      }
    }
  }
  return opp;
}

int across(const std::vector<std::pair<int, int>>& pairs, int e) {
  for (auto [a, b] : pairs)
    if (a == e) return b;
  return -1;
}

int other_end(const CreasePattern& p, int e, int v) {
  return p.edges[e][0] == v ? p.edges[e][1] : p.edges[e][0];
}

}  // namespace

StraightLineAnalysis straight_line_folds(const CreasePattern& p, const Topology& t, const StraightLineOptions& o) {
  StraightLineAnalysis out;
  const int ne = p.num_edges();
  const auto opp = opposite_creases(t, p.num_vertices(), o.tolerances.flat_kawasaki);
  auto lettered = [&](int e) { return assigned_fold_sign(p.assignments[e]) != 0; };

  // Strict obstruction: two straight lines crossing at a degree-4 vertex.
  for (int v : t.interior_vertices) {
    const Fan& f = t.stars[v].fans[0];
    if (f.edges.size() != 4 || opp[v].size() != 4) continue;
    if (across(opp[v], f.edges[0]) != f.edges[2] || across(opp[v], f.edges[1]) != f.edges[3]) continue;
    bool can_fold = true, all_lettered = true;
    for (int e : f.edges) {
      can_fold = can_fold && foldable(p, t, e);
      all_lettered = all_lettered && (!o.use_assignment || lettered(e));
    }
    if (!can_fold) continue;
    out.crossing_vertices.push_back(v);
    if (all_lettered) out.strict_obstruction_vertices.push_back(v);
  }

  // Boundary-to-boundary lines.
  std::vector<char> seen(ne, 0);
  std::vector<StraightLineFold> lines;
  for (int e0 = 0; e0 < ne; ++e0) {
    if (seen[e0] || !foldable(p, t, e0)) continue;
    // Walks from edge e0 through vertex `from`, appending to `chain` (edges) and `verts`;
    // returns false if the line ends at an interior vertex or meets a rigid crease.
    std::vector<int> verts_side[2];
    std::vector<int> edges_side[2];
    bool ok = true;
    for (int side = 0; side < 2 && ok; ++side) {
      int e = e0;
      int v = p.edges[e0][side];
      for (int guard = 0; guard <= ne; ++guard) {
        verts_side[side].push_back(v);
        if (!t.stars[v].interior()) break;  // reached the boundary
        const int next = across(opp[v], e);
        if (next < 0 || !foldable(p, t, next) || seen[next] || next == e0) {
          ok = false;
          break;
        }
        seen[next] = 1;
        edges_side[side].push_back(next);
        e = next;
        v = other_end(p, e, v);
      }
    }
    seen[e0] = 1;
    if (!ok) continue;
    StraightLineFold line;
    // Order: from the far end of side 0, through e0, to the far end of side 1.
    line.vertices.assign(verts_side[0].rbegin(), verts_side[0].rend());
    line.vertices.insert(line.vertices.end(), verts_side[1].begin(), verts_side[1].end());
    line.creases.assign(edges_side[0].rbegin(), edges_side[0].rend());
    line.creases.push_back(e0);
    line.creases.insert(line.creases.end(), edges_side[1].begin(), edges_side[1].end());
    ++out.lines_found;
    int sign = 0;
    bool letters_ok = true;
    if (o.use_assignment)
      for (int e : line.creases) {
        const int s = assigned_fold_sign(p.assignments[e]);
        if (s != 0 && sign != 0 && s != sign) letters_ok = false;
        if (s != 0) sign = s;
      }
    if (!letters_ok) continue;
    line.sign = sign;
    lines.push_back(std::move(line));
  }
  std::stable_sort(lines.begin(), lines.end(),
                   [](const StraightLineFold& a, const StraightLineFold& b) { return a.creases.size() > b.creases.size(); });

  // Check each motion (longest lines first) until max_reported are certified.
  int tried = 0;
  for (StraightLineFold& line : lines) {
    if (static_cast<int>(out.folds.size()) >= o.max_reported || tried >= 4 * o.max_reported) break;
    ++tried;
    const double dir = line.sign != 0 ? line.sign : 1.0;
    for (int k = 1; k <= o.samples; ++k) {
      Eigen::VectorXd rho = Eigen::VectorXd::Zero(ne);
      for (int e : line.creases) rho[e] = dir * o.tolerances.fold_limit() * k / o.samples;
      line.max_residual = std::max(line.max_residual, max_vertex_closure_residual(t, rho));
      line.path.push_back(std::move(rho));
    }
    if (line.max_residual <= o.tolerances.certificate_residual) out.folds.push_back(std::move(line));
  }
  return out;
}

}  // namespace rigidfold
