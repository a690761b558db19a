// SORCE (seed 002 section 13) axodes of general 3D relative motion: planar folds reduce to
// their centrodes (eqs 56/57, the circle oracle), a cone rolling on a plane against its
// closed form, a general zero-pitch motion (residuals of eqs 71/72, s' against finite
// differences, the i/j swap of eq 85), the digest's counter-example to eq 82 (pitch against
// an independent twist, q vs M q), and the degenerate kinds and bad input.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "design/sorce/sorce_axode.hpp"
#include "design/sorce/sorce_profile.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/math/so3.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using Eigen::Matrix3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;

std::vector<double> grid(double a, double b, int n) {
  std::vector<double> t;
  for (int k = 0; k <= n; ++k) t.push_back(a + (b - a) * k / n);
  return t;
}

// A rotation with its first two derivatives in t.
struct RotJet {
  Matrix3d R = Matrix3d::Identity(), dR = Matrix3d::Zero(), ddR = Matrix3d::Zero();
};
// exp(a K) with a(t): R' = a' K R, R'' = (a'' K + a'^2 K^2) R.
RotJet about(const Vector3d& axis, double a, double da, double dda) {
  const Matrix3d K = skew(axis), R = rotation_about(axis, a);
  return {R, da * K * R, (dda * K + da * da * K * K) * R};
}
RotJet fixed(const Matrix3d& R) { return {R, Matrix3d::Zero(), Matrix3d::Zero()}; }
RotJet operator*(const RotJet& A, const RotJet& B) {
  return {A.R * B.R, A.dR * B.R + A.R * B.dR, A.ddR * B.R + 2.0 * A.dR * B.dR + A.R * B.ddR};
}
SpatialPose pose(const RotJet& R, const Vector3d& r, const Vector3d& dr, const Vector3d& ddr) {
  SpatialPose p;
  p.R = R.R;
  p.dR = R.dR;
  p.ddR = R.ddR;
  p.r = r;
  p.dr = dr;
  p.ddr = ddr;
  p.second_derivatives = true;
  return p;
}
// G after P: p -> G.R (P.R p + P.r) + G.r.
SpatialPose compose(const SpatialPose& G, const SpatialPose& P) {
  const RotJet R = RotJet{G.R, G.dR, G.ddR} * RotJet{P.R, P.dR, P.ddR};
  return pose(R, G.R * P.r + G.r, G.dR * P.r + G.R * P.dr + G.dr,
              G.ddR * P.r + 2.0 * G.dR * P.dr + G.R * P.ddr + G.ddr);
}

// Figures for the test log (std::to_string would print 1e-15 as 0.000000).
std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

// Distance between unit directions up to sign.
double direction_gap(const Vector3d& a, const Vector3d& b) { return std::min((a - b).norm(), (a + b).norm()); }

// Central differences of s_ij, s_ji (test-only check of the closed-form s').
struct Differences {
  Vector3d ds_ij, ds_ji, dq_ij;
};
Differences differences(const PoseFunction& i, const PoseFunction& j, double t, const Vector3d& seed, double h) {
  const AxodePoint a = axode_point(i(t - h), j(t - h), seed), b = axode_point(i(t + h), j(t + h), seed);
  return {(b.s_ij - a.s_ij) / (2 * h), (b.s_ji - a.s_ji) / (2 * h), (b.q_ij - a.q_ij) / (2 * h)};
}

// ---- 1. planar folds embedded in 3D -------------------------------------------------------

TEST(SorceAxode, PlanarFoldsReduceToTheirCentrodes) {
  std::vector<FoldMotion> folds;
  for (const FoldMotion& f : testing::vertex_a_linear(1.0).folds) folds.push_back(f);
  for (const FoldMotion& f : testing::vertex_b_split(2).folds) folds.push_back(f);  // split folds: d != 0
  double worst_s = 0.0, worst_ds = 0.0, worst_q = 0.0, worst_pitch = 0.0;
  for (const FoldMotion& f : folds) {
    for (double t : grid(0.0, 1.0, 40)) {
      const ProfilePoint pp = profile_point(f, t);
      const SpatialPosePair poses = fold_spatial_poses(f, t);
      const AxodePoint a = axode_point(poses.left, poses.right);
      ASSERT_EQ(a.kind, AxodeKind::kWellBehaved) << "t = " << t << " pitch " << a.pitch;
      worst_s = std::max(worst_s, (a.s_ij - Vector3d(pp.s_left.x(), pp.s_left.y(), 0.0)).norm());
      worst_s = std::max(worst_s, (a.s_ji - Vector3d(pp.s_right.x(), pp.s_right.y(), 0.0)).norm());
      worst_ds = std::max(worst_ds, (a.ds_ij - Vector3d(pp.ds_left.x(), pp.ds_left.y(), 0.0)).norm());
      worst_ds = std::max(worst_ds, (a.ds_ji - Vector3d(pp.ds_right.x(), pp.ds_right.y(), 0.0)).norm());
      worst_q = std::max({worst_q, direction_gap(a.q_ij, Vector3d::UnitZ()), direction_gap(a.q_ji, Vector3d::UnitZ())});
      worst_pitch = std::max(worst_pitch, std::abs(a.pitch));
      // The default seed is omega_i: left relative to right turns by -gamma about z.
      EXPECT_GT(a.q_ij.dot(-pp.dgamma * Vector3d::UnitZ()), 0.0);
    }
  }
  RecordProperty("worst_s", sci(worst_s));
  RecordProperty("worst_ds", sci(worst_ds));
  RecordProperty("worst_q", sci(worst_q));
  RecordProperty("worst_pitch", sci(worst_pitch));
  EXPECT_LE(worst_s, 1e-12);
  EXPECT_LE(worst_ds, 1e-11);
  EXPECT_LE(worst_q, 1e-15);
  EXPECT_LE(worst_pitch, 1e-14);
}

TEST(SorceAxode, CircleOracle) {
  // CORE joint: gamma = pi t, z = -r tan(gamma / 4); profiles are circles of radius r at (-+r, 0).
  const double r = 0.35;
  const ScalarFunction gamma = linear_fold(kPi);
  const FoldMotion f{gamma, circular_offset(r, gamma), circular_offset(r, gamma), {}};
  for (double t : grid(0.0, 1.0, 50)) {
    const SpatialPosePair p = fold_spatial_poses(f, t);
    const AxodePoint a = axode_point(p.left, p.right);
    ASSERT_EQ(a.kind, AxodeKind::kWellBehaved);
    EXPECT_NEAR((a.s_ij - Vector3d(-r, 0.0, 0.0)).norm(), r, 1e-12) << t;
    EXPECT_NEAR((a.s_ji - Vector3d(r, 0.0, 0.0)).norm(), r, 1e-12) << t;
    EXPECT_LE(std::abs(a.s_ij.z()) + std::abs(a.s_ji.z()), 1e-15);
    EXPECT_LE(direction_gap(a.q_ij, Vector3d::UnitZ()), 1e-15);
    const AxodeResidual res = axode_residual(p.left, p.right, a, {-2.0, 0.0, 3.0});
    EXPECT_LE(res.contact, 1e-14);
    EXPECT_LE(res.rolling, 1e-14);
  }
}

// ---- 2. general spatial motions with zero pitch --------------------------------------------

// A cone (half-angle beta, apex at body point c) rolling on the plane z = 0 of the world,
// its contact line through the world point a0 in direction u(phi): R_i = Rz(phi) Ry(pi/2 -
// beta) Rz(psi), psi = -phi / sin(beta) (the angular velocity phi' e_z + psi' axis then lies
// along u). Body j carries the plane at a fixed pose.
struct Cone {
  double beta = 0.5;
  Vector3d c{0.2, -0.1, 0.4}, a0{0.3, 0.2, 0.0};
  Matrix3d Rj = rot_x(0.4) * rot_z(0.2);
  Vector3d rj{-0.5, 0.1, 0.3};
  double phi(double t) const { return 2 * t + 0.3 * std::sin(t); }
  SpatialPose body(double t) const {
    const double p = phi(t), dp = 2 + 0.3 * std::cos(t), ddp = -0.3 * std::sin(t), k = -1 / std::sin(beta);
    const RotJet R = about(Vector3d::UnitZ(), p, dp, ddp) * fixed(rotation_about(Vector3d::UnitY(), kPi / 2 - beta)) *
                     about(Vector3d::UnitZ(), k * p, k * dp, k * ddp);
    return pose(R, a0 - R.R * c, -R.dR * c, -R.ddR * c);
  }
  SpatialPose plane() const { return pose(fixed(Rj), rj, Vector3d::Zero(), Vector3d::Zero()); }
};

TEST(SorceAxode, ConeRollingOnAPlaneMatchesItsClosedForm) {
  const Cone cone;
  const PoseFunction i = [&](double t) { return cone.body(t); }, j = [&](double) { return cone.plane(); };
  const std::vector<double> ts = grid(0.0, 2.0, 40);
  const std::vector<AxodePoint> pts = sample_axodes(i, j, ts);
  double worst = 0.0;
  for (const AxodePoint& a : pts) {
    ASSERT_EQ(a.kind, AxodeKind::kWellBehaved) << a.t;
    const double p = cone.phi(a.t), dp = 2 + 0.3 * std::cos(a.t), psi = -p / std::sin(cone.beta);
    const Vector3d u(std::cos(p), std::sin(p), 0.0);
    // Body i: the cone's generator at azimuth -psi; the base point is the foot of that line.
    const Vector3d q = rot_z(-psi) * Vector3d(std::sin(cone.beta), 0.0, std::cos(cone.beta));
    const Vector3d s = cone.c - cone.c.dot(q) * q;
    worst = std::max({worst, direction_gap(a.q_ij, q), (a.s_ij - s).norm()});
    // Body j: the contact line of the plane, R_j^T (a0 + lambda u - r_j).
    const Vector3d qj = cone.Rj.transpose() * u, foot = cone.Rj.transpose() * (cone.a0 - cone.rj);
    const Vector3d off = a.s_ji - foot;
    worst = std::max({worst, direction_gap(a.q_ji, qj), (off - off.dot(qj) * qj).norm()});
    // omega: rolling about the contact line, -phi' cot(beta) u (world = plane frame rotated).
    worst = std::max(worst, (a.omega_j - cone.Rj.transpose() * (-dp / std::tan(cone.beta) * u)).norm());
    EXPECT_LE(std::abs(a.pitch), 1e-13);
  }
  RecordProperty("cone_closed_form", sci(worst));
  EXPECT_LE(worst, 1e-12);
  // s', q' against central differences (|omega| varies here, unlike the test below).
  double worst_fd = 0.0;
  for (const AxodePoint& a : pts) {
    const Differences d = differences(i, j, a.t, a.q_ij, 1e-5);
    worst_fd = std::max({worst_fd, (a.ds_ij - d.ds_ij).norm(), (a.ds_ji - d.ds_ji).norm(), (a.dq_ij - d.dq_ij).norm()});
  }
  RecordProperty("cone_derivative_vs_fd", sci(worst_fd));
  EXPECT_LE(worst_fd, 1e-8);
  // q keeps its sign along the samples (chained eq 84 seeds).
  for (std::size_t k = 1; k < pts.size(); ++k) EXPECT_GT(pts[k].q_ij.dot(pts[k - 1].q_ij), 0.9);
  const AxodeResidual res = sampled_axode_residual(i, j, pts, {-1.0, 0.0, 0.5, 2.0});
  RecordProperty("cone_contact", sci(res.contact));
  RecordProperty("cone_rolling", sci(res.rolling));
  EXPECT_LE(res.contact, 1e-10);
  EXPECT_LE(res.rolling, 1e-10);
  EXPECT_GE(res.rolling, 0.0);
}

// Body j turns as Rz(t) Rx(0.7 t) and sits at R_j w(t) in i's frame, with w' orthogonal to
// its body angular velocity (0.7, sin 0.7t, cos 0.7t): zero pitch. Both bodies then ride a
// common motion G(t), which leaves the relative motion unchanged.
struct SpinningPair {
  double b = 0.8;
  Vector3d w0{0.3, -0.2, 0.5};
  SpatialPose common(double t) const {
    return pose(about(Vector3d(1, 2, 2).normalized(), 0.5 * t * t, t, 1.0), Vector3d(t, t * t, 0.3),
                Vector3d(1.0, 2 * t, 0.0), Vector3d(0.0, 2.0, 0.0));
  }
  SpatialPose i(double t) const { return common(t); }
  SpatialPose j(double t) const {
    const double a = 0.7 * t, s = std::sin(a), c = std::cos(a);
    const RotJet R = about(Vector3d::UnitZ(), t, 1.0, 0.0) * about(Vector3d::UnitX(), a, 0.7, 0.0);
    const Vector3d w = w0 + Vector3d(-b * s / 0.7, s / 0.7, (c - 1) / 0.7 + 0.7 * b * t);
    const Vector3d dw(-b * c, c, -s + 0.7 * b), ddw(0.7 * b * s, -0.7 * s, -0.7 * c);
    return compose(common(t), pose(R, R.R * w, R.dR * w + R.R * dw, R.ddR * w + 2.0 * R.dR * dw + R.R * ddw));
  }
};

TEST(SorceAxode, GeneralZeroPitchMotionRolls) {
  const SpinningPair m;
  const PoseFunction i = [&](double t) { return m.i(t); }, j = [&](double t) { return m.j(t); };
  const std::vector<AxodePoint> pts = sample_axodes(i, j, grid(-1.0, 2.0, 60));
  for (const AxodePoint& a : pts) {
    ASSERT_EQ(a.kind, AxodeKind::kWellBehaved) << a.t << " pitch " << a.pitch;
    EXPECT_LE(std::abs(a.pitch), 1e-13);
    // pinv(M') m' solves eq 79 and is the axis point nearest i's origin.
    EXPECT_LE((a.dM * a.s_ij - a.dm).norm(), 1e-13);
    EXPECT_LE(std::abs(a.s_ij.dot(a.q_ij)), 1e-13);
    EXPECT_LE((a.dM * a.q_ij).norm(), 1e-14);
  }
  const AxodeResidual res = sampled_axode_residual(i, j, pts, {-2.0, 0.0, 1.5});
  RecordProperty("general_contact", sci(res.contact));
  RecordProperty("general_rolling", sci(res.rolling));
  EXPECT_LE(res.contact, 1e-10);
  EXPECT_LE(res.rolling, 1e-10);

  // s', q' against central differences (h = 1e-5: truncation ~1e-10 x the third derivative),
  // and the rolling residual of eq 72 with the differenced derivatives in their place.
  double worst = 0.0, worst_fd_rolling = 0.0;
  for (const AxodePoint& a : pts) {
    const Differences d = differences(i, j, a.t, a.q_ij, 1e-5);
    worst = std::max({worst, (a.ds_ij - d.ds_ij).norm(), (a.ds_ji - d.ds_ji).norm(), (a.dq_ij - d.dq_ij).norm()});
    AxodePoint fd = a;
    fd.ds_ij = d.ds_ij;
    fd.ds_ji = d.ds_ji;
    fd.dq_ij = d.dq_ij;
    fd.dq_ji = a.M * d.dq_ij + a.dM * a.q_ij;
    worst_fd_rolling = std::max(worst_fd_rolling, axode_residual(m.i(a.t), m.j(a.t), fd, {-2.0, 0.0, 1.5}).rolling);
  }
  RecordProperty("derivative_vs_fd", sci(worst));
  RecordProperty("fd_rolling", sci(worst_fd_rolling));
  EXPECT_LE(worst, 1e-8);
  EXPECT_LE(worst_fd_rolling, 1e-7);

  // eq 85: the same construction with i and j swapped gives the same line in body j.
  for (const AxodePoint& a : pts) {
    const AxodePoint b = axode_point(m.j(a.t), m.i(a.t));
    const Vector3d off = b.s_ij - a.s_ji;
    EXPECT_LE((off - off.dot(a.q_ji) * a.q_ji).norm(), 1e-12);
    EXPECT_LE(direction_gap(b.q_ij, a.q_ji), 1e-13);
    EXPECT_NEAR(b.pitch, a.pitch, 1e-13);
  }
}

// ---- 3. the digest's counter-example to eq 82 ----------------------------------------------

// Body i fixed at the identity; body j turns as Rz(t) Rx(0.7 t) and sits at R_j w(t), so
// m = w. The pitch from the relative twist T_rel^{-1} T_rel', T_rel = T_j^{-1} T_i,
// independently of axode_point.
double twist_pitch(const SpatialPose& i, const SpatialPose& j) {
  const auto homogeneous = [](const Matrix3d& R, const Vector3d& r, double w) {
    Matrix4d T = Matrix4d::Zero();
    T.topLeftCorner<3, 3>() = R;
    T.topRightCorner<3, 1>() = r;
    T(3, 3) = w;
    return T;
  };
  const Matrix4d Ti = homogeneous(i.R, i.r, 1.0), dTi = homogeneous(i.dR, i.dr, 0.0);
  const Matrix4d Tj = homogeneous(j.R, j.r, 1.0), dTj = homogeneous(j.dR, j.dr, 0.0);
  const Matrix4d Tjinv = Tj.inverse();
  const Matrix4d T = Tjinv * Ti, dT = -Tjinv * dTj * Tjinv * Ti + Tjinv * dTi;
  const Matrix4d twist = T.inverse() * dT;
  const Vector3d omega(twist(2, 1), twist(0, 2), twist(1, 0)), v = twist.topRightCorner<3, 1>();
  return omega.dot(v) / omega.squaredNorm();
}

SpatialPose counter_j(double t, const Vector3d& w, const Vector3d& dw) {
  const RotJet R = about(Vector3d::UnitZ(), t, 1.0, 0.0) * about(Vector3d::UnitX(), 0.7 * t, 0.7, 0.0);
  return pose(R, R.R * w, R.dR * w + R.R * dw, R.ddR * w + 2.0 * R.dR * dw);
}

TEST(SorceAxode, CounterExampleToThePapersCondition) {
  const double t = 0.6;
  const SpatialPose i = pose(fixed(Matrix3d::Identity()), Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero());
  // Translation w = (0.5 t, 0.1, 0): w' along x, which has a component along the axis.
  const SpatialPose j = counter_j(t, Vector3d(0.5 * t, 0.1, 0.0), Vector3d(0.5, 0.0, 0.0));
  const AxodePoint a = axode_point(i, j);
  const double expected = twist_pitch(i, j);
  RecordProperty("pitch", sci(a.pitch));
  RecordProperty("pitch_vs_twist", sci(std::abs(a.pitch - expected)));
  EXPECT_EQ(a.kind, AxodeKind::kNonZeroPitch);
  EXPECT_GT(std::abs(expected), 0.1);
  EXPECT_NEAR(a.pitch, expected, 1e-14);
  // The velocity on the axis is the pitch times omega (the least-squares point of eq 83).
  EXPECT_NEAR((a.dM * a.s_ij - a.dm).norm(), std::abs(a.pitch) * a.omega_j.norm(), 1e-13);
  const AxodeResidual res = axode_residual(i, j, a, {0.0, 1.0});
  EXPECT_LE(res.contact, 1e-14);
  EXPECT_NEAR(res.rolling, std::abs(a.pitch) * a.omega_j.norm(), 1e-13);  // sliding along the axis

  // q (body i: the spatial angular velocity of j, up to sign, (0.7 cos t, 0.7 sin t, 1)) and
  // M q (body j's own, (0.7, sin 0.7t, cos 0.7t)) are ~7.1 degrees apart.
  const Vector3d ws(0.7 * std::cos(t), 0.7 * std::sin(t), 1.0), wb(0.7, std::sin(0.7 * t), std::cos(0.7 * t));
  const double angle = std::acos(std::clamp(a.q_ij.dot(a.q_ji), -1.0, 1.0));
  RecordProperty("q_Mq_degrees", sci(to_degrees(angle)));
  EXPECT_NEAR(angle, std::acos(ws.normalized().dot(wb.normalized())), 1e-9);
  EXPECT_NEAR(to_degrees(angle), 7.1, 0.05);
  EXPECT_LE(direction_gap(a.q_ij, ws.normalized()), 1e-14);
  EXPECT_LE(direction_gap(a.q_ji, wb.normalized()), 1e-14);

  // A translation meeting the paper's condition m' . q_ij = 0 is still not solvable ...
  const Vector3d paper = ws.cross(Vector3d::UnitX()).normalized();
  const SpatialPose jp = counter_j(t, Vector3d::Zero(), paper);
  const AxodePoint ap = axode_point(i, jp);
  EXPECT_LE(std::abs(ap.dm.dot(ap.q_ij)), 1e-15);
  EXPECT_GT(std::abs(ap.dm.dot(ap.q_ji)), 1e-3);
  EXPECT_EQ(ap.kind, AxodeKind::kNonZeroPitch);
  EXPECT_GT((ap.dM * ap.s_ij - ap.dm).norm(), 1e-3);  // eq 79 has no solution
  EXPECT_NEAR(ap.pitch, twist_pitch(i, jp), 1e-14);
  // ... while one meeting the corrected m' . (M q_ij) = 0 is.
  const Vector3d corrected = wb.cross(Vector3d::UnitX()).normalized();
  const AxodePoint ac = axode_point(i, counter_j(t, Vector3d::Zero(), corrected));
  EXPECT_GT(std::abs(ac.dm.dot(ac.q_ij)), 1e-3);
  EXPECT_LE(std::abs(ac.dm.dot(ac.q_ji)), 1e-15);
  EXPECT_EQ(ac.kind, AxodeKind::kWellBehaved);
  EXPECT_LE((ac.dM * ac.s_ij - ac.dm).norm(), 1e-15);
}

// ---- 4. degenerate kinds and bad input -----------------------------------------------------

TEST(SorceAxode, PureTranslationIsIllBehavedAndNoMotionStationary) {
  // Both bodies turn together (M = I) while j slides along its own x: pure relative translation.
  const RotJet R = about(Vector3d(0, 1, 1).normalized(), 0.3, 0.8, 0.1);
  const SpatialPose i = pose(R, Vector3d(1, 2, 3), Vector3d(0.1, 0, 0), Vector3d::Zero());
  const Vector3d x = R.R * Vector3d(0.4, 0, 0), dx = R.dR * Vector3d(0.4, 0, 0) + R.R * Vector3d(0.5, 0, 0);
  const SpatialPose j = pose(R, i.r + x, i.dr + dx, Vector3d::Zero());
  const AxodePoint a = axode_point(i, j);
  EXPECT_EQ(a.kind, AxodeKind::kIllBehaved);
  EXPECT_TRUE(std::isinf(a.pitch));
  EXPECT_THROW(axode_residual(i, j, a, {0.0}), InputError);

  // Same motion without the slide: stationary; and two bodies at rest.
  const SpatialPose j0 = pose(R, i.r + x, i.dr + R.dR * Vector3d(0.4, 0, 0), Vector3d::Zero());
  EXPECT_EQ(axode_point(i, j0).kind, AxodeKind::kStationary);
  EXPECT_EQ(axode_point(SpatialPose{}, SpatialPose{}).kind, AxodeKind::kStationary);
  SpatialPose moving;
  moving.dr = Vector3d(0, 0, 1);
  EXPECT_EQ(axode_point(SpatialPose{}, moving).kind, AxodeKind::kIllBehaved);
  // A slow but real relative rotation is not mistaken for none.
  const SpatialPose slow = pose(about(Vector3d::UnitZ(), 0.0, 1e-6, 0.0), Vector3d::Zero(), Vector3d::Zero(),
                                Vector3d::Zero());
  EXPECT_EQ(axode_point(slow, SpatialPose{}).kind, AxodeKind::kWellBehaved);
}

template <class F>
std::string place_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.place();
  }
  return "(no throw)";
}

TEST(SorceAxode, BadInputNamesThePlace) {
  const SpatialPose ok = pose(about(Vector3d::UnitZ(), 0.2, 1.0, 0.0), Vector3d(1, 0, 0), Vector3d::Zero(),
                              Vector3d::Zero());
  SpatialPose bad = ok;
  bad.R(0, 0) += 1e-3;
  EXPECT_EQ(place_of([&] { axode_point(bad, ok); }), "i.R");
  bad = ok;
  bad.R = -ok.R;  // a reflection
  EXPECT_EQ(place_of([&] { axode_point(ok, bad); }), "j.R");
  bad = ok;
  bad.dR += 1e-3 * Matrix3d::Identity();
  EXPECT_EQ(place_of([&] { axode_point(ok, bad); }), "j.dR");
  bad = ok;
  bad.ddR = Matrix3d::Zero();  // would need -R [w]x^2 != 0
  EXPECT_EQ(place_of([&] { axode_point(bad, SpatialPose{}); }), "i.ddR");
  bad = ok;
  bad.r.x() = std::nan("");
  EXPECT_EQ(place_of([&] { axode_point(bad, ok); }), "i.r");
  // Seed orthogonal to the axis (z): eq 84 cannot sign q.
  EXPECT_EQ(place_of([&] { axode_point(ok, SpatialPose{}, Vector3d::UnitX()); }), "seed");
  // A seed keeps its sign: -z gives q = -z.
  EXPECT_LE((axode_point(ok, SpatialPose{}, -Vector3d::UnitZ()).q_ij + Vector3d::UnitZ()).norm(), 1e-15);
  EXPECT_EQ(place_of([&] { axode_residual(ok, SpatialPose{}, axode_point(ok, SpatialPose{}), {}); }), "u");
  const PoseFunction f = [&](double) { return ok; };
  EXPECT_EQ(place_of([&] { sample_axodes(f, f, {0.0, INFINITY}); }), "t[1]");
  EXPECT_EQ(place_of([&] { sampled_axode_residual(f, f, sample_axodes(f, f, {0.0}), {0.0}); }), "points");
}

}}  // namespace
}  // namespace rigidfold::sorce
