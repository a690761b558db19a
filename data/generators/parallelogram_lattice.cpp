#include "data/generators/parallelogram_lattice.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rigidfold::generators {

Eigen::Vector2d unit_vector(double theta) { return {std::cos(theta), std::sin(theta)}; }

ParallelogramLattice parallelogram_lattice(const std::vector<Eigen::Vector2d>& u, const std::vector<Eigen::Vector2d>& v,
                                           const Eigen::Vector2d& origin) {
  ParallelogramLattice L;
  L.ni = static_cast<int>(u.size());
  L.nj = static_cast<int>(v.size());
  if (L.ni < 1 || L.nj < 1) throw std::invalid_argument("parallelogram_lattice: needs at least one panel each way");
  for (int i = 0; i < L.ni; ++i)
    for (int j = 0; j < L.nj; ++j) {
      const double cross = u[i].x() * v[j].y() - u[i].y() * v[j].x();
      if (!(cross > 0))
        throw std::invalid_argument("parallelogram_lattice: panel (" + std::to_string(i) + ", " + std::to_string(j) +
                                    ") is not counter-clockwise");
    }
  CreasePattern& p = L.pattern;
  p.coords_2d = true;
  p.vertices.resize(static_cast<std::size_t>((L.ni + 1) * (L.nj + 1)));
  Eigen::Vector2d row = origin;
  for (int j = 0; j <= L.nj; ++j) {
    Eigen::Vector2d x = row;
    for (int i = 0; i <= L.ni; ++i) {
      p.vertices[L.node(i, j)] = Eigen::Vector3d(x.x(), x.y(), 0.0);
      if (i < L.ni) x += u[i];
    }
    if (j < L.nj) row += v[j];
  }
  p.edges.resize(static_cast<std::size_t>(L.ni * (L.nj + 1) + (L.ni + 1) * L.nj));
  p.assignments.resize(p.edges.size(), Assignment::Unassigned);
  for (int j = 0; j <= L.nj; ++j)
    for (int i = 0; i < L.ni; ++i) {
      p.edges[L.i_edge(i, j)] = {L.node(i, j), L.node(i + 1, j)};
      if (j == 0 || j == L.nj) p.assignments[L.i_edge(i, j)] = Assignment::Boundary;
    }
  for (int j = 0; j < L.nj; ++j)
    for (int i = 0; i <= L.ni; ++i) {
      p.edges[L.j_edge(i, j)] = {L.node(i, j), L.node(i, j + 1)};
      if (i == 0 || i == L.ni) p.assignments[L.j_edge(i, j)] = Assignment::Boundary;
    }
  for (int j = 0; j < L.nj; ++j)
    for (int i = 0; i < L.ni; ++i)
      p.faces.push_back({L.node(i, j), L.node(i + 1, j), L.node(i + 1, j + 1), L.node(i, j + 1)});
  return L;
}

}  // namespace rigidfold::generators
