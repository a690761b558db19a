#include "kernel/vertex/degree4_first_order_modes.hpp"

#include <cmath>

namespace rigidfold {

Degree4FirstOrderModes degree4_first_order_modes(const std::array<IntervalVector2, 4>& u) {
  Degree4FirstOrderModes out;
  using I = OutwardInterval;
  std::array<I, 4> length;
  for (int i = 0; i < 4; ++i) {
    length[i] = sqrt(square(u[i].x) + square(u[i].y));
    if (!length[i].excludes_zero()) {
      out.why_not = "crease " + std::to_string(i) + " may have zero length within its box";
      return out;
    }
  }
  // s[i][j] = e_i x e_j (z component of the cross product of the unit directions).
  std::array<std::array<I, 4>, 4> s;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      s[i][j] = i == j ? I(0.0) : (u[i].x * u[j].y - u[i].y * u[j].x) / (length[i] * length[j]);
  // The CCW order must hold for every vector in the boxes: consecutive creases never turn
  // into each other.
  for (int i = 0; i < 4; ++i)
    if (!s[i][(i + 1) % 4].excludes_zero()) {
      out.why_not = "creases " + std::to_string(i) + " and " + std::to_string((i + 1) % 4) +
                    " may be collinear or swap order within their boxes";
      return out;
    }
  // Eliminate the pair (p, q) farthest from collinear; the other two, a and b, are free:
  // c_a = 1, c_b = r.
  int p = -1, q = -1;
  double best = -1.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      if (s[i][j].excludes_zero() && std::min(std::abs(s[i][j].lo), std::abs(s[i][j].hi)) > best) {
        best = std::min(std::abs(s[i][j].lo), std::abs(s[i][j].hi));
        p = i, q = j;
      }
  if (p < 0) {
    out.why_not = "every pair of creases may be collinear within the boxes";
    return out;
  }
  int a = -1, b = -1;
  for (int i = 0; i < 4; ++i)
    if (i != p && i != q) (a < 0 ? a : b) = i;
  // c_p e_p + c_q e_q = -(e_a + r e_b): crossing with e_q and with e_p,
  //   c_p = -(s_aq + r s_bq) / s_pq,   c_q = (s_ap + r s_bp) / s_pq.
  // Each rate is alpha + beta r.
  std::array<I, 4> alpha, beta;
  alpha[a] = I(1.0), beta[a] = I(0.0);
  alpha[b] = I(0.0), beta[b] = I(1.0);
  alpha[p] = -(s[a][q] / s[p][q]), beta[p] = -(s[b][q] / s[p][q]);
  alpha[q] = s[a][p] / s[p][q], beta[q] = s[b][p] / s[p][q];
  // Q = sum_{i<j} s_ij c_i c_j = A r^2 + B r + C.
  I A(0.0), B(0.0), C(0.0);
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      A = A + s[i][j] * beta[i] * beta[j];
      B = B + s[i][j] * (alpha[i] * beta[j] + beta[i] * alpha[j]);
      C = C + s[i][j] * alpha[i] * alpha[j];
    }
  if (!A.excludes_zero()) {
    out.why_not = "the quadratic of the second-order closure may lose its leading term within the boxes";
    return out;
  }
  const I discriminant = square(B) - I(4.0) * A * C;
  if (!(discriminant.bounded() && discriminant.lo > 0.0)) {
    out.why_not = "the two modes may meet within the boxes (discriminant not proven positive)";
    return out;
  }
  const I root = sqrt(discriminant);
  const std::array<I, 2> r{(-B + root) / (I(2.0) * A), (-B - root) / (I(2.0) * A)};
  for (int m = 0; m < 2; ++m)
    for (int i = 0; i < 4; ++i) out.rates[m][i] = alpha[i] + beta[i] * r[m];
  out.unit_crease = a;
  out.proven = true;
  return out;
}

}  // namespace rigidfold
