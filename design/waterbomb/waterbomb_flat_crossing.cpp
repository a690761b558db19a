#include "design/waterbomb/waterbomb_flat_crossing.hpp"

#include <Eigen/QR>
#include <cmath>
#include <stdexcept>

#include "kernel/analysis/tolerances.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/tangent_cone.hpp"

namespace rigidfold::waterbomb {

namespace {

// First-order vertex height rate along per-edge direction d at the flat state: the plane
// z = a + b x + c y through the supports' far ends (crease 0's frame), height = -a.
// du_i/drho_j = u_j x u_i for j < i in fan order; at flat its z part is sin(phi_i - phi_j).
double height_rate(const CreasePattern& p, const Fan& fan, const std::vector<int>& supports, const Eigen::VectorXd& d) {
  const int m = static_cast<int>(supports.size());
  Eigen::MatrixXd A(m, 3);
  Eigen::VectorXd z(m);
  for (int s = 0; s < m; ++s) {
    int i = 0;
    while (fan.edges[i] != supports[s]) ++i;
    double phi_i = 0.0;
    for (int j = 0; j < i; ++j) phi_i += fan.sectors[j];
    const auto& ev = p.edges[supports[s]];
    const double L = (p.vertices[ev[0]] - p.vertices[ev[1]]).norm();
    double dz = 0.0, phi_j = 0.0;
    for (int j = 0; j < i; ++j) {
      dz += d[fan.edges[j]] * std::sin(phi_i - phi_j);
      phi_j += fan.sectors[j];
    }
    A.row(s) << 1.0, L * std::cos(phi_i), L * std::sin(phi_i);
    z[s] = L * dz;
  }
  return -A.colPivHouseholderQr().solve(z)[0];
}

}  // namespace

FlatCrossing waterbomb_flat_crossing(const CreasePattern& base, const std::vector<int>& support_edges,
                                     const std::vector<std::vector<int>>& motion_classes) {
  const Topology topo = build_topology(base);
  if (topo.stars.empty() || !topo.stars[0].interior() || topo.stars[0].fans[0].edges.size() < 6)
    throw std::invalid_argument("waterbomb_flat_crossing: vertex 0 must be the base's interior vertex with >= 6 creases");
  const Fan& fan = topo.stars[0].fans[0];
  if (support_edges.size() < 3) throw std::invalid_argument("waterbomb_flat_crossing: needs at least 3 support creases");
  auto in_fan = [&](int e) {
    for (int f : fan.edges)
      if (f == e) return true;
    return false;
  };
  for (int e : support_edges)
    if (!in_fan(e)) throw std::invalid_argument("waterbomb_flat_crossing: support crease not at the centre vertex");
  // The symmetric motion: every crease of a class moves with the class's first crease.
  std::vector<int> seen(base.num_edges(), 0);
  ClosureOptions opt;
  for (const std::vector<int>& c : motion_classes) {
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] < 0 || c[i] >= base.num_edges() || !in_fan(c[i]) || seen[c[i]]++)
        throw std::invalid_argument("waterbomb_flat_crossing: motion classes must partition the centre vertex's creases");
      if (i > 0) opt.equalities.push_back({c[i], c[0], 1.0});
    }
  }
  for (int f : fan.edges)
    if (!seen[f]) throw std::invalid_argument("waterbomb_flat_crossing: motion classes must partition the centre vertex's creases");
  const ClosureSystem sys(base, topo, opt);
  TangentConeOptions cone_opt;
  cone_opt.rank_tolerance = kDefaultTolerances.cone_rank_cut;
  const TangentCone cone = tangent_cone(sys, topo, Eigen::VectorXd::Zero(sys.num_unknowns()), cone_opt);

  FlatCrossing out;
  out.kernel_dimension = cone.kernel_dimension;
  const double threshold = kDefaultTolerances.sign_threshold;
  for (const TangentLine& line : cone.lines) {
    if (!line.isolated) continue;  // a continuum sample is no branch to choose
    ++out.cone_lines;
    for (double sign : {1.0, -1.0}) {
      FlatBranch b;
      b.direction = sys.edges_from_unknowns(sign * line.direction);
      b.direction.normalize();
      b.height_rate = height_rate(base, fan, support_edges, b.direction);
      b.far_side = b.height_rate < 0.0;
      b.keeps_letters = true;
      for (int e : fan.edges) {
        const double v = b.direction[e];
        const Assignment a = base.assignments[e];
        const bool wrong = (a == Assignment::Mountain && v > threshold) || (a == Assignment::Valley && v < -threshold);
        if (wrong && b.keeps_letters) {
          b.keeps_letters = false;
          b.first_wrong_crease = e;
        }
      }
      out.branches.push_back(b);
    }
  }
  for (std::size_t i = 0; i < out.branches.size(); ++i) {
    const FlatBranch& b = out.branches[i];
    if (!b.far_side) continue;
    ++out.far_side_branches;
    if (!b.keeps_letters) continue;
    ++out.letter_keeping;
    out.taken = static_cast<int>(i);
  }
  if (out.letter_keeping == 1) {
    out.continues = true;
  } else {
    out.taken = -1;
    out.message = out.cone_lines == 0
                      ? "the flat state's tangent cone has no isolated line (first-order kernel of dimension " +
                            std::to_string(out.kernel_dimension) +
                            "): the symmetric closure system leaves a continuum of branches, none to choose: the loaded "
                            "path stops at the flat state"
                  : out.letter_keeping == 0
                      ? "no branch of the flat state's tangent cone (" + std::to_string(out.cone_lines) + " lines, " +
                            std::to_string(out.far_side_branches) +
                            " rays below the supports) keeps the M/V letters: the loaded path stops at the flat state"
                      : std::to_string(out.letter_keeping) +
                            " branches of the flat state's tangent cone keep the M/V letters below the supports: no "
                            "unique continuation, the loaded path stops at the flat state";
  }
  return out;
}

FlatCrossing waterbomb_flat_crossing(const CreasePattern& base, const std::vector<int>& support_edges) {
  const Topology topo = build_topology(base);
  if (topo.stars.empty() || !topo.stars[0].interior() || topo.stars[0].fans[0].edges.size() % 2 != 0 ||
      topo.stars[0].fans[0].edges.size() < 6)
    throw std::invalid_argument("waterbomb_flat_crossing: vertex 0 must be the base's interior vertex with 2n >= 6 creases");
  const Fan& fan = topo.stars[0].fans[0];
  std::vector<std::vector<int>> classes(2);
  for (std::size_t k = 0; k < fan.edges.size(); ++k) classes[k % 2].push_back(fan.edges[k]);
  return waterbomb_flat_crossing(base, support_edges, classes);
}

}  // namespace rigidfold::waterbomb
