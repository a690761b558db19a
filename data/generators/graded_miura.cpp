#include "data/generators/graded_miura.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "data/generators/generator_common.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::generators {
namespace {

bool zigzag_is_mountain(int i) { return i % 2 == 0; }  // as miura_ori

void check(const GradedMiuraParams& p) {
  require(p.rows >= 1 && p.rows <= 2000, "rows", "must be between 1 and 2000, got " + std::to_string(p.rows));
  require(p.cols >= 1 && p.cols <= 2000, "cols", "must be between 1 and 2000, got " + std::to_string(p.cols));
  for (double t : {p.theta_min, p.theta_max})
    require(std::isfinite(t) && t > 0 && t < kPi / 2, t == p.theta_min ? "theta_min" : "theta_max",
            "line angles must lie strictly between 0 and 90 deg");
  require(std::isfinite(p.h) && p.h > 0, "h", "the row height must be positive and finite");
  require(std::isfinite(p.b) && p.b > 0, "b", "the line spacing must be positive and finite");
  const std::vector<double> th = graded_miura_line_angles(p);
  double worst = 0;
  for (std::size_t i = 0; i + 1 < th.size(); ++i)
    worst = std::max(worst, std::fabs(1 / std::tan(th[i]) - 1 / std::tan(th[i + 1])));
  require(p.b > 1.25 * p.h * worst, "b",
          "line spacing too small for the angle variation: panels would fold over (need b > " +
              std::to_string(1.25 * p.h * worst) + ")");
}

}  // namespace

std::vector<double> graded_miura_line_angles(const GradedMiuraParams& p) {
  std::vector<double> th(static_cast<std::size_t>(p.cols) + 1);
  for (int i = 0; i <= p.cols; ++i)
    th[i] = p.theta_min + (p.theta_max - p.theta_min) * (1 - std::cos(2 * kPi * i / p.cols)) / 2;
  return th;
}

CreasePattern graded_miura(const GradedMiuraParams& params) {
  check(params);
  const int ni = params.cols, nj = params.rows;
  const std::vector<double> th = graded_miura_line_angles(params);
  auto node = [&](int i, int j) { return j * (ni + 1) + i; };
  auto i_edge = [&](int i, int j) { return j * ni + i; };
  auto j_edge = [&](int i, int j) { return ni * (nj + 1) + j * (ni + 1) + i; };
  CreasePattern p;
  p.coords_2d = true;
  p.vertices.resize(static_cast<std::size_t>((ni + 1) * (nj + 1)));
  for (int j = 0; j <= nj; ++j)
    for (int i = 0; i <= ni; ++i)
      p.vertices[node(i, j)] =
          Eigen::Vector3d(i * params.b + (j % 2 == 1 ? params.h / std::tan(th[i]) : 0.0), j * params.h, 0.0);
  p.edges.resize(static_cast<std::size_t>(ni * (nj + 1) + (ni + 1) * nj));
  p.assignments.assign(p.edges.size(), Assignment::Boundary);
  for (int j = 0; j <= nj; ++j)
    for (int i = 0; i < ni; ++i) {
      p.edges[i_edge(i, j)] = {node(i, j), node(i + 1, j)};
      if (j > 0 && j < nj)
        p.assignments[i_edge(i, j)] =
            ((j % 2 == 1) == zigzag_is_mountain(i)) ? Assignment::Mountain : Assignment::Valley;
    }
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i <= ni; ++i) {
      p.edges[j_edge(i, j)] = {node(i, j), node(i, j + 1)};
      if (i > 0 && i < ni) p.assignments[j_edge(i, j)] = zigzag_is_mountain(i) ? Assignment::Mountain : Assignment::Valley;
    }
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i) p.faces.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)});

  nlohmann::ordered_json g;
  g["kind"] = "graded_miura";
  g["rows"] = nj;
  g["cols"] = ni;
  g["theta_min_deg"] = deg_rounded(params.theta_min);
  g["theta_max_deg"] = deg_rounded(params.theta_max);
  g["h"] = params.h;
  g["b"] = params.b;
  return finish_pattern(std::move(p), "Graded Miura-ori " + std::to_string(nj) + "x" + std::to_string(ni),
                        "zig-zag line angles vary across the sheet; Miura assignment; 1 DOF", g);
}

std::vector<std::optional<double>> graded_miura_fold_angles(const GradedMiuraParams& params, double rho_straight) {
  if (!(std::fabs(rho_straight) <= kPi))
    throw std::invalid_argument("graded_miura_fold_angles: rho_straight must lie in [-pi, pi]");
  const int ni = params.cols, nj = params.rows;
  const std::vector<double> th = graded_miura_line_angles(params);
  const double direction = rho_straight < 0 ? -1.0 : 1.0;
  const double straight = std::fabs(rho_straight);
  auto sign = [&](bool mountain) { return (mountain ? -1.0 : 1.0) * direction; };
  std::vector<std::optional<double>> rho(static_cast<std::size_t>(ni * (nj + 1) + (ni + 1) * nj));
  for (int j = 1; j < nj; ++j)
    for (int i = 0; i < ni; ++i) rho[j * ni + i] = sign((j % 2 == 1) == zigzag_is_mountain(i)) * straight;
  for (int i = 1; i < ni; ++i) {
    const double zigzag = 2 * std::atan(std::tan(straight / 2) / std::cos(th[i]));
    for (int j = 0; j < nj; ++j) rho[ni * (nj + 1) + j * (ni + 1) + i] = sign(zigzag_is_mountain(i)) * zigzag;
  }
  return rho;
}

}  // namespace rigidfold::generators
