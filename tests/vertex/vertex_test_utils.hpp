#pragma once
// Helpers shared by the vertex tests: random vertices, closed configurations, wrapping,
// a Newton solve of the general closure, and the adapter to the seeds' convention.
#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include "kernel/math/angle_units.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold::test {

inline double wrap(double x) { return std::remainder(x, 2.0 * kPi); }
// Distance between two angles on the circle.
inline double angle_distance(double a, double b) { return std::abs(wrap(a - b)); }

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline std::span<const double> as_span(const std::vector<double>& v) { return {v.data(), v.size()}; }
template <std::size_t N>
std::span<const double> as_span(const std::array<double, N>& v) {
  return {v.data(), v.size()};
}

// Makes the loop close exactly by overwriting fold angles n-2, n-1 and sector n-2 with the
// x-z-x Euler angles of the rotation the loop is missing: Rx(a) Rz(b) Rx(c) = T.
inline void close_loop(std::vector<double>& sectors, std::vector<double>& folds) {
  const std::size_t n = sectors.size();
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i + 2 < n; ++i) P = P * rot_x(folds[i]) * rot_z(sectors[i]);
  const Eigen::Matrix3d T = P.transpose() * rot_z(-sectors[n - 1]);
  // T e_x = (cos b, sin b cos a, sin b sin a); e_x^T T = (cos b, -sin b cos c, sin b sin c).
  folds[n - 2] = std::atan2(T(2, 0), T(1, 0));
  sectors[n - 2] = std::atan2(std::hypot(T(1, 0), T(2, 0)), T(0, 0));
  folds[n - 1] = std::atan2(T(0, 2), -T(0, 1));
}

// Newton (square Gauss-Newton) on the general closure with rho[fixed] held: solves the three
// closure equations for the other three fold angles of a degree-4 vertex. Returns the number
// of iterations, or -1 if it did not converge.
inline int newton_degree4(const std::array<double, 4>& sectors, std::array<double, 4>& rho,
                          int fixed = 0) {
  Eigen::Vector3d r;
  Eigen::Matrix3Xd J;
  for (int it = 0; it < 60; ++it) {
    vertex_closure_jacobian(as_span(sectors), as_span(rho), r, J);
    Eigen::Matrix3d Jr;
    int col = 0;
    for (int j = 0; j < 4; ++j) {
      if (j != fixed) Jr.col(col++) = J.col(j);
    }
    const Eigen::Vector3d step = Jr.fullPivLu().solve(-r);
    col = 0;
    for (int j = 0; j < 4; ++j) {
      if (j != fixed) rho[j] += step(col++);
    }
    if (step.norm() < 1e-15) return it + 1;
  }
  vertex_closure_jacobian(as_span(sectors), as_span(rho), r, J);
  return r.norm() < 1e-14 ? 60 : -1;
}

// Adapter to seeds 001/003: theta (DH joint angle, mountain > 0) = -rho, twists and
// numbering unchanged (seed index i+1 = kernel index i).
inline std::array<double, 4> seed_theta_from_rho(const std::array<double, 4>& rho) {
  return {-rho[0], -rho[1], -rho[2], -rho[3]};
}
inline double rho_from_seed_theta(double theta) { return -theta; }

}  // namespace rigidfold::test
