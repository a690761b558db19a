#include "data/generators/stacked_metamaterial.hpp"
#include "kernel/math/angle_units.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "data/generators/generator_common.hpp"
#include "data/generators/parallelogram_lattice.hpp"

namespace rigidfold::generators {
namespace {

using V3 = Eigen::Vector3d;

// A half-turn about the unit axis n, and the reflection in the plane with unit normal m.
V3 half_turn(const V3& n, const V3& x) { return 2 * n.dot(x) * n - x; }
V3 reflect(const V3& m, const V3& x) { return x - 2 * m.dot(x) * m; }

// The four vectors of one motion of the mesh at parameter t (a dihedral, radians; t = pi is
// the flat state): the in-plane pair p0, p1 of the planar direction, the climbing vectors
// for an up / down step at an even / odd edge of the other direction.
struct Family {
  V3 p0, p1;
  V3 up_even, down_even, up_odd, down_odd;
};

// Elements 1 and 2: A2 at the origin, A2B2 = V0 along x, A2A1 = -U0 at pi - beta from it in
// the xy plane, A2A3 = U1 at alpha from it on the other side, dihedral t at A2B2 (the test's
// vector construction of element 1). V1 = half-turn of V0 about the bisector of A1A2A3 (row C
// back in the base plane, (3-24c)) or its mirror in the base plane (C', (3-25)).
Family family_j(double alpha, double beta, double t) {
  const V3 a1(-std::cos(beta), std::sin(beta), 0);
  const V3 a3(std::cos(alpha), std::sin(alpha) * std::cos(t), std::sin(alpha) * std::sin(t));
  const V3 v0 = V3::UnitX();
  V3 normal = (-a1).cross(a3).normalized();
  if (normal.dot(v0) < 0) normal = -normal;
  const V3 bis = (a1 + a3).normalized();
  const V3 rv0 = half_turn(bis, v0);
  return {-a1, a3, v0, reflect(normal, v0), reflect(normal, rv0), rv0};
}

// Element 3: B5 at the origin, B5B4 = -U0 along x, B5A5 = -V0 at beta from it, B5C5 = V1 at
// alpha from it on the other side, dihedral t at B4B5 (the test's vector construction of
// element 3). U1 = half-turn of U0 about the bisector of A5B5C5, or its mirror.
Family family_i(double alpha, double beta, double t) {
  const V3 a5(std::cos(beta), std::sin(beta), 0);
  const V3 c5(std::cos(alpha), std::sin(alpha) * std::cos(t), std::sin(alpha) * std::sin(t));
  const V3 u0 = -V3::UnitX();
  V3 normal = a5.cross(c5).normalized();
  if (normal.dot(u0) < 0) normal = -normal;
  const V3 bis = (a5 + c5).normalized();
  const V3 ru0 = half_turn(bis, u0);
  return {-a5, c5, u0, reflect(normal, u0), reflect(normal, ru0), ru0};
}

// The climbing vectors for a level sequence.
std::vector<V3> climbing(const Family& f, const std::vector<int>& levels) {
  std::vector<V3> out;
  for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
    const bool up = levels[k + 1] > levels[k];
    out.push_back(k % 2 == 0 ? (up ? f.up_even : f.down_even) : (up ? f.up_odd : f.down_odd));
  }
  return out;
}

}  // namespace

namespace {

void check_params(const StackedMetamaterialParams& params) {
  const int m = params.metamaterial;
  require(m >= 1 && m <= 4, "metamaterial", "must be 1, 2, 3 or 4");
  require(std::isfinite(params.alpha) && params.alpha > 0 && params.alpha < kPi, "alpha",
          "must lie strictly between 0 and 180 degrees");
  require(std::isfinite(params.beta) && params.beta > 0 && params.beta < kPi, "beta",
          "must lie strictly between 0 and 180 degrees");
  require(std::isfinite(params.l) && params.l > 0, "l", "must be a finite number > 0");
  // Element 3 with alpha + beta = pi does not move ((3-26): theta stays 0).
  if (m == 4)
    require(std::fabs(std::cos((params.alpha + params.beta) / 2)) > 1e-6, "beta",
            "metamaterial 4 needs alpha + beta != 180 degrees (element 3 is locked there)");
}

// Layout (levels, sizes) of a metamaterial's layer, without the pattern.
StackedLayerSheet layout(int m) {
  StackedLayerSheet s;
  s.levels_along_j = m != 4;
  switch (m) {
    case 1: s.levels = {0, 1, 0, 1, 0, 1, 0, 1, 0}; s.element = 1; s.cells_W = 2; s.cells_L = 4; break;
    case 2: s.levels = {0, 1, 2, 1, 0, 1, 2, 1, 0}; s.element = 2; s.cells_W = 2; s.cells_L = 2; break;
    case 3: s.levels = {0, 1, 2, 1, 0, 1, 0, 1, 0}; s.element = 2; s.cells_W = 2; s.cells_L = 2; break;
    default: s.levels = {0, 1, 2, 1, 0}; s.element = 3; s.cells_W = 1; s.cells_L = 4; break;
  }
  s.ni = 4;
  s.nj = 8;
  return s;
}

// The edge vectors of the analytic motion at parameter t (units of l).
void edge_vectors(const StackedMetamaterialParams& params, const StackedLayerSheet& s, double t, std::vector<V3>& U,
                  std::vector<V3>& V) {
  const Family f = s.levels_along_j ? family_j(params.alpha, params.beta, t) : family_i(params.alpha, params.beta, t);
  std::vector<V3> planar;
  const int n_planar = s.levels_along_j ? s.ni : s.nj;
  for (int k = 0; k < n_planar; ++k) planar.push_back(k % 2 == 0 ? f.p0 : f.p1);
  const std::vector<V3> climb = climbing(f, s.levels);
  U = s.levels_along_j ? planar : climb;
  V = s.levels_along_j ? climb : planar;
}

// rho per edge of the lattice: atan2((n_R x n_L) . e, n_R . n_L) with face normals
// U_i x V_j (the flat +z side); the left face of i-edge (i, j) is panel (i, j), of j-edge
// (i, j) panel (i - 1, j) (panels are counter-clockwise: v is left of u).
std::vector<double> fold_angles(const StackedLayerSheet& s, const std::vector<V3>& U, const std::vector<V3>& V,
                                bool reversed) {
  std::vector<double> rho(s.ni * (s.nj + 1) + s.nj * (s.ni + 1), 0.0);
  auto normal = [&](int i, int j) { return U[i].cross(V[j]).normalized(); };
  auto angle = [&](const V3& e, const V3& nl, const V3& nr) {
    const double r = std::atan2(nr.cross(nl).dot(e.normalized()), nr.dot(nl));
    return reversed ? -r : r;
  };
  for (int j = 1; j < s.nj; ++j)
    for (int i = 0; i < s.ni; ++i) rho[s.i_edge(i, j)] = angle(U[i], normal(i, j), normal(i, j - 1));
  for (int j = 0; j < s.nj; ++j)
    for (int i = 1; i < s.ni; ++i) rho[s.j_edge(i, j)] = angle(V[j], normal(i - 1, j), normal(i, j));
  return rho;
}

}  // namespace

std::vector<double> stacked_layer_fold_angles(const StackedMetamaterialParams& params, bool reversed, double t) {
  check_params(params);
  const StackedLayerSheet s = layout(params.metamaterial);
  std::vector<V3> U, V;
  edge_vectors(params, s, t, U, V);
  return fold_angles(s, U, V, reversed);
}

StackedLayerSheet stacked_layer_sheet(const StackedMetamaterialParams& params, bool reversed) {
  check_params(params);
  const int m = params.metamaterial;
  StackedLayerSheet s = layout(m);
  std::vector<V3> U, V;
  edge_vectors(params, s, kPi, U, V);  // flat layout
  for (V3& x : U) x *= params.l;
  for (V3& x : V) x *= params.l;
  // Rotate the flat layout so that the first i-edge runs along +x (any rotation would do).
  const double turn = -std::atan2(U[0].y(), U[0].x());
  const Eigen::Rotation2Dd rot(turn);
  std::vector<Eigen::Vector2d> u2, v2;
  for (const V3& x : U) u2.push_back(rot * x.head<2>());
  for (const V3& x : V) v2.push_back(rot * x.head<2>());
  ParallelogramLattice lat = parallelogram_lattice(u2, v2);
  CreasePattern p = std::move(lat.pattern);
  // Letters: the analytic motion's signs at a folded state (t = 2 rad).
  std::vector<V3> Uf, Vf;
  edge_vectors(params, s, 2.0, Uf, Vf);
  const std::vector<double> rho = fold_angles(s, Uf, Vf, reversed);
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] != Assignment::Boundary) p.assignments[e] = rho[e] > 0 ? Assignment::Valley : Assignment::Mountain;

  s.phi_edge = s.levels_along_j ? s.j_edge(1, 0) : s.j_edge(2, 0);
  s.theta_edge = s.levels_along_j ? -1 : s.i_edge(0, 1);
  const int top = *std::max_element(s.levels.begin(), s.levels.end());
  for (int j = 0; j <= s.nj; ++j)
    for (int i = 0; i <= s.ni; ++i)
      if (s.levels[s.levels_along_j ? j : i] == top) s.bonding_vertices.push_back(s.node(i, j));

  nlohmann::ordered_json g;
  g["kind"] = "stacked-metamaterial-layer";
  g["metamaterial"] = m;
  g["alpha_deg"] = deg_rounded(params.alpha);
  g["beta_deg"] = deg_rounded(params.beta);
  g["l"] = params.l;
  g["reversed"] = reversed;
  char title[160];
  std::snprintf(title, sizeof title, "Stacked metamaterial %d layer%s, alpha %g deg, beta %g deg", m,
                reversed ? " (reversed M-V)" : "", deg_rounded(params.alpha), deg_rounded(params.beta));
  s.pattern = finish_pattern(std::move(p), title, "layer of seed 003 Fig 3-10 (reconstruction)", g);
  return s;
}

}  // namespace rigidfold::generators
