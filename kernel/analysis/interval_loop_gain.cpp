#include "kernel/analysis/interval_loop_gain.hpp"

#include <algorithm>
#include <array>

#include "kernel/pattern/assignment.hpp"
#include "kernel/vertex/degree4_first_order_modes.hpp"

namespace rigidfold {

namespace {

int slot_of(const Fan& fan, int edge) {
  for (int i = 0; i < static_cast<int>(fan.edges.size()); ++i)
    if (fan.edges[i] == edge) return i;
  return -1;
}

}  // namespace

IntervalLoopGainProof interval_loop_gain_proof(const CreasePattern& pattern, const Topology& topology,
                                               const std::vector<Eigen::Vector2d>& box_lo,
                                               const std::vector<Eigen::Vector2d>& box_hi,
                                               const std::vector<int>& cycle_vertices,
                                               const std::vector<int>& cycle_creases) {
  IntervalLoopGainProof out;
  const int n = static_cast<int>(cycle_vertices.size());
  if (n < 2 || cycle_creases.size() != cycle_vertices.size()) {
    out.why_not = "not a cycle (vertices and creases do not pair up)";
    return out;
  }
  if (static_cast<int>(box_lo.size()) != pattern.num_vertices() || box_hi.size() != box_lo.size()) {
    out.why_not = "no box for every vertex";
    return out;
  }
  auto box = [&](int v, int axis) { return OutwardInterval(box_lo[v][axis], box_hi[v][axis]); };
  OutwardInterval gain(1.0);
  for (int k = 0; k < n; ++k) {
    const int v = cycle_vertices[k];
    const std::string at = "vertex " + std::to_string(v);
    if (v < 0 || v >= pattern.num_vertices() || !topology.stars[v].interior() ||
        topology.stars[v].fans[0].edges.size() != 4) {
      out.why_not = at + " is not an interior degree-4 vertex";
      return out;
    }
    const Fan& fan = topology.stars[v].fans[0];
    std::array<IntervalVector2, 4> u;
    std::array<int, 4> letter{};
    for (int i = 0; i < 4; ++i) {
      const int e = fan.edges[i];
      const int w = pattern.edges[e][0] == v ? pattern.edges[e][1] : pattern.edges[e][0];
      for (int axis = 0; axis < 2; ++axis) {
        if (!(box_lo[w][axis] <= pattern.vertices[w][axis] && pattern.vertices[w][axis] <= box_hi[w][axis])) {
          out.why_not = "the box of vertex " + std::to_string(w) + " does not hold the vertex";
          return out;
        }
        out.largest_box_half_width =
            std::max({out.largest_box_half_width, 0.5 * (box_hi[w][axis] - box_lo[w][axis]),
                      0.5 * (box_hi[v][axis] - box_lo[v][axis])});
      }
      u[i].x = box(w, 0) - box(v, 0);
      u[i].y = box(w, 1) - box(v, 1);
      letter[i] = assigned_fold_sign(pattern.assignments[e]);
      if (letter[i] == 0) {
        out.why_not = at + ": crease " + std::to_string(e) + " has no M/V letter";
        return out;
      }
    }
    const Degree4FirstOrderModes modes = degree4_first_order_modes(u);
    if (!modes.proven) {
      out.why_not = at + ": " + modes.why_not;
      return out;
    }
    // A mode is ruled out when two of its rates of proven sign disagree with their letters
    // (in either direction of the motion): those creases move at the lowest order, with
    // those signs.
    std::vector<int> allowed;
    for (int m = 0; m < 2; ++m) {
      bool plus = false, minus = false;
      for (int i = 0; i < 4; ++i) {
        const int need = modes.rates[m][i].sign() * letter[i];
        plus = plus || need > 0;
        minus = minus || need < 0;
      }
      if (!(plus && minus)) allowed.push_back(m);
    }
    if (allowed.size() != 1) {
      out.why_not = at + (allowed.empty() ? ": the letters match neither first-order mode"
                                          : ": the letters do not rule out either first-order mode");
      return out;
    }
    const int in = slot_of(fan, cycle_creases[(k + n - 1) % n]);
    const int out_slot = slot_of(fan, cycle_creases[k]);
    if (in < 0 || out_slot < 0) {
      out.why_not = at + ": a cycle crease is not one of its creases";
      return out;
    }
    // Both cycle creases must move whenever the vertex does: rates of proven sign.
    const auto& rate = modes.rates[allowed[0]];
    if (!rate[in].excludes_zero() || !rate[out_slot].excludes_zero()) {
      out.why_not = at + ": a cycle crease may stay flat to first order in the mode the letters allow";
      return out;
    }
    gain = gain * (rate[out_slot] / rate[in]);
  }
  out.gain = gain;
  if (!gain.bounded() || gain.contains(1.0)) {
    out.why_not = "the loop gain's enclosure [" + std::to_string(gain.lo) + ", " + std::to_string(gain.hi) +
                  "] holds 1";
    return out;
  }
  out.proven = true;
  return out;
}

}  // namespace rigidfold

namespace rigidfold {

bool every_hinge_has_a_locked_end(const CreasePattern& pattern, const Topology& topology,
                                  const std::vector<char>& locked) {
  for (int e = 0; e < pattern.num_edges(); ++e)
    if (topology.edge_is_hinge[e] && !locked[pattern.edges[e][0]] && !locked[pattern.edges[e][1]]) return false;
  return true;
}

FaceCycleProof face_cycle_loop_gain_proof(const CreasePattern& pattern, const Topology& topology,
                                          const std::vector<Eigen::Vector2d>& box_lo,
                                          const std::vector<Eigen::Vector2d>& box_hi) {
  FaceCycleProof out;
  std::vector<char> locked(pattern.num_vertices(), 0);
  auto degree4 = [&](int v) { return topology.stars[v].interior() && topology.stars[v].fans[0].edges.size() == 4; };
  for (int f = 0; f < pattern.num_faces(); ++f) {
    const std::vector<int>& corners = pattern.faces[f];
    const int n = static_cast<int>(corners.size());
    if (n < 3 || !std::all_of(corners.begin(), corners.end(), degree4)) continue;
    // The face's edges: the crease joining corner k and k + 1, found in corner k's fan.
    std::vector<int> creases;
    for (int k = 0; k < n; ++k) {
      const int a = corners[k], b = corners[(k + 1) % n];
      for (int e : topology.stars[a].fans[0].edges)
        if ((pattern.edges[e][0] == a && pattern.edges[e][1] == b) || (pattern.edges[e][0] == b && pattern.edges[e][1] == a)) {
          creases.push_back(e);
          break;
        }
    }
    if (static_cast<int>(creases.size()) != n) continue;
    ++out.faces_tried;
    IntervalLoopGainProof proof = interval_loop_gain_proof(pattern, topology, box_lo, box_hi, corners, creases);
    if (!proof.proven) continue;
    ++out.faces_proven;
    for (int v : corners) locked[v] = 1;
    if (!out.proven) {
      out.proven = true;
      out.face = f;
      out.cycle_vertices = corners;
      out.cycle_creases = creases;
      out.proof = std::move(proof);
    }
  }
  for (int v = 0; v < pattern.num_vertices(); ++v)
    if (locked[v]) out.locked_vertices.push_back(v);
  out.every_crease_locked = out.proven && every_hinge_has_a_locked_end(pattern, topology, locked);
  return out;
}

}  // namespace rigidfold
