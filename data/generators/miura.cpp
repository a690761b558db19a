#include "data/generators/miura.hpp"

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

#include "data/generators/generator_common.hpp"
#include "data/generators/parallelogram_lattice.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::generators {
namespace {

void check(const MiuraParams& p) {
  require(p.rows >= 1 && p.rows <= 2000, "rows", "must be between 1 and 2000, got " + std::to_string(p.rows));
  require(p.cols >= 1 && p.cols <= 2000, "cols", "must be between 1 and 2000, got " + std::to_string(p.cols));
  require(std::isfinite(p.alpha) && p.alpha > 0 && p.alpha < kPi / 2, "alpha",
          "the acute panel angle must lie strictly between 0 and 90 deg, got " + std::to_string(to_degrees(p.alpha)) + " deg");
  require(std::isfinite(p.a) && p.a > 0, "a", "the zig-zag segment length must be positive and finite");
  require(std::isfinite(p.b) && p.b > 0, "b", "the straight segment length must be positive and finite");
  const double limit = 0.2 * std::min(p.a, p.b) * std::sin(p.alpha);
  require(std::isfinite(p.perturbation) && p.perturbation >= 0 && p.perturbation <= limit, "perturbation",
          "must lie in [0, 0.2 * min(a, b) * sin(alpha)] = [0, " + std::to_string(limit) + "], got " +
              std::to_string(p.perturbation));
}

// Assignment sign of zig-zag line i: true = mountain.
bool zigzag_is_mountain(int i) { return i % 2 == 0; }

// Uniform double in [0, 1) from the exactly specified mt19937_64 stream (the standard
// distributions are implementation-defined, so they are avoided for reproducibility).
double unit_uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

std::vector<MiuraCrease> miura_crease_kinds(const MiuraParams& params) {
  const int ni = params.cols, nj = params.rows;
  std::vector<MiuraCrease> kinds(static_cast<std::size_t>(ni * (nj + 1) + (ni + 1) * nj));
  for (int j = 0; j <= nj; ++j)
    for (int i = 0; i < ni; ++i) kinds[j * ni + i] = (j == 0 || j == nj) ? MiuraCrease::Boundary : MiuraCrease::Straight;
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i <= ni; ++i)
      kinds[ni * (nj + 1) + j * (ni + 1) + i] = (i == 0 || i == ni) ? MiuraCrease::Boundary : MiuraCrease::ZigZag;
  return kinds;
}

CreasePattern miura_ori(const MiuraParams& params) {
  check(params);
  const double ca = std::cos(params.alpha), sa = std::sin(params.alpha);
  std::vector<Eigen::Vector2d> u(params.cols, Eigen::Vector2d(params.b, 0.0));
  std::vector<Eigen::Vector2d> v(params.rows);
  for (int j = 0; j < params.rows; ++j) v[j] = params.a * Eigen::Vector2d(j % 2 == 0 ? ca : -ca, sa);
  ParallelogramLattice L = parallelogram_lattice(u, v);
  CreasePattern& p = L.pattern;

  for (int j = 0; j < params.rows; ++j)
    for (int i = 1; i < params.cols; ++i)
      p.assignments[L.j_edge(i, j)] = zigzag_is_mountain(i) ? Assignment::Mountain : Assignment::Valley;
  for (int j = 1; j < params.rows; ++j)
    for (int i = 0; i < params.cols; ++i) {
      const bool mountain = (j % 2 == 1) == zigzag_is_mountain(i);
      p.assignments[L.i_edge(i, j)] = mountain ? Assignment::Mountain : Assignment::Valley;
    }

  if (params.perturbation > 0) {
    std::mt19937_64 rng(params.seed);
    for (int j = 1; j < params.rows; ++j)
      for (int i = 1; i < params.cols; ++i) {
        const double dx = params.perturbation * (2 * unit_uniform(rng) - 1);
        const double dy = params.perturbation * (2 * unit_uniform(rng) - 1);
        p.vertices[L.node(i, j)] += Eigen::Vector3d(dx, dy, 0.0);
      }
    // Perturbed panels are general quads; let validation derive nothing but check them.
  }

  nlohmann::ordered_json g;
  g["kind"] = "miura";
  g["rows"] = params.rows;
  g["cols"] = params.cols;
  g["alpha_deg"] = deg_rounded(params.alpha);
  g["a"] = params.a;
  g["b"] = params.b;
  g["perturbation"] = params.perturbation;
  if (params.perturbation > 0) g["seed"] = params.seed;
  char title[160];
  std::snprintf(title, sizeof title, "Miura-ori %dx%d, alpha %g deg%s", params.rows, params.cols, to_degrees(params.alpha),
                params.perturbation > 0 ? ", perturbed" : "");
  const std::string frame = params.perturbation > 0
                                ? "interior vertices randomly perturbed (not flat-foldable); standard Miura assignment kept"
                                : "standard rigid mode assignment: zig-zag lines alternate M/V, straight creases alternate";
  return finish_pattern(std::move(p), title, frame, g);
}

double miura_zigzag_fold_angle(double alpha, double rho_straight) {
  return 2 * std::atan(std::tan(std::fabs(rho_straight) / 2) / std::cos(alpha));
}

std::vector<std::optional<double>> miura_fold_angles(const CreasePattern& pattern, const MiuraParams& params,
                                                     double rho_straight) {
  if (params.perturbation != 0)
    throw std::invalid_argument("miura_fold_angles: the closed form holds only for the unperturbed Miura-ori");
  if (!(std::fabs(rho_straight) <= kPi))
    throw std::invalid_argument("miura_fold_angles: rho_straight must lie in [-pi, pi]");
  const std::vector<MiuraCrease> kinds = miura_crease_kinds(params);
  const int ni = params.cols, nj = params.rows;
  if (pattern.num_vertices() != (ni + 1) * (nj + 1) || pattern.num_edges() != static_cast<int>(kinds.size()))
    throw std::invalid_argument("miura_fold_angles: pattern was not made by miura_ori with these parameters");
  for (int j = 0; j <= nj; ++j)
    for (int i = 0; i <= ni; ++i) {
      const int v = j * (ni + 1) + i;
      if (i < ni && pattern.edges[j * ni + i] != std::array<int, 2>{v, v + 1})
        throw std::invalid_argument("miura_fold_angles: edge order differs from miura_ori");
      if (j < nj && pattern.edges[ni * (nj + 1) + j * (ni + 1) + i] != std::array<int, 2>{v, v + ni + 1})
        throw std::invalid_argument("miura_fold_angles: edge order differs from miura_ori");
    }
  const double direction = rho_straight < 0 ? -1.0 : 1.0;
  const double straight = std::fabs(rho_straight);
  const double zigzag = miura_zigzag_fold_angle(params.alpha, straight);
  std::vector<std::optional<double>> rho(kinds.size());
  // Signs from the standard assignment rule (not from pattern.assignments, which a caller
  // may have edited): V folds positive, M negative.
  auto sign = [&](bool mountain) { return (mountain ? -1.0 : 1.0) * direction; };
  for (int j = 1; j < nj; ++j)
    for (int i = 0; i < ni; ++i) rho[j * ni + i] = sign((j % 2 == 1) == zigzag_is_mountain(i)) * straight;
  for (int j = 0; j < nj; ++j)
    for (int i = 1; i < ni; ++i) rho[ni * (nj + 1) + j * (ni + 1) + i] = sign(zigzag_is_mountain(i)) * zigzag;
  return rho;
}

}  // namespace rigidfold::generators
