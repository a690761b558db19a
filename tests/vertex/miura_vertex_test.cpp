// Asymmetric Miura vertex closed form: against a 50-digit reference computed by a different
// route (cone intersection, reference/miura_reference.hpp), against the general loop
// closure (Newton on the kernel's closure), its motion limit, and the seed's printed form.
//
// Error measure: relative, |x - ref| / |ref|, for phi, psi and the four fold angles. None of
// them crosses zero inside the domain except at theta = 0 (where all are exactly 0 and we
// require exact zeros) and psi when alpha1 == alpha2 (required to be exactly 0).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "kernel/math/so3.hpp"
#include "kernel/vertex/miura_vertex.hpp"
#include "kernel/vertex/vertex_closure.hpp"
#include "reference/miura_reference.hpp"
#include "tests/vertex/vertex_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using test::as_span;
using test::Real50;


// 400 digits for theta ~ 1e-150..1e-160, where the reference's 1 - |m|^2 ~ theta^2 would
// swallow all 50 digits of Real50.
using Real400 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<400>>;

template <class T>
double rel_error(double x, const T& ref) {
  return static_cast<double>(abs(T(x) - ref) / abs(ref));
}

// Seed 000 as printed, with the docs/DESIGN.md corrections: eq. (24) K3 = (K2/cos)^2 + (K1/sin)^2,
// eq. (39) psi = arctan(f_y / f_x), eq. (40) as printed (alpha1 <= alpha2 assumed).
struct Printed {
  double phi, psi;
};
Printed printed_form(double a1, double a2, double th) {
  const double K1 = 0.5 * (1.0 / std::tan(a1) + 1.0 / std::tan(a2));
  const double K2 = 0.5 * (1.0 / std::tan(a1) - 1.0 / std::tan(a2));
  const double K3 = std::pow(K2 / std::cos(th), 2) + std::pow(K1 / std::sin(th), 2);
  const double fx = K3 - 1.0, fy = 2.0 * K2 / std::cos(th), fz = 2.0 * K1 / std::sin(th);
  return {std::atan2(fz, fx), std::atan(fy / fx)};
}
double printed_theta_limit(double a1, double a2) {
  return kPi / 2 - 0.5 * std::acos(std::tan(a1) / std::tan(a2));
}

// Theta samples from 1e-9 rad to theta_limit - 1e-9 rad: near flat, interior, near the limit.
std::vector<double> theta_samples(double limit) {
  std::vector<double> t{1e-9, 1e-6, 1e-3};
  for (double f : {0.05, 0.25, 0.5, 0.75, 0.95, 0.999}) t.push_back(f * limit);
  t.push_back(limit - 1e-6);
  t.push_back(limit - 1e-9);
  return t;
}

struct Worst {
  double err = 0.0;
  double a1 = 0, a2 = 0, th = 0;
  void update(double e, double x1, double x2, double t) {
    if (e > err) *this = {e, x1, x2, t};
  }
};
std::ostream& operator<<(std::ostream& os, const Worst& w) {
  return os << w.err << " at alpha1 = " << to_degrees(w.a1) << " deg, alpha2 = " << to_degrees(w.a2) << " deg, theta = " << w.th
            << " rad";
}

// Compares one evaluation with the reference (expectations fail if any quantity is off by
// more than tol relative). psi is the seed's arctan(a_y / a_x): where the reference a_x is
// within 1e-8 of 0 its condition number (~ 1 / |a_x|) makes a relative bound meaningless
// (it jumps between +-pi/2 there; at alpha_min = 45 deg a_x -> 0 at the limit), so psi is
// skipped there and the direction a_hat, which is well conditioned, is checked everywhere.
template <class T = Real50>
void expect_matches_reference(double a1, double a2, double th, double tol, Worst& wphi, Worst& wpsi, Worst& wrho,
                              Worst* wdir = nullptr) {
  const MiuraVertexState st = miura_vertex(a1, a2, th);
  const auto ref = test::miura_reference<T>(a1, a2, th);
  const double ephi = rel_error(st.phi, ref.phi);
  EXPECT_LE(ephi, tol) << "phi at " << to_degrees(a1) << ", " << to_degrees(a2) << ", " << th;
  wphi.update(ephi, a1, a2, th);
  double edir = 0.0;
  for (int i = 0; i < 3; ++i) edir = std::max(edir, static_cast<double>(abs(T(st.spinal_out[i]) - ref.a[i])));
  EXPECT_LE(edir, 1e-15) << "a_hat at " << to_degrees(a1) << ", " << to_degrees(a2) << ", " << th;
  if (wdir) wdir->update(edir, a1, a2, th);
  if (a1 == a2) {
    EXPECT_EQ(st.psi, 0.0);
  } else if (abs(ref.a[0]) > T(1e-8)) {
    const double epsi = rel_error(st.psi, ref.psi);
    EXPECT_LE(epsi, tol) << "psi at " << to_degrees(a1) << ", " << to_degrees(a2) << ", " << th;
    wpsi.update(epsi, a1, a2, th);
  }
  for (int i = 0; i < 4; ++i) {
    const double e = rel_error(st.fold_angles[i], ref.rho[i]);
    EXPECT_LE(e, tol) << "fold angle " << i << " at " << to_degrees(a1) << ", " << to_degrees(a2) << ", " << th;
    wrho.update(e, a1, a2, th);
  }
}

TEST(MiuraVertex, MatchesHighPrecisionReferenceOverTheDomain) {
  Worst wphi, wpsi, wrho, wdir;
  for (int i1 = 5; i1 <= 85; i1 += 5) {
    for (int i2 = 5; i2 <= 85; i2 += 5) {
      const double a1 = to_radians(i1), a2 = to_radians(i2);
      const double limit = miura_theta_limit(a1, a2);
      for (double th : theta_samples(limit)) {
        expect_matches_reference(a1, a2, th, 1e-13, wphi, wpsi, wrho, &wdir);
        expect_matches_reference(a1, a2, -th, 1e-13, wphi, wpsi, wrho, &wdir);
      }
    }
  }
  std::cout << "[ worst ] phi " << wphi << "\n[ worst ] psi " << wpsi << "\n[ worst ] fold angles " << wrho
            << "\n[ worst ] a_hat (absolute) " << wdir << "\n";
}

TEST(MiuraVertex, MatchesReferenceInTheHardCorners) {
  Worst wphi, wpsi, wrho;
  struct Case {
    double a1, a2, th;
  };
  const double near_sym = to_radians(60) + 1e-8;
  const std::vector<Case> cases{
      {to_radians(60), to_radians(60), kPi / 2 - 1e-9},                                            // cos theta -> 0, symmetric
      {to_radians(30), to_radians(30), kPi / 2},                                                   // exactly at the symmetric limit
      {to_radians(60), near_sym, miura_theta_limit(to_radians(60), near_sym) - 1e-9},              // cos theta ~ 1e-4, q ~ 1e-8
      {to_radians(45), to_radians(45) + 1e-12, 1.2},                                               // alpha1 ~ alpha2: tiny psi
      {1e-6, to_radians(30), 0.5},                                                                 // alpha -> 0
      {to_radians(30), 1e-6, -0.5},
      {kPi / 2 - 1e-7, to_radians(85), 0.3},                                                       // alpha -> 90 deg
      {kPi / 2 - 1e-7, kPi / 2 - 2e-7, 1.0},                                                       // both -> 90 deg, phi -> pi
      {to_radians(70), to_radians(20), -1e-12},                                                    // near-flat
      {to_radians(45), to_radians(75), miura_theta_limit(to_radians(45), to_radians(75)) - 1e-3},  // a_x -> 0 at the limit
  };
  for (const auto& c : cases) expect_matches_reference(c.a1, c.a2, c.th, 1e-13, wphi, wpsi, wrho);
  // Deep near-flat: psi ~ theta^2 ~ 1e-300 is still a normal double.
  expect_matches_reference<Real400>(to_radians(20), to_radians(70), 1e-150, 1e-13, wphi, wpsi, wrho);
  std::cout << "[ worst ] phi " << wphi << "\n[ worst ] psi " << wpsi << "\n[ worst ] fold angles " << wrho << "\n";
}

TEST(MiuraVertex, FlatStateIsExactlyZero) {
  const MiuraVertexState st = miura_vertex(to_radians(30), to_radians(60), 0.0);
  EXPECT_EQ(st.phi, 0.0);
  EXPECT_EQ(st.psi, 0.0);
  for (double r : st.fold_angles) EXPECT_EQ(r, 0.0);
  EXPECT_EQ(st.spinal_out, Eigen::Vector3d::UnitX());
}

TEST(MiuraVertex, SymmetricVertexHasExactlyZeroPsi) {
  std::mt19937_64 rng(11);
  for (int k = 0; k < 2000; ++k) {
    const double a = test::uniform(rng, 1e-3, kPi / 2 - 1e-3);
    const double th = test::uniform(rng, -kPi / 2, kPi / 2);
    const MiuraVertexState st = miura_vertex(a, a, th);
    ASSERT_EQ(st.psi, 0.0) << a << " " << th;
    ASSERT_EQ(st.spinal_out.y(), 0.0);
    // Flat-foldable: both peripheral creases fold alike.
    ASSERT_EQ(st.fold_angles[kMiuraPeripheral1], st.fold_angles[kMiuraPeripheral2]);
  }
}

TEST(MiuraVertex, SignsAndSymmetries) {
  const double a1 = to_radians(35), a2 = to_radians(65), th = 0.4;
  const MiuraVertexState p = miura_vertex(a1, a2, th), m = miura_vertex(a1, a2, -th), s = miura_vertex(a2, a1, th);
  // theta > 0: c, b, d valley, a mountain; alpha1 < alpha2 tilts a towards b (+y).
  EXPECT_LT(p.fold_angles[kMiuraSpinalOut], 0.0);
  EXPECT_GT(p.fold_angles[kMiuraPeripheral1], 0.0);
  EXPECT_GT(p.fold_angles[kMiuraSpinalIn], 0.0);
  EXPECT_GT(p.fold_angles[kMiuraPeripheral2], 0.0);
  EXPECT_GT(p.phi, 0.0);
  EXPECT_GT(p.psi, 0.0);
  // Mirror z -> -z: theta -> -theta flips phi and every fold angle, keeps psi.
  EXPECT_EQ(m.phi, -p.phi);
  EXPECT_EQ(m.psi, p.psi);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(m.fold_angles[i], -p.fold_angles[i]);
  // Mirror y -> -y swaps alpha1, alpha2: same phi, opposite psi, b and d swap.
  EXPECT_NEAR(s.phi, p.phi, 1e-15);
  EXPECT_NEAR(s.psi, -p.psi, 1e-15);
  EXPECT_NEAR(s.fold_angles[kMiuraPeripheral1], p.fold_angles[kMiuraPeripheral2], 1e-15);
}

TEST(MiuraVertex, ThetaLimitAgreesWithEq40AndIsWhereAPeripheralCreaseFoldsFully) {
  for (int i1 = 5; i1 <= 85; i1 += 5) {
    for (int i2 = 5; i2 <= 85; i2 += 5) {
      const double a1 = to_radians(i1), a2 = to_radians(i2);
      const double lim = miura_theta_limit(a1, a2);
      EXPECT_EQ(lim, miura_theta_limit(a2, a1));
      if (i1 == i2) {
        EXPECT_EQ(lim, kPi / 2);
        continue;
      }
      // Eq. (40) needs the smaller alpha first (NaN otherwise, see the next test).
      EXPECT_NEAR(lim, printed_theta_limit(std::min(a1, a2), std::max(a1, a2)), 1e-14);
      // Independently: at the limit the 50-digit reference has |rho| = pi at the peripheral
      // crease next to the smaller alpha, and every |rho| < pi just inside it.
      const int full = a1 < a2 ? kMiuraPeripheral1 : kMiuraPeripheral2;
      const auto at = test::miura_reference<Real50>(a1, a2, lim);
      EXPECT_LT(static_cast<double>(test::Real50(kPi) - abs(at.rho[full])), 1e-14) << i1 << " " << i2;
      const auto inside = test::miura_reference<Real50>(a1, a2, lim * (1 - 1e-6));
      for (int i = 0; i < 4; ++i) EXPECT_LT(static_cast<double>(abs(inside.rho[i])), kPi - 1e-7);
      // The closed form reports +-pi there with the sign of theta, not a rounding flip.
      EXPECT_NEAR(miura_vertex(a1, a2, lim).fold_angles[full], kPi, 1e-13);
      EXPECT_NEAR(miura_vertex(a1, a2, -lim).fold_angles[full], -kPi, 1e-13);
    }
  }
  // Limit tends to 45 deg as the smaller alpha tends to 0.
  EXPECT_NEAR(miura_theta_limit(1e-9, to_radians(40)), kPi / 4, 1e-8);
}

TEST(MiuraVertex, RejectsBadInput) {
  const double nan = std::nan("");
  EXPECT_THROW(miura_vertex(0.0, 0.5, 0.1), std::invalid_argument);
  EXPECT_THROW(miura_vertex(0.5, kPi / 2, 0.1), std::invalid_argument);
  EXPECT_THROW(miura_vertex(-0.5, 0.5, 0.1), std::invalid_argument);
  EXPECT_THROW(miura_vertex(nan, 0.5, 0.1), std::invalid_argument);
  EXPECT_THROW(miura_vertex(0.5, 0.7, nan), std::invalid_argument);
  EXPECT_THROW(miura_vertex(0.5, 0.7, INFINITY), std::invalid_argument);
  const double lim = miura_theta_limit(to_radians(30), to_radians(60));
  EXPECT_NO_THROW(miura_vertex(to_radians(30), to_radians(60), lim));
  EXPECT_NO_THROW(miura_vertex(to_radians(30), to_radians(60), -lim));
  EXPECT_THROW(miura_vertex(to_radians(30), to_radians(60), std::nextafter(lim, 1.0)), std::invalid_argument);
  EXPECT_THROW(miura_vertex(to_radians(30), to_radians(60), -std::nextafter(lim, 1.0)), std::invalid_argument);
  EXPECT_THROW(miura_vertex_rotation(to_radians(30), to_radians(60), 1.0), std::invalid_argument);
  EXPECT_THROW(miura_theta_limit(to_radians(30), to_radians(91)), std::invalid_argument);
}

// The kernel's vertex frames for a configuration (sectors, rho) of the Miura vertex:
// F2 = frame of crease c (x along c, z normal of panel b-c); incoming frame = F2 Rx(rho_c/2)
// Rz(pi); outgoing frame = Rx(rho_a/2) (crease a is the kernel's reference frame).
struct KernelFrames {
  Eigen::Matrix3d in, out;
};
KernelFrames kernel_frames(const std::array<double, 4>& sec, const std::array<double, 4>& rho) {
  const Eigen::Matrix3d F2 = rot_x(rho[0]) * rot_z(sec[0]) * rot_x(rho[1]) * rot_z(sec[1]);
  return {F2 * rot_x(rho[2] / 2) * rot_z(kPi), rot_x(rho[0] / 2)};
}

TEST(MiuraVertex, FoldAnglesCloseTheGeneralLoop) {
  double worst = 0.0;
  for (int i1 = 5; i1 <= 85; i1 += 5) {
    for (int i2 = 5; i2 <= 85; i2 += 5) {
      const double a1 = to_radians(i1), a2 = to_radians(i2);
      for (double th : theta_samples(miura_theta_limit(a1, a2))) {
        const MiuraVertexState st = miura_vertex(a1, a2, th);
        const double r = vertex_closure_residual(as_span(st.sectors), as_span(st.fold_angles)).norm();
        EXPECT_LE(r, 1e-12) << i1 << " " << i2 << " " << th;
        worst = std::max(worst, r);
      }
    }
  }
  std::cout << "[ worst ] closure residual " << worst << " rad\n";
}

TEST(MiuraVertex, PhiPsiAndRotationAgreeWithANewtonSolveOfTheGeneralClosure) {
  std::mt19937_64 rng(5);
  double worst_angle = 0.0, worst_rot = 0.0;
  for (int k = 0; k < 300; ++k) {
    const double a1 = test::uniform(rng, to_radians(5), to_radians(85)), a2 = test::uniform(rng, to_radians(5), to_radians(85));
    const double lim = miura_theta_limit(a1, a2);
    const double th = (rng() % 2 ? 1 : -1) * test::uniform(rng, 0.05, 0.95) * lim;
    const MiuraVertexState st = miura_vertex(a1, a2, th);
    // General solver: crease c held at 2 theta, the other three from a perturbed start.
    std::array<double, 4> rho = st.fold_angles;
    for (int i : {0, 1, 3}) rho[i] += test::uniform(rng, -0.02, 0.02);
    ASSERT_GT(test::newton_degree4(st.sectors, rho, kMiuraSpinalIn), 0);
    // phi, psi from the converged loop's crease geometry: a in the incoming frame.
    const KernelFrames f = kernel_frames(st.sectors, rho);
    const Eigen::Vector3d a = f.in.transpose() * Eigen::Vector3d::UnitX();
    const double phi = std::atan2(a.z(), a.x()), psi = std::atan(a.y() / a.x());
    EXPECT_NEAR(phi, st.phi, 1e-10);
    EXPECT_NEAR(psi, st.psi, 1e-10);
    worst_angle = std::max({worst_angle, std::abs(phi - st.phi), std::abs(psi - st.psi)});
    // The frame-to-frame rotation of the header, rebuilt from the kernel's frames.
    const Eigen::Matrix3d R = miura_vertex_rotation(a1, a2, th);
    const Eigen::Matrix3d R_loop = f.in.transpose() * f.out;
    EXPECT_LE((R - R_loop).cwiseAbs().maxCoeff(), 1e-12);
    worst_rot = std::max(worst_rot, (R - R_loop).cwiseAbs().maxCoeff());
    EXPECT_LE(orthonormality_error(R), 1e-15);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
    EXPECT_LE((R.col(0) - st.spinal_out).norm(), 0.0);
    // The product form quoted in the header.
    const Eigen::Matrix3d Rd = rot_z(-a2) * rot_x(st.fold_angles[kMiuraPeripheral2]) * rot_z(a2);
    EXPECT_LE((rot_x(-th) * Rd * rot_x(-th) - R).cwiseAbs().maxCoeff(), 1e-14);
  }
  std::cout << "[ worst ] |phi, psi - Newton| " << worst_angle << " rad, |R - R_loop| " << worst_rot << "\n";
}

TEST(MiuraVertex, TwoVertexStringChainsRotations) {
  // A second vertex whose crease c is this crease a: its theta is rho_a / 2 = -theta, and the
  // crease after it, expressed in the first incoming frame, is R1 R2 e_x. Check it against
  // the direct geometry: rotate the second vertex's a_hat by R1.
  const double a1 = to_radians(40), a2 = to_radians(55), b1 = to_radians(25), b2 = to_radians(50), th = 0.35;
  const MiuraVertexState v1 = miura_vertex(a1, a2, th);
  const double th2 = v1.fold_angles[kMiuraSpinalOut] / 2;
  const MiuraVertexState v2 = miura_vertex(b1, b2, th2);
  const Eigen::Matrix3d R1 = miura_vertex_rotation(a1, a2, th), R2 = miura_vertex_rotation(b1, b2, th2);
  EXPECT_LE(((R1 * R2).col(0) - R1 * v2.spinal_out).norm(), 1e-15);
  // Panel a-b of vertex 1 is panel b-c of vertex 2: its normal agrees in both frames.
  const Eigen::Vector3d n_ab1 = v1.spinal_out.cross(v1.crease_directions[kMiuraPeripheral1]).normalized();
  const Eigen::Vector3d n_bc2 = v2.crease_directions[kMiuraPeripheral1].cross(v2.crease_directions[kMiuraSpinalIn]).normalized();
  EXPECT_LE((R1 * n_bc2 - n_ab1).norm(), 1e-14);
}

TEST(MiuraVertex, PrintedFormAgreesWhereWellConditioned) {
  double worst = 0.0;
  for (int i1 = 5; i1 <= 85; i1 += 5) {
    for (int i2 = 5; i2 <= 85; i2 += 5) {
      if (i1 == i2) continue;
      const double a1 = to_radians(i1), a2 = to_radians(i2);
      for (double th : theta_samples(miura_theta_limit(a1, a2))) {
        const MiuraVertexState st = miura_vertex(a1, a2, th);
        const Printed pr = printed_form(a1, a2, th);
        if (std::abs(st.spinal_out.x()) < 1e-3) continue;  // psi's jump at a_x = 0, both forms ill-conditioned
        const double e = std::max(std::abs(pr.phi - st.phi) / std::abs(st.phi), std::abs(pr.psi - st.psi) / std::abs(st.psi));
        EXPECT_LE(e, 1e-12) << i1 << " " << i2 << " " << th;
        worst = std::max(worst, e);
      }
    }
  }
  std::cout << "[ worst ] printed vs closed form (relative) " << worst << "\n";
}

TEST(MiuraVertex, PrintedFormLosesAccuracyWhereTheRewriteDoesNot) {
  // (1) alpha1 ~ alpha2: cot a1 - cot a2 cancels, psi keeps only ~7 digits.
  {
    const double a1 = to_radians(45), a2 = to_radians(45) + 1e-9, th = 1.0;
    const auto ref = test::miura_reference<Real50>(a1, a2, th);
    EXPECT_GT(rel_error(printed_form(a1, a2, th).psi, ref.psi), 1e-9);
    EXPECT_LE(rel_error(miura_vertex(a1, a2, th).psi, ref.psi), 1e-13);
  }
  // (2) theta = 0: the printed form divides by sin theta = 0 and returns phi = atan2(inf, inf).
  EXPECT_FALSE(printed_form(to_radians(30), to_radians(60), 0.0).phi == 0.0);
  EXPECT_EQ(miura_vertex(to_radians(30), to_radians(60), 0.0).phi, 0.0);
  // (3) very small theta: (K1 / sin theta)^2 overflows and phi comes out as 0.
  {
    const double th = 1e-160;
    const auto ref = test::miura_reference<Real400>(to_radians(30), to_radians(60), th);
    EXPECT_EQ(printed_form(to_radians(30), to_radians(60), th).phi, 0.0);
    EXPECT_LE(rel_error(miura_vertex(to_radians(30), to_radians(60), th).phi, ref.phi), 1e-13);
  }
  // (4) At theta = 1e-9 the printed form is still accurate (no cancellation: K3 >> 1), which
  // we record rather than assume.
  {
    const double th = 1e-9;
    const auto ref = test::miura_reference<Real50>(to_radians(30), to_radians(60), th);
    const Printed pr = printed_form(to_radians(30), to_radians(60), th);
    std::cout << "[ info ] printed form at theta = 1e-9: phi rel err " << rel_error(pr.phi, ref.phi) << ", psi rel err "
              << rel_error(pr.psi, ref.psi) << "\n";
  }
  // (5) Eq. (40) as printed is NaN when alpha1 > alpha2.
  EXPECT_TRUE(std::isnan(printed_theta_limit(to_radians(60), to_radians(30))));
  EXPECT_FALSE(std::isnan(miura_theta_limit(to_radians(60), to_radians(30))));
  // (6) Near alpha1 = alpha2 eq. (40) takes acos of a number close to 1 and loses digits.
  {
    const double a1 = to_radians(50), a2 = to_radians(50) + 1e-12;
    // tan^2 theta_limit = sin(a1 + a2) / sin(a2 - a1), in 50 digits.
    const Real50 A1 = a1, A2 = a2;
    const Real50 ref = atan(sqrt(sin(A1 + A2) / sin(A2 - A1)));
    EXPECT_GT(static_cast<double>(abs(Real50(printed_theta_limit(a1, a2)) - ref) / ref), 1e-12);  // observed 1.6e-11
    EXPECT_LE(static_cast<double>(abs(Real50(miura_theta_limit(a1, a2)) - ref) / ref), 1e-15);
  }
}

}}  // namespace
}  // namespace rigidfold
