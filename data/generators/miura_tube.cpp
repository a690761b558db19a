#include "data/generators/miura_tube.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "data/generators/generator_common.hpp"
#include "data/generators/miura.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::generators {
namespace {

MiuraParams strip_params(const MiuraTubeParams& t) {
  MiuraParams m;
  m.rows = t.rows;
  m.cols = 2;
  m.alpha = t.alpha;
  m.a = t.a;
  m.b = t.b;
  return m;
}

int a_vertex(int i, int j) { return j * 3 + i; }

}  // namespace

int miura_tube_a_straight(const MiuraTubeParams&, int i, int j) { return j * 2 + i; }
int miura_tube_a_zigzag(const MiuraTubeParams& t, int i, int j) { return 2 * (t.rows + 1) + j * 3 + i; }
int miura_tube_b_straight(const MiuraTubeParams& t, int side, int j) {
  return 2 * (t.rows + 1) + 3 * t.rows + 2 * j + side;
}
int miura_tube_b_zigzag(const MiuraTubeParams& t, int j) { return 2 * (t.rows + 1) + 3 * t.rows + 2 * (t.rows + 1) + j; }

CreasePattern miura_tube(const MiuraTubeParams& params) {
  require(std::isfinite(params.fold) && params.fold > 0 && params.fold < std::numbers::pi, "fold",
          "the reference fold angle must lie strictly between 0 and 180 deg (flat or fully folded, the two strips "
          "coincide)");
  const MiuraParams mp = strip_params(params);
  const CreasePattern strip = miura_ori(mp);  // checks rows, alpha, a, b
  const Topology strip_topology = build_topology(strip, "Miura strip");
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(strip.num_edges());
  const auto angles = miura_fold_angles(strip, mp, params.fold);
  for (int e = 0; e < strip.num_edges(); ++e)
    if (angles[e]) rho[e] = *angles[e];
  const FoldedGeometry folded = place_faces(strip, strip_topology, rho, Eigen::VectorXd::Zero(strip.num_edges()));

  // The mirror plane through zig-zag lines 0 and 2.
  const int R = params.rows;
  const Eigen::Vector3d o = folded.vertices[a_vertex(0, 0)];
  const Eigen::Vector3d along = folded.vertices[a_vertex(0, 1)] - o;
  const Eigen::Vector3d across = folded.vertices[a_vertex(2, 0)] - o;
  const Eigen::Vector3d n = along.cross(across).normalized();
  const double scale = std::max(params.a, params.b);
  for (int j = 0; j <= R; ++j)
    for (int i : {0, 2})
      if (std::abs((folded.vertices[a_vertex(i, j)] - o).dot(n)) > 1e-9 * scale * (R + 1))
        throw std::logic_error("miura_tube: zig-zag lines 0 and 2 of the folded strip are not coplanar");

  CreasePattern p;
  p.vertices = folded.vertices;
  for (int j = 0; j <= R; ++j) {
    const Eigen::Vector3d q = folded.vertices[a_vertex(1, j)];
    p.vertices.push_back(q - 2 * (q - o).dot(n) * n);
  }
  auto b_vertex = [&](int j) { return 3 * (R + 1) + j; };
  p.edges = strip.edges;
  p.assignments.assign(strip.num_edges(), Assignment::Unassigned);
  for (int j = 0; j <= R; ++j) {
    const Assignment rim = (j == 0 || j == R) ? Assignment::Boundary : Assignment::Unassigned;
    p.edges.push_back({a_vertex(0, j), b_vertex(j)});
    p.edges.push_back({b_vertex(j), a_vertex(2, j)});
    p.assignments.insert(p.assignments.end(), {rim, rim});
  }
  for (int j = 0; j < R; ++j) {
    p.edges.push_back({b_vertex(j), b_vertex(j + 1)});
    p.assignments.push_back(Assignment::Unassigned);
  }
  for (int j : {0, R})
    for (int i : {0, 1}) p.assignments[miura_tube_a_straight(params, i, j)] = Assignment::Boundary;
  p.faces = strip.faces;
  for (const auto& f : strip.faces) {
    std::vector<int> g(f.rbegin(), f.rend());
    for (int& v : g)
      if (v % 3 == 1 && v < 3 * (R + 1)) v = b_vertex(v / 3);
    p.faces.push_back(g);
  }
  return finish_folded_pattern(std::move(p), "Miura tube", "Miura tube, " + std::to_string(R) + " cells",
                               {{"type", "miura_tube"},
                                {"rows", R},
                                {"alpha_deg", deg_rounded(params.alpha)},
                                {"a", params.a},
                                {"b", params.b},
                                {"fold_deg", deg_rounded(params.fold)}});
}

}  // namespace rigidfold::generators
