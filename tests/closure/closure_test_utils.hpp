#pragma once
// Test helpers shared by tests/closure and tests/solve: small patterns built by hand and
// closed-form Miura states as unknown vectors.
#include <Eigen/Core>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "data/generators/miura.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::testing {

// One interior vertex (index 0, at the origin) with creases at the given directions
// (radians, strictly increasing in [0, 2pi)), all assigned `a`, triangular faces between
// consecutive creases and a boundary polygon through the crease ends (unit length).
inline CreasePattern single_vertex_pattern(const std::vector<double>& directions, Assignment a = Assignment::Unassigned) {
  CreasePattern p;
  const int n = static_cast<int>(directions.size());
  p.vertices.push_back(Eigen::Vector3d::Zero());
  for (double t : directions) p.vertices.emplace_back(std::cos(t), std::sin(t), 0.0);
  for (int i = 0; i < n; ++i) {
    p.edges.push_back({0, i + 1});
    p.assignments.push_back(a);
  }
  for (int i = 0; i < n; ++i) {
    p.edges.push_back({i + 1, (i + 1) % n + 1});
    p.assignments.push_back(Assignment::Boundary);
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  for (int i = 0; i < n; ++i) p.faces.push_back({0, i + 1, (i + 1) % n + 1});
  return p;
}

// The same from the sectors (radians, summing to 2 pi): crease i at the sum of sectors 0..i-1,
// creases 0..n-1 = edges 0..n-1.
inline CreasePattern single_vertex_from_sectors(const std::vector<double>& sectors, Assignment a = Assignment::Unassigned) {
  std::vector<double> directions;
  double direction = 0.0;
  for (double s : sectors) {
    directions.push_back(direction);
    direction += s;
  }
  return single_vertex_pattern(directions, a);
}

// Random crease directions with every sector in [min_sector, ...): n sorted angles.
inline std::vector<double> random_directions(int n, std::mt19937_64& rng, double min_sector = 0.3) {
  for (;;) {
    std::uniform_real_distribution<double> u(0.0, 2 * std::numbers::pi);
    std::vector<double> d(n);
    for (double& t : d) t = u(rng);
    std::sort(d.begin(), d.end());
    bool ok = true;
    for (int i = 0; i < n; ++i) {
      const double s = (i + 1 < n ? d[i + 1] : d[0] + 2 * std::numbers::pi) - d[i];
      if (s < min_sector) ok = false;
    }
    if (ok) return d;
  }
}

// Closed-form Miura state as per-edge angles (nullopt -> 0).
inline Eigen::VectorXd miura_edge_angles(const CreasePattern& p, const generators::MiuraParams& m, double straight) {
  return fold_angle_vector(generators::miura_fold_angles(p, m, straight));
}

inline Eigen::VectorXd random_vector(int n, std::mt19937_64& rng, double amplitude) {
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = u(rng);
  return v;
}

}  // namespace rigidfold::testing
