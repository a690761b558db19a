#include "data/generators/double_corrugated.hpp"

#include <cmath>
#include <cstdio>

#include "data/generators/generator_common.hpp"
#include "data/generators/parallelogram_lattice.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::generators {
namespace {

// Lattice directions from a node.
enum Dir { PlusI, PlusJ, MinusI, MinusJ };

// 3x3-panel lattice index maps (the same as ParallelogramLattice with ni = nj = 3).
int node(int i, int j) { return j * 4 + i; }
int edge_from(int i, int j, Dir d) {
  switch (d) {
    case PlusI: return j * 3 + i;
    case MinusI: return j * 3 + (i - 1);
    case PlusJ: return 12 + j * 4 + i;
    case MinusJ: return 12 + (j - 1) * 4 + i;
  }
  return -1;
}

struct VertexSpec {
  char name;
  int i, j;
  bool type_one;
  std::array<Dir, 4> joints;  // directions of j1..j4
};

// Star shapes (see the header): "A-like" and "C-like" type I, "B-like" and "D-like" type II.
constexpr std::array<Dir, 4> kALike{PlusI, PlusJ, MinusI, MinusJ};
constexpr std::array<Dir, 4> kCLike{MinusI, MinusJ, PlusI, PlusJ};
constexpr std::array<Dir, 4> kBLike{PlusJ, MinusI, MinusJ, PlusI};
constexpr std::array<Dir, 4> kDLike{MinusJ, PlusI, PlusJ, MinusI};

std::array<VertexSpec, 4> specs(CorrugatedUnit unit) {
  if (unit == CorrugatedUnit::P)
    return {{{'A', 1, 1, true, kALike}, {'B', 1, 2, false, kBLike}, {'C', 2, 2, true, kCLike}, {'D', 2, 1, false, kDLike}}};
  return {{{'A', 2, 1, true, kALike}, {'B', 2, 2, false, kBLike}, {'E', 1, 2, true, kCLike}, {'F', 1, 1, false, kDLike}}};
}

// (vertex k, joint 1..4) of the 12 interior creases in assignment order.
std::array<std::pair<int, int>, 12> interior_joints(CorrugatedUnit unit) {
  if (unit == CorrugatedUnit::P)
    return {{{0, 2}, {1, 4}, {2, 2}, {3, 4}, {0, 3}, {0, 4}, {1, 1}, {1, 2}, {2, 3}, {2, 4}, {3, 1}, {3, 2}}};
  return {{{0, 2}, {1, 2}, {2, 2}, {3, 2}, {0, 4}, {0, 1}, {1, 4}, {1, 1}, {2, 4}, {2, 1}, {3, 4}, {3, 1}}};
}

Assignment flip(Assignment a) { return a == Assignment::Mountain ? Assignment::Valley : Assignment::Mountain; }

// Tries to build the assignment; returns false if the shared creases disagree.
bool try_assignment(CorrugatedUnit unit, const std::array<int, 4>& odd, Assignment sigma_a, std::vector<Assignment>& out) {
  const auto vs = corrugated_vertices(unit);
  // Sign of every joint given sigma per vertex; propagate sigma around the loop A->...
  // by trying both sigmas per vertex and checking all shared creases (16 combinations).
  for (int mask = 0; mask < 8; ++mask) {
    std::array<Assignment, 4> sigma{sigma_a, (mask & 1) ? Assignment::Valley : Assignment::Mountain,
                                     (mask & 2) ? Assignment::Valley : Assignment::Mountain,
                                     (mask & 4) ? Assignment::Valley : Assignment::Mountain};
    std::vector<int> edge_sign(24, -1);  // -1 unset, else Assignment cast
    bool ok = true;
    for (int k = 0; k < 4 && ok; ++k)
      for (int jt = 1; jt <= 4 && ok; ++jt) {
        const Assignment s = jt == odd[k] ? flip(sigma[k]) : sigma[k];
        const int e = vs[k].joints[jt - 1];
        if (edge_sign[e] < 0)
          edge_sign[e] = static_cast<int>(s);
        else if (edge_sign[e] != static_cast<int>(s))
          ok = false;
      }
    if (!ok) continue;
    out.clear();
    for (int e : corrugated_interior_edges(unit)) out.push_back(static_cast<Assignment>(edge_sign[e]));
    return true;
  }
  return false;
}

bool rigid_by_loop_gain(CorrugatedUnit unit, const std::array<int, 4>& odd) {
  if (unit == CorrugatedUnit::P) {
    const int ac3 = (odd[0] == 3) + (odd[2] == 3), bd4 = (odd[1] == 4) + (odd[3] == 4);
    return ac3 == bd4;
  }
  int threes = 0;
  for (int o : odd) threes += o == 3;
  return threes == 2;
}

}  // namespace

const char* to_string(CorrugatedUnit unit) { return unit == CorrugatedUnit::P ? "P" : "Q"; }

std::array<CorrugatedVertex, 4> corrugated_vertices(CorrugatedUnit unit) {
  std::array<CorrugatedVertex, 4> out;
  const auto s = specs(unit);
  for (int k = 0; k < 4; ++k) {
    out[k].name = s[k].name;
    out[k].vertex = node(s[k].i, s[k].j);
    out[k].type_one = s[k].type_one;
    for (int jt = 0; jt < 4; ++jt) out[k].joints[jt] = edge_from(s[k].i, s[k].j, s[k].joints[jt]);
  }
  return out;
}

std::array<int, 12> corrugated_interior_edges(CorrugatedUnit unit) {
  const auto vs = corrugated_vertices(unit);
  const auto ij = interior_joints(unit);
  std::array<int, 12> out{};
  for (int c = 0; c < 12; ++c) out[c] = vs[ij[c].first].joints[ij[c].second - 1];
  return out;
}

std::vector<Assignment> corrugated_assignment(CorrugatedUnit unit, const std::array<int, 4>& odd_joint,
                                              Assignment sigma) {
  for (int k = 0; k < 4; ++k)
    require(odd_joint[k] == 3 || odd_joint[k] == 4, "odd_joint",
            "the odd crease must be joint 3 or 4 (the creases bounding the smallest sector gamma)");
  require(sigma == Assignment::Mountain || sigma == Assignment::Valley, "sigma", "must be M or V");
  std::vector<Assignment> out;
  require(try_assignment(unit, odd_joint, sigma, out), "odd_joint",
          "no consistent assignment: in unit Q an even number of vertices must have their odd crease at joint 3");
  return out;
}

std::vector<CorrugatedChoice> corrugated_flat_foldable_assignments(CorrugatedUnit unit) {
  std::vector<CorrugatedChoice> out;
  for (int mask = 0; mask < 16; ++mask) {
    CorrugatedChoice c;
    for (int k = 0; k < 4; ++k) c.odd_joint[k] = (mask >> k) & 1 ? 4 : 3;
    for (Assignment sigma : {Assignment::Mountain, Assignment::Valley}) {
      std::vector<Assignment> a;
      if (!try_assignment(unit, c.odd_joint, sigma, a) || a[0] != Assignment::Mountain) continue;
      c.assignment = a;
      c.rigid = rigid_by_loop_gain(unit, c.odd_joint);
      out.push_back(c);
    }
  }
  return out;
}

std::vector<Assignment> corrugated_rigid_assignment(CorrugatedUnit unit) {
  return unit == CorrugatedUnit::P ? corrugated_assignment(unit, {4, 3, 4, 3}) : corrugated_assignment(unit, {3, 4, 3, 4});
}

CreasePattern corrugated_unit(CorrugatedUnit unit, const CorrugatedParams& params, const std::vector<Assignment>& interior) {
  const double al = params.alpha, be = params.beta;
  require(std::isfinite(al) && al > kPi / 2 && al < kPi, "alpha",
          "must lie strictly between 90 and 180 deg (gamma = 180 - alpha is the smallest sector), got " +
              std::to_string(to_degrees(al)) + " deg");
  require(std::isfinite(be) && be > kPi - al && be < al, "beta",
          "must lie strictly between 180 - alpha and alpha (gamma smallest), i.e. (" + std::to_string(180 - to_degrees(al)) +
              ", " + std::to_string(to_degrees(al)) + ") deg, got " + std::to_string(to_degrees(be)) + " deg");
  require(std::isfinite(params.a) && params.a > 0, "a", "must be positive");
  require(std::isfinite(params.b) && params.b > 0, "b", "must be positive");
  require(interior.size() == 12, "assignment",
          std::string("needs 12 letters (") +
              (unit == CorrugatedUnit::P ? "AB BC CD DA a3 a4 b1 b2 c3 c4 d1 d2" : "AB BE EF FA a4 a1 b4 b1 e4 e1 f4 f1") +
              "), got " + std::to_string(interior.size()));
  for (std::size_t k = 0; k < 12; ++k)
    require(interior[k] == Assignment::Mountain || interior[k] == Assignment::Valley ||
                interior[k] == Assignment::Flat || interior[k] == Assignment::Unassigned,
            "assignment", "letter " + std::to_string(k) + " must be M, V, F or U for an interior crease");

  const double zig = al + be + kPi;
  const Eigen::Vector2d u0 = params.a * unit_vector(0.0), u1 = params.a * unit_vector(zig);
  const Eigen::Vector2d va = params.b * unit_vector(al), vb = params.b * unit_vector(be);
  const std::vector<Eigen::Vector2d> u = unit == CorrugatedUnit::P ? std::vector<Eigen::Vector2d>{u1, u0, u1}
                                                                   : std::vector<Eigen::Vector2d>{u0, u1, u0};
  ParallelogramLattice L = parallelogram_lattice(u, {vb, va, vb});
  CreasePattern p = std::move(L.pattern);
  const auto edges = corrugated_interior_edges(unit);
  for (int c = 0; c < 12; ++c) p.assignments[edges[c]] = interior[c];

  nlohmann::ordered_json g;
  g["kind"] = unit == CorrugatedUnit::P ? "corrugated-p" : "corrugated-q";
  g["alpha_deg"] = deg_rounded(al);
  g["beta_deg"] = deg_rounded(be);
  g["gamma_deg"] = 180 - deg_rounded(al);
  g["delta_deg"] = 180 - deg_rounded(be);
  g["a"] = params.a;
  g["b"] = params.b;
  g["interior_assignment"] = assignment_letters(interior);
  g["interior_order"] = unit == CorrugatedUnit::P ? "AB BC CD DA a3 a4 b1 b2 c3 c4 d1 d2" : "AB BE EF FA a4 a1 b4 b1 e4 e1 f4 f1";
  const auto vs = corrugated_vertices(unit);
  nlohmann::ordered_json names = nlohmann::ordered_json::object();
  for (const auto& v : vs) names[std::string(1, v.name)] = v.vertex;
  g["vertices"] = names;
  char title[200];
  std::snprintf(title, sizeof title, "Double-corrugated unit %s, alpha %g deg, beta %g deg", to_string(unit), to_degrees(al),
                to_degrees(be));
  return finish_pattern(std::move(p), title, "assignment " + assignment_letters(interior) + " (seed 003 §3.2)", g);
}

}  // namespace rigidfold::generators
