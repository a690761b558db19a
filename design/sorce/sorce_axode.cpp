#include "design/sorce/sorce_axode.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "kernel/math/so3.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

// Largest entry magnitude (the scale the relative input checks use).
double max_abs(const Matrix3d& A) { return A.cwiseAbs().maxCoeff(); }

// |R'|_2: a body's own angular speed (R' = R [w]x has singular values |w|, |w|, 0).
double angular_speed(const SpatialPose& p) { return p.dR.norm() / std::sqrt(2.0); }

void check_pose(const SpatialPose& p, const std::string& name, double tol) {
  if (!p.R.allFinite()) throw InputError(name + ".R", "not finite");
  if (!p.dR.allFinite()) throw InputError(name + ".dR", "not finite");
  if (!p.r.allFinite()) throw InputError(name + ".r", "not finite");
  if (!p.dr.allFinite()) throw InputError(name + ".dr", "not finite");
  if (orthonormality_error(p.R) > tol || p.R.determinant() < 0.0)
    throw InputError(name + ".R",
                     "not a rotation (orthonormality error " + std::to_string(orthonormality_error(p.R)) + ")");
  // d/dt (R^T R) = 0: R^T R' is skew.
  const Matrix3d W = p.R.transpose() * p.dR;
  if (max_abs(W + W.transpose()) > tol * max_abs(p.dR))
    throw InputError(name + ".dR", "not tangent to SO(3) at R (R^T R' is not skew)");
  if (!p.second_derivatives) return;
  if (!p.ddR.allFinite()) throw InputError(name + ".ddR", "not finite");
  if (!p.ddr.allFinite()) throw InputError(name + ".ddr", "not finite");
  // d2/dt2 (R^T R) = 0: sym(R^T R'') = -R'^T R'.
  const Matrix3d A = p.R.transpose() * p.ddR, B = p.dR.transpose() * p.dR;
  const double scale = max_abs(p.ddR) + max_abs(B);
  if (max_abs(A + A.transpose() + 2.0 * B) > tol * scale)
    throw InputError(name + ".ddR", "not the second derivative of a rotation (sym(R^T R'') != -R'^T R')");
}

}  // namespace

const char* axode_kind_name(AxodeKind kind) {
  switch (kind) {
    case AxodeKind::kWellBehaved: return "well-behaved";
    case AxodeKind::kNonZeroPitch: return "non-zero pitch";
    case AxodeKind::kIllBehaved: return "ill-behaved";
    case AxodeKind::kStationary: return "stationary";
  }
  return "?";
}

AxodePoint axode_point(const SpatialPose& i, const SpatialPose& j, const Vector3d& seed, const AxodeOptions& o) {
  check_pose(i, "i", o.input_tolerance);
  check_pose(j, "j", o.input_tolerance);
  if (!seed.allFinite()) throw InputError("seed", "not finite");

  AxodePoint a;
  const Vector3d dr = j.r - i.r, ddr = j.dr - i.dr;
  a.M = j.R.transpose() * i.R;
  a.dM = j.dR.transpose() * i.R + j.R.transpose() * i.dR;
  a.m = j.R.transpose() * dr;
  a.dm = j.dR.transpose() * dr + j.R.transpose() * ddr;
  // M^T M' = [omega_i]x exactly for exact input; take its skew part.
  a.omega_i = skew_part_vector(a.M.transpose() * a.dM);
  a.omega_j = a.M * a.omega_i;

  const double own = angular_speed(i) + angular_speed(j);
  const double length_rate = own * dr.norm() + ddr.norm();  // L_m: bounds |m'|
  const Eigen::JacobiSVD<Matrix3d> svd(a.dM, Eigen::ComputeFullU | Eigen::ComputeFullV);
  a.singular_values = svd.singularValues();
  if (a.singular_values(0) <= o.rank_tolerance * own) {
    // No relative rotation: zero velocity everywhere or nowhere.
    const bool moving = a.dm.norm() > o.rank_tolerance * length_rate;
    a.kind = moving ? AxodeKind::kIllBehaved : AxodeKind::kStationary;
    a.pitch = moving ? std::numeric_limits<double>::infinity() : 0.0;
    a.omega_i.setZero();
    a.omega_j.setZero();
    return a;
  }

  // Rank 2: pinv(M') from the two non-zero singular triplets (the third is round-off).
  const Matrix3d& U = svd.matrixU();
  const Matrix3d& V = svd.matrixV();
  Matrix3d pinv = Matrix3d::Zero();
  for (int k = 0; k < 2; ++k) pinv += V.col(k) * U.col(k).transpose() / a.singular_values(k);
  a.s_ij = pinv * a.dm;  // eq 83 (u = 0)

  // eq 84: project the seed on the null space; omega_i when no seed is given.
  const Vector3d from = seed.squaredNorm() > 0.0 ? seed : a.omega_i;
  const Vector3d q = (Matrix3d::Identity() - pinv * a.dM) * from;
  if (!(q.norm() > o.seed_tolerance * from.norm()))
    throw InputError("seed", "orthogonal to the screw axis: cannot sign q (eq 84)");
  a.q_ij = q.normalized();
  a.s_ji = a.M * a.s_ij - a.m;  // eqs 89, 90 at u = 0
  a.q_ji = a.M * a.q_ij;        // eq 91

  const double w2 = a.omega_j.squaredNorm(), w = std::sqrt(w2);
  a.pitch = -a.dm.dot(a.omega_j) / w2;
  a.pitch_scale = length_rate / w;
  a.kind = std::abs(a.pitch) <= o.pitch_tolerance * a.pitch_scale ? AxodeKind::kWellBehaved : AxodeKind::kNonZeroPitch;

  if (i.second_derivatives && j.second_derivatives) {
    // s_ij = c x omega_i / |omega|^2 with c = M^T m' (pinv(M') = -[omega_i]x M^T / |omega|^2),
    // differentiated: c' = M'^T m' + M^T m'', omega_i' = skew part of M^T M'' (M'^T M' is
    // symmetric).
    const Vector3d ddr2 = j.ddr - i.ddr;
    const Matrix3d ddM = j.ddR.transpose() * i.R + 2.0 * j.dR.transpose() * i.dR + j.R.transpose() * i.ddR;
    const Vector3d ddm = j.ddR.transpose() * dr + 2.0 * j.dR.transpose() * ddr + j.R.transpose() * ddr2;
    const Vector3d c = a.M.transpose() * a.dm, dc = a.dM.transpose() * a.dm + a.M.transpose() * ddm;
    const Vector3d& om = a.omega_i;
    const Vector3d dom = skew_part_vector(a.M.transpose() * ddM);
    a.ds_ij = (dc.cross(om) + c.cross(dom)) / w2 - 2.0 * om.dot(dom) / (w2 * w2) * c.cross(om);
    // q = sign * omega_i / |omega_i|.
    const double sign = a.q_ij.dot(om) >= 0.0 ? 1.0 : -1.0;
    const Vector3d unit = om / w;
    a.dq_ij = sign * (dom - unit * unit.dot(dom)) / w;
    // Derivatives of s_ji = M s_ij - m and q_ji = M q_ij, as they are (not assuming pitch 0).
    a.ds_ji = a.dM * a.s_ij + a.M * a.ds_ij - a.dm;
    a.dq_ji = a.dM * a.q_ij + a.M * a.dq_ij;
    a.has_derivatives = true;
  }
  return a;
}

std::vector<AxodePoint> sample_axodes(const PoseFunction& i, const PoseFunction& j, const std::vector<double>& t,
                                      const Vector3d& seed, const AxodeOptions& options) {
  std::vector<AxodePoint> out;
  out.reserve(t.size());
  Vector3d s = seed;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!std::isfinite(t[k])) throw InputError("t[" + std::to_string(k) + "]", "not finite");
    AxodePoint p = axode_point(i(t[k]), j(t[k]), s, options);
    p.t = t[k];
    if (p.kind == AxodeKind::kWellBehaved || p.kind == AxodeKind::kNonZeroPitch) s = p.q_ij;
    out.push_back(p);
  }
  return out;
}

AxodeResidual axode_residual(const SpatialPose& i, const SpatialPose& j, const AxodePoint& p,
                             const std::vector<double>& u) {
  if (p.kind == AxodeKind::kIllBehaved || p.kind == AxodeKind::kStationary)
    throw InputError("point", std::string("no screw axis (") + axode_kind_name(p.kind) + ")");
  if (u.empty()) throw InputError("u", "no ruling points");
  AxodeResidual res;
  res.rolling = p.has_derivatives ? 0.0 : -1.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    if (!std::isfinite(u[k])) throw InputError("u[" + std::to_string(k) + "]", "not finite");
    const Vector3d wi = i.R * (p.s_ij + u[k] * p.q_ij) + i.r, wj = j.R * (p.s_ji + u[k] * p.q_ji) + j.r;
    res.contact = std::max(res.contact, (wi - wj).norm());
    if (p.has_derivatives) {
      const Vector3d vi = i.R * (p.ds_ij + u[k] * p.dq_ij), vj = j.R * (p.ds_ji + u[k] * p.dq_ji);
      res.rolling = std::max(res.rolling, (vi - vj).norm());
    }
  }
  return res;
}

AxodeResidual sampled_axode_residual(const PoseFunction& i, const PoseFunction& j,
                                     const std::vector<AxodePoint>& points, const std::vector<double>& u) {
  AxodeResidual worst;
  worst.rolling = -1.0;
  bool any = false;
  for (const AxodePoint& p : points) {
    if (p.kind == AxodeKind::kIllBehaved || p.kind == AxodeKind::kStationary) continue;
    const AxodeResidual r = axode_residual(i(p.t), j(p.t), p, u);
    worst.contact = std::max(worst.contact, r.contact);
    worst.rolling = std::max(worst.rolling, r.rolling);
    any = true;
  }
  if (!any) throw InputError("points", "no sampled point has a screw axis");
  return worst;
}

SpatialPosePair fold_spatial_poses(const FoldMotion& m, double t) {
  const Jet g = m.gamma(t), zl = m.z_left(t), zr = m.z_right(t);
  const VectorJet d = m.d ? m.d(t) : VectorJet{};
  SpatialPosePair p;
  p.left.r = Vector3d(0.0, zl[0], 0.0);
  p.left.dr = Vector3d(0.0, zl[1], 0.0);
  p.left.ddr = Vector3d(0.0, zl[2], 0.0);
  p.left.second_derivatives = true;

  // Right: Rz(gamma) (p + z_r e_y) + d; Rz' = gamma' K Rz, Rz'' = (gamma'' K + gamma'^2 K^2) Rz.
  const Matrix3d K = skew(Vector3d::UnitZ());
  const Matrix3d R = rot_z(g[0]);
  const Matrix3d dR = g[1] * K * R, ddR = (g[2] * K + g[1] * g[1] * K * K) * R;
  const Vector3d e(0.0, zr[0], 0.0), de(0.0, zr[1], 0.0), dde(0.0, zr[2], 0.0);
  SpatialPose& q = p.right;
  q.R = R;
  q.dR = dR;
  q.ddR = ddR;
  q.r = Vector3d(d[0][0], d[1][0], 0.0) + R * e;
  q.dr = Vector3d(d[0][1], d[1][1], 0.0) + dR * e + R * de;
  q.ddr = Vector3d(d[0][2], d[1][2], 0.0) + ddR * e + 2.0 * dR * de + R * dde;
  q.second_derivatives = true;
  return p;
}

}  // namespace rigidfold::sorce
