#pragma once
// High-precision reference for the asymmetric Miura vertex, computed WITHOUT the closed form:
// rotate b and d about x by +-theta, intersect the two cones {a : a.b = cos a1} and
// {a : a.d = cos a2} on the unit sphere in the basis (b, d, b x d) (a 2x2 Gram solve and
// one square root), keep the intersection that is not +x, then take the fold angles from
// the panel normals. In 50 digits the cancellations of this route (1 - |m|^2 ~ theta^2 near
// flat) still leave > 30 correct digits, so it is a reference for double results.
// Used by tests/vertex/miura_vertex_test.cpp and benchmarks/miura_vertex_bench.cpp.
#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>

namespace rigidfold::test {

using Real50 = boost::multiprecision::cpp_bin_float_50;

template <class T>
struct MiuraReference {
  T phi, psi;                 // seed projection angles of a_hat (psi = arctan(a_y / a_x))
  std::array<T, 3> a;         // a_hat in the incoming frame
  std::array<T, 4> rho;       // fold angles of a, b, c, d (kernel convention, valley > 0)
};

template <class T>
MiuraReference<T> miura_reference(double alpha1_d, double alpha2_d, double theta_d) {
  using std::atan, std::atan2, std::cos, std::sin, std::sqrt;
  using V = std::array<T, 3>;
  const T a1 = alpha1_d, a2 = alpha2_d, th = theta_d;  // exact copies of the double inputs
  const auto dot = [](const V& u, const V& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  const auto cross = [](const V& u, const V& v) {
    return V{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  const auto unit = [&](const V& u) {
    const T n = sqrt(dot(u, u));
    return V{u[0] / n, u[1] / n, u[2] / n};
  };
  const V b{cos(a1), sin(a1) * cos(th), sin(a1) * sin(th)};
  const V c{T(-1), T(0), T(0)};
  const V d{cos(a2), -sin(a2) * cos(th), sin(a2) * sin(th)};
  // a = l b + m d + n (b x d): Gram system for l, m, then n from |a| = 1.
  const T ca1 = cos(a1), ca2 = cos(a2), gbd = dot(b, d), det = 1 - gbd * gbd;
  const T l = (ca1 - gbd * ca2) / det, m = (ca2 - gbd * ca1) / det;
  const V bxd = cross(b, d);
  const T n = sqrt((1 - (l * ca1 + m * ca2)) / dot(bxd, bxd));
  V best{};
  T best_dist = -1;
  for (int sign : {-1, 1}) {
    V cand;
    for (int i = 0; i < 3; ++i) cand[i] = l * b[i] + m * d[i] + sign * n * bxd[i];
    const V diff{cand[0] - 1, cand[1], cand[2]};
    const T dist = dot(diff, diff);
    if (dist > best_dist) {
      best_dist = dist;
      best = cand;
    }
  }
  MiuraReference<T> r;
  r.a = best;
  r.phi = atan2(best[2], best[0]);
  r.psi = atan(best[1] / best[0]);
  // Panel normals (the +z side of the sheet), sector i between crease i and i+1.
  const std::array<V, 4> creases{best, b, c, d};
  std::array<V, 4> normal;
  for (int i = 0; i < 4; ++i) normal[i] = unit(cross(creases[i], creases[(i + 1) % 4]));
  for (int i = 0; i < 4; ++i) {
    const V& before = normal[(i + 3) % 4];
    const V& after = normal[i];
    r.rho[i] = atan2(dot(creases[i], cross(before, after)), dot(before, after));
  }
  return r;
}

}  // namespace rigidfold::test
