#include "kernel/pattern/flat_foldability.hpp"

#include <cmath>
#include <numbers>

namespace rigidfold {

std::vector<VertexFlatFoldability> flat_foldability(const CreasePattern& p, const Topology& t, double tolerance) {
  std::vector<VertexFlatFoldability> out;
  out.reserve(t.interior_vertices.size());
  for (int v : t.interior_vertices) {
    const Fan& fan = t.stars[v].fans[0];
    const int n = static_cast<int>(fan.edges.size());
    // Merge sectors across non-folding edges: start at a folding crease.
    int start = -1;
    for (int i = 0; i < n; ++i)
      if (is_foldable_crease(p.assignments[fan.edges[i]])) {
        start = i;
        break;
      }
    VertexFlatFoldability r;
    r.vertex = v;
    r.sector_sum = t.stars[v].sector_sum();
    r.developability_defect = r.sector_sum - 2 * std::numbers::pi;
    std::vector<double> merged;
    if (start >= 0) {
      double acc = 0;
      for (int k = 0; k < n; ++k) {
        const int i = (start + k) % n;
        const Assignment a = p.assignments[fan.edges[i]];
        if (k > 0 && is_foldable_crease(a)) {
          merged.push_back(acc);
          acc = 0;
        }
        if (a == Assignment::Mountain) ++r.mountains;
        if (a == Assignment::Valley) ++r.valleys;
        if (a == Assignment::Unassigned) ++r.unassigned;
        acc += fan.sectors[i];
      }
      merged.push_back(acc);
    }
    r.degree = r.mountains + r.valleys + r.unassigned;
    if (r.degree > 0 && r.degree % 2 == 0) {
      double alt = 0;
      for (int i = 0; i < r.degree; ++i) alt += (i % 2 == 0 ? 1.0 : -1.0) * merged[i];
      r.kawasaki_residual = alt;
      r.kawasaki = std::fabs(alt) <= tolerance && std::fabs(r.developability_defect) <= tolerance;
    }
    // A vertex with no folding crease is a point inside a panel: flat as long as developable.
    if (r.degree == 0) r.kawasaki = std::fabs(r.developability_defect) <= tolerance;
    if (r.unassigned == 0 && r.degree > 0) r.maekawa = std::abs(r.mountains - r.valleys) == 2;
    out.push_back(r);
  }
  return out;
}

}  // namespace rigidfold
