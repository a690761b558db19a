#include "data/generators/waterbomb.hpp"

#include <cmath>

#include "data/generators/generator_common.hpp"
#include "data/generators/parallelogram_lattice.hpp"
#include "kernel/math/angle_units.hpp"

namespace rigidfold::generators {

CreasePattern waterbomb_base(const WaterbombParams& params) {
  const int n = params.n;
  require(n >= 3 && n <= 180, "n", "the number of mountain (= valley) folds must be between 3 and 180, got " +
                                       std::to_string(n));
  require(std::isfinite(params.radius) && params.radius > 0, "radius", "the sheet radius must be positive");
  const Assignment corner = params.corners_mountain ? Assignment::Mountain : Assignment::Valley;
  const Assignment middle = params.corners_mountain ? Assignment::Valley : Assignment::Mountain;

  CreasePattern p;
  p.coords_2d = true;
  p.vertices.emplace_back(0.0, 0.0, 0.0);
  for (int k = 0; k < 2 * n; ++k) {
    // Even k: midpoint of an edge (distance R cos(pi/n)); odd k: a corner (distance R).
    const double angle = k * kPi / n;
    const double distance = (k % 2 == 0) ? params.radius * std::cos(kPi / n) : params.radius;
    const Eigen::Vector2d x = distance * unit_vector(angle);
    p.vertices.emplace_back(x.x(), x.y(), 0.0);
  }
  for (int k = 0; k < 2 * n; ++k) {
    p.edges.push_back({0, 1 + k});
    p.assignments.push_back(k % 2 == 0 ? middle : corner);
  }
  for (int k = 0; k < 2 * n; ++k) {
    p.edges.push_back({1 + k, 1 + (k + 1) % (2 * n)});
    p.assignments.push_back(Assignment::Boundary);
  }
  for (int k = 0; k < 2 * n; ++k) p.faces.push_back({0, 1 + k, 1 + (k + 1) % (2 * n)});

  nlohmann::ordered_json g;
  g["kind"] = "waterbomb";
  g["n"] = n;
  g["radius"] = params.radius;
  g["corners"] = params.corners_mountain ? "M" : "V";
  const std::string title = n == 4 ? "Waterbomb base (traditional, n = 4)" : "Waterbomb base, n = " + std::to_string(n);
  const std::string frame = std::string("2n = ") + std::to_string(2 * n) + " creases alternating; corner creases " +
                            (params.corners_mountain ? "M, mid-lines V" : "V, mid-lines M");
  return finish_pattern(std::move(p), title, frame, g);
}

}  // namespace rigidfold::generators
