#include "kernel/thick/bennett_heights.hpp"
#include "kernel/math/angle_units.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "kernel/closure/closure_system.hpp"
#include "kernel/thick/hinge_heights.hpp"

namespace rigidfold {
namespace {


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
  std::vector<std::vector<double>> steps(flat.num_vertices());
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
    for (int i = 0; i < 4; ++i) steps[v].push_back(h[(i + 1) % 4] - h[i]);
  }
  return hinge_heights_from_steps(flat, topology, steps, 1e-12 * thickness);
}

}  // namespace rigidfold
