#include "data/generators/hexagonal_box.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "data/generators/generator_common.hpp"

namespace rigidfold::generators {

CreasePattern hexagonal_box(const HexagonalBoxParams& params) {
  require(std::isfinite(params.side) && params.side > 0, "side", "must be > 0");
  require(std::isfinite(params.height) && params.height > 0, "height", "must be > 0");
  constexpr double kPi = std::numbers::pi;
  const double s = params.side, h = params.height;
  auto dir = [](double angle) { return Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0); };
  CreasePattern p;
  p.coords_2d = true;
  for (int i = 0; i < 6; ++i) p.vertices.push_back(s * dir(kPi / 3 * i));
  auto corner = [](int i) { return (i % 6 + 6) % 6; };
  auto wall_plus = [](int i) { return 6 + 3 * i; };      // P_i + h n_i
  auto wall_minus = [](int i) { return 6 + 3 * i + 1; }; // P_i + h n_{i-1}
  auto tip = [](int i) { return 6 + 3 * i + 2; };
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d P = p.vertices[i];
    p.vertices.push_back(P + h * dir(kPi / 3 * i + kPi / 6));
    p.vertices.push_back(P + h * dir(kPi / 3 * i - kPi / 6));
    p.vertices.push_back(P + h / std::cos(kPi / 6) * dir(kPi / 3 * i));
  }
  auto edge = [&](int a, int b, Assignment letter) {
    p.edges.push_back({a, b});
    p.assignments.push_back(letter);
  };
  for (int i = 0; i < 6; ++i) {
    edge(i, tip(i), Assignment::Valley);
    edge(i, wall_plus(i), Assignment::Mountain);
    edge(i, wall_minus(i), Assignment::Mountain);
    edge(i, corner(i + 1), Assignment::Mountain);
  }
  for (int i = 0; i < 6; ++i) {
    edge(wall_plus(i), wall_minus(corner(i + 1)), Assignment::Boundary);
    edge(wall_minus(i), tip(i), Assignment::Boundary);
    edge(tip(i), wall_plus(i), Assignment::Boundary);
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  nlohmann::ordered_json g;
  g["kind"] = "hexagonal_box";
  g["side"] = s;
  g["height"] = h;
  return finish_pattern(std::move(p), "Hexagonal box (six Myard vertices)", "five-crease vertices 30, 90, 120, 90, 30 deg", g);
}

}  // namespace rigidfold::generators
