#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/math/angle_units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>
#include <cstdio>
#include <span>

#include "kernel/math/so3.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {

namespace {


double wrap_angle(double x) { return std::remainder(x, 2.0 * kPi); }

void check_crease(int k) {
  if (k < 0 || k > 3) {
    throw std::invalid_argument("spherical 4R: crease index " + std::to_string(k) +
                                " is not in 0..3");
  }
}

// Sectors renamed so that crease k becomes crease 0: a[j] = alpha_{k+j}.
S4RSectors rotate_sectors(const S4RSectors& sectors, int k) {
  return {sectors[k % 4], sectors[(k + 1) % 4], sectors[(k + 2) % 4], sectors[(k + 3) % 4]};
}

}  // namespace

CosSinRoots solve_cos_sin(double A, double B, double C, double tol) {
  CosSinRoots out;
  const double h = std::hypot(A, B);
  if (h <= tol) {
    out.any = std::abs(C) <= tol;
    return out;
  }
  double q = C / h;
  if (std::abs(q) > 1.0 + tol) return out;
  q = std::clamp(q, -1.0, 1.0);
  const double mid = std::atan2(B, A);
  if (std::abs(q) >= 1.0 - tol) {
    // Double root: acos is ill-conditioned here, and the two roots are within
    // sqrt(2 tol) of each other and of mid + acos(q).
    out.count = 1;
    out.x[0] = wrap_angle(mid + std::acos(q));
    return out;
  }
  const double half = std::acos(q);
  out.count = 2;
  out.x[0] = wrap_angle(mid + half);
  out.x[1] = wrap_angle(mid - half);
  return out;
}

S4RPairCoefficients s4r_pair_coefficients(const S4RSectors& sectors, int k, double rho_k) {
  check_crease(k);
  const S4RSectors a = rotate_sectors(sectors, k);
  const double c1 = std::cos(a[0]), s1 = std::sin(a[0]);
  const double c2 = std::cos(a[1]), s2 = std::sin(a[1]);
  const double c3 = std::cos(a[2]);
  const double c4 = std::cos(a[3]), s4 = std::sin(a[3]);
  const double cr = std::cos(rho_k), sr = std::sin(rho_k);
  // Axis of crease k+1 in the frame of crease k is (c1, s1 cr, s1 sr) and the axis of
  // crease k+3 is (c4, -s4, 0); z is the cosine of the angle between them.
  const double z = c1 * c4 - s1 * s4 * cr;
  S4RPairCoefficients out;
  out.A = -s2 * (s1 * c4 + c1 * s4 * cr);
  out.B = s2 * s4 * sr;
  out.C = c3 - c2 * z;
  return out;
}

double s4r_pair_residual(const S4RSectors& sectors, int k, double rho_k, double rho_next) {
  const S4RPairCoefficients p = s4r_pair_coefficients(sectors, k, rho_k);
  return p.A * std::cos(rho_next) + p.B * std::sin(rho_next) - p.C;
}

S4RBranches s4r_branches(const S4RSectors& sectors, double rho_in, int input_crease,
                         double tol) {
  check_crease(input_crease);
  S4RBranches out;
  const S4RSectors a = rotate_sectors(sectors, input_crease);
  const double s2 = std::sin(a[1]), s3 = std::sin(a[2]);
  const double rho0 = wrap_angle(rho_in);

  const S4RPairCoefficients p = s4r_pair_coefficients(a, 0, rho0);
  const CosSinRoots roots = solve_cos_sin(p.A, p.B, p.C, tol);
  if (roots.any) {
    // Creases 1 and 3 (relative) coaxial, or sin a2 = 0: rho_1 is free.
    out.feasible = true;
    out.degenerate = true;
    return out;
  }
  if (roots.count == 0) return out;
  out.feasible = true;
  if (std::abs(s2) <= tol || std::abs(s3) <= tol) {
    // Coaxial creases: only sums of the remaining angles are determined.
    out.degenerate = true;
    return out;
  }

  // With rho_0, rho_1 known, W = Rx(rho_2) Rz(a2) Rx(rho_3) = (Rx Rz Rx Rz)^T Rz(-a3).
  // W e_x = (c2', s2' cos rho_2, s2' sin rho_2) and e_x^T W = (c2', -s2' cos rho_3,
  // s2' sin rho_3), with c2'/s2' = cos/sin a[2]; this pairs rho_2, rho_3 with the branch.
  const double sigma = s3 > 0.0 ? 1.0 : -1.0;
  for (int b = 0; b < roots.count; ++b) {
    const double rho1 = roots.x[b];
    const Eigen::Matrix3d M = rot_x(rho0) * rot_z(a[0]) * rot_x(rho1) * rot_z(a[1]);
    const Eigen::Matrix3d W = M.transpose() * rot_z(-a[3]);
    const double rho2 = std::atan2(sigma * W(2, 0), sigma * W(1, 0));
    const double rho3 = std::atan2(sigma * W(0, 2), -sigma * W(0, 1));
    const std::array<double, 4> local = {rho0, rho1, rho2, rho3};
    S4RFoldAngles rho{};
    for (int j = 0; j < 4; ++j) rho[(input_crease + j) % 4] = local[j];
    out.branches.push_back(rho);
  }
  return out;
}

namespace {

double closure_residual(const S4RSectors& sectors, const S4RFoldAngles& rho) {
  const double r = vertex_closure_residual(std::span<const double>(sectors.data(), 4), std::span<const double>(rho.data(), 4)).norm();
  return std::isfinite(r) ? r : std::numeric_limits<double>::infinity();
}

// Gauss-Newton on log R(rho) = 0 over the three free fold angles (rank-revealing least
// squares: at a motion limit the 3 x 3 Jacobian is singular). Returns the residual reached.
double refine_branch(const S4RSectors& sectors, S4RFoldAngles& rho, int input_crease) {
  double best = closure_residual(sectors, rho);
  Eigen::Vector3d r;
  Eigen::Matrix3Xd J;
  for (int it = 0; it < 30 && best > 0.1 * kS4RClosureTolerance; ++it) {
    vertex_closure_jacobian(std::span<const double>(sectors.data(), 4), std::span<const double>(rho.data(), 4), r, J);
    Eigen::Matrix3d Jf;
    for (int j = 0, c = 0; j < 4; ++j)
      if (j != input_crease) Jf.col(c++) = J.col(j);
    const Eigen::Vector3d step = Jf.completeOrthogonalDecomposition().solve(-r);
    if (!step.allFinite()) break;
    S4RFoldAngles next = rho;
    for (int j = 0, c = 0; j < 4; ++j)
      if (j != input_crease) next[j] = wrap_angle(next[j] + step[c++]);
    const double res = closure_residual(sectors, next);
    if (!(res < best)) break;
    best = res;
    rho = next;
  }
  return best;
}

}  // namespace

S4RBranches s4r_branches_checked(const S4RSectors& sectors, double rho_in, int input_crease) {
  S4RBranches out = s4r_branches(sectors, rho_in, input_crease);
  for (auto& branch : out.branches) {
    double res = closure_residual(sectors, branch);
    if (res > kS4RClosureTolerance) res = refine_branch(sectors, branch, input_crease);
    if (!(res <= kS4RClosureTolerance)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "spherical 4R with twists (%.17g, %.17g, %.17g, %.17g) rad at input %.17g rad: a branch has closure "
                    "residual %.3e rad (tolerance %.0e) even after Newton refinement",
                    sectors[0], sectors[1], sectors[2], sectors[3], rho_in, res, kS4RClosureTolerance);
      throw NoAnswerError(text, res);
    }
  }
  return out;
}

S4RInputRange s4r_input_range(const S4RSectors& sectors, int input_crease) {
  check_crease(input_crease);
  const S4RSectors a = rotate_sectors(sectors, input_crease);
  const double c1 = std::cos(a[0]), s1 = std::sin(a[0]);
  const double c2 = std::cos(a[1]), s2 = std::sin(a[1]);
  const double c3 = std::cos(a[2]), s3 = std::sin(a[2]);
  const double c4 = std::cos(a[3]), s4 = std::sin(a[3]);

  // Feasible iff (C)^2 <= A^2 + B^2, i.e. z^2 - 2 c2 c3 z + c3^2 - s2^2 <= 0 with
  // z = c1 c4 - s1 s4 cos(rho): z must lie between the roots c2 c3 -+ |s2 s3|.
  const double z_lo = c2 * c3 - std::abs(s2 * s3);
  const double z_hi = c2 * c3 + std::abs(s2 * s3);
  const double p = s1 * s4;

  S4RInputRange out;
  if (std::abs(p) < 1e-15) {
    // z does not depend on the input: all or nothing.
    const double z = c1 * c4;
    out.feasible = z >= z_lo && z <= z_hi;
    out.min_abs = 0.0;
    out.max_abs = kPi;
    return out;
  }
  // cos(rho) = (c1 c4 - z) / p, monotone in z.
  double x_lo = (c1 * c4 - z_hi) / p;
  double x_hi = (c1 * c4 - z_lo) / p;
  if (x_lo > x_hi) std::swap(x_lo, x_hi);
  x_lo = std::max(x_lo, -1.0);
  x_hi = std::min(x_hi, 1.0);
  if (x_lo > x_hi) return out;
  out.feasible = true;
  out.min_abs = std::acos(x_hi);
  out.max_abs = std::acos(x_lo);
  return out;
}

std::vector<double> S4RInputRange::limits() const {
  std::vector<double> out;
  if (!feasible) return out;
  if (max_abs < kPi) {
    out.push_back(-max_abs);
  }
  if (min_abs > 0.0) {
    out.push_back(-min_abs);
    out.push_back(min_abs);
  }
  if (max_abs < kPi) out.push_back(max_abs);
  return out;
}

std::vector<std::array<double, 2>> S4RInputRange::intervals() const {
  std::vector<std::array<double, 2>> out;
  if (!feasible) return out;
  if (min_abs <= 0.0) {
    out.push_back({-max_abs, max_abs});  // one interval through 0 (all of it if max_abs = pi)
  } else if (max_abs >= kPi) {
    out.push_back({-kPi, -min_abs});  // one arc through +-pi, split at the cut
    out.push_back({min_abs, kPi});
  } else {
    out.push_back({-max_abs, -min_abs});
    out.push_back({min_abs, max_abs});
  }
  return out;
}

bool S4RInputRange::contains(double rho) const {
  if (!feasible) return false;
  const double r = std::abs(wrap_angle(rho));
  return r >= min_abs && r <= max_abs;
}

}  // namespace rigidfold
