#pragma once
// Rolling axodes of the general 3D relative motion of two rigid bodies (seed 002 section 13,
// with the digest's correction of eq 82). The 3D counterpart of planar_centrodes
// (sorce_profile.hpp, eq 54).
//
// Inputs. Two bodies i, j move as p -> R(t) p + r(t) (eq 70): p in the body's own t = 0
// coordinates, R in SO(3), r a translation; each pose carries R', r' and optionally R'', r''
// (derivatives in t). With M = R_j^T R_i (eq 77) and m = R_j^T (r_j - r_i) (eq 78), the
// body-i point p sits, in body j's coordinates, at M p - m, so its velocity relative to j is
// M' p - m'. Rolling contact needs points of zero relative velocity, M' s_ij = m' (eqs 76, 79).
//
// Outputs (AxodePoint). M' = [omega_j]x M = M [omega_i]x: omega_j is the angular velocity
// of body i relative to body j in body j's coordinates, omega_i = M^T omega_j the same vector
// in body i's; M' has rank 2 (singular values |omega|, |omega|, 0) or 0. The screw of the
// relative motion has pitch p = omega . v / |omega|^2 = -m' . omega_j / |omega|^2 (v the
// relative velocity of any point, in the same frame). M' s = m' is solvable iff m' is
// orthogonal to the left null vector of M', omega_j = M q_ij: the digest's corrected eq 82,
// m' . (M q_ij) = 0, i.e. zero pitch (no lateral sliding). The paper's m' . q_ij = 0 tests
// omega_i instead, which differs wherever the axis turns out of a fixed plane.
//   s_ij = pinv(M') m' (eq 83): the point of the instantaneous screw axis nearest body i's
//          origin, in body i's coordinates (with non-zero pitch still the axis: the least-
//          squares solution; it is then not a contact point);
//   q_ij   the unit null vector of M' (body i), signed by eq 84: q = (I - pinv(M') M') seed;
//   s_ji = M s_ij - m, q_ji = M q_ij (eqs 89-91): the same line in body j's coordinates.
// The axodes are the ruled surfaces s_ij(t) + u q_ij(t) and s_ji(t) + u q_ji(t) (eqs 86, 87);
// when the pitch is 0 for all t they touch along the ruling (eq 71) and roll (eq 72).
// With second derivatives the point also carries s', q' of both base curves and rulings,
// differentiated in closed form (s_ij = (M^T m') x omega_i / |omega|^2, which equals
// pinv(M') m'), never by differencing.
//
// Tolerances (AxodeOptions; all relative, dimensionless):
//   input_tolerance 1e-9: R orthonormal with det +1, R^T R' skew, sym(R^T R'') = -R'^T R',
//     each relative to the sizes of the matrices involved;
//   rank_tolerance 1e-10: M' is rank 0 when sigma_max(M') <= rank_tolerance (|w_i| + |w_j|)
//     (w the bodies' own angular speeds |R'|_2); then m' counts as 0 when
//     |m'| <= rank_tolerance L_m, L_m = (|w_i| + |w_j|) |r_j - r_i| + |r_j' - r_i'|;
//   pitch_tolerance 1e-9: the pitch is 0 when |p| <= pitch_tolerance L_m / |omega| (L_m /
//     |omega| bounds |m'| / |omega|, the numbers the pitch is formed from);
//   seed_tolerance 1e-6: the seed must keep |P seed| > seed_tolerance |seed| (not orthogonal
//     to the axis).
//
// Units: lengths in the caller's unit, angles radians, t dimensionless; omega in radians per
// unit t, pitch in length per radian, s' in length per unit t.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "design/sorce/sorce_profile.hpp"

namespace rigidfold::sorce {

// One body's pose p -> R p + r at some t, with derivatives in t. ddR, ddr are read only when
// second_derivatives is set (then the axode point carries s', q').
struct SpatialPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity(), dR = Eigen::Matrix3d::Zero(), ddR = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero(), dr = Eigen::Vector3d::Zero(), ddr = Eigen::Vector3d::Zero();
  bool second_derivatives = false;
};
using PoseFunction = std::function<SpatialPose(double t)>;

enum class AxodeKind {
  kWellBehaved,   // rank 2, pitch 0: a rolling pair exists (theorem 2)
  kNonZeroPitch,  // rank 2, pitch != 0: lateral sliding along the axis, no rolling pair
  kIllBehaved,    // M' = 0, m' != 0: pure relative translation (pitch reported +infinity)
  kStationary,    // M' = 0, m' = 0: no relative motion (axis undefined, pitch 0)
};
const char* axode_kind_name(AxodeKind kind);

struct AxodeOptions {
  double input_tolerance = 1e-9;
  double rank_tolerance = 1e-10;
  double pitch_tolerance = 1e-9;
  double seed_tolerance = 1e-6;
};

struct AxodePoint {
  double t = 0.0;  // set by sample_axodes (axode_point leaves 0)
  AxodeKind kind = AxodeKind::kStationary;
  Eigen::Matrix3d M = Eigen::Matrix3d::Identity(), dM = Eigen::Matrix3d::Zero();  // eq 77 and M'
  Eigen::Vector3d m = Eigen::Vector3d::Zero(), dm = Eigen::Vector3d::Zero();      // eq 78 and m'
  Eigen::Vector3d omega_i = Eigen::Vector3d::Zero(), omega_j = Eigen::Vector3d::Zero();
  Eigen::Vector3d singular_values = Eigen::Vector3d::Zero();  // of M', descending
  double pitch = 0.0;
  double pitch_scale = 0.0;  // L_m / |omega|: the length the pitch tolerance is relative to
  // Rank 2 only (zero otherwise): the axis in both bodies.
  Eigen::Vector3d s_ij = Eigen::Vector3d::Zero(), q_ij = Eigen::Vector3d::Zero();
  Eigen::Vector3d s_ji = Eigen::Vector3d::Zero(), q_ji = Eigen::Vector3d::Zero();
  // Rank 2 with second derivatives only: d/dt of the four above.
  bool has_derivatives = false;
  Eigen::Vector3d ds_ij = Eigen::Vector3d::Zero(), dq_ij = Eigen::Vector3d::Zero();
  Eigen::Vector3d ds_ji = Eigen::Vector3d::Zero(), dq_ji = Eigen::Vector3d::Zero();
};

// The relative screw of body i with respect to body j at one t. seed signs q_ij (eq 84);
// a zero seed means omega_i (q along the relative angular velocity). Throws InputError with
// places "i.R", "i.dR", "i.ddR", "i.r" (and "j. ...") for non-finite or non-rotation input,
// "seed" for a non-finite seed or one orthogonal to the axis.
AxodePoint axode_point(const SpatialPose& i, const SpatialPose& j,
                       const Eigen::Vector3d& seed = Eigen::Vector3d::Zero(), const AxodeOptions& options = {});

// axode_point at each t in turn, each seeded with the last rank-2 point's q_ij (the first
// with `seed`), so that q keeps its sign along the samples. Throws InputError("t") for a
// non-finite t, and passes on axode_point's errors.
std::vector<AxodePoint> sample_axodes(const PoseFunction& i, const PoseFunction& j, const std::vector<double>& t,
                                      const Eigen::Vector3d& seed = Eigen::Vector3d::Zero(),
                                      const AxodeOptions& options = {});

// Residuals of a sampled axode pair, from the point's fields as given (so a caller may put in
// its own s, q or their derivatives), over the ruling points u (length units):
//   contact (eq 71): max_u |R_i (s_ij + u q_ij) + r_i - R_j (s_ji + u q_ji) - r_j|  (length)
//   rolling (eq 72): max_u |R_i (s_ij' + u q_ij') - R_j (s_ji' + u q_ji')|        (length / t)
// rolling is -1 when the point has no derivatives. Throws InputError("point") for a point
// without an axis (ill-behaved or stationary), InputError("u") for an empty or non-finite u.
struct AxodeResidual {
  double contact = 0.0, rolling = 0.0;
};
AxodeResidual axode_residual(const SpatialPose& i, const SpatialPose& j, const AxodePoint& point,
                             const std::vector<double>& u);
// The largest residuals over sampled points (each at its own t), skipping points without an
// axis; rolling -1 if no point has derivatives. Throws InputError("points") if none has an axis.
AxodeResidual sampled_axode_residual(const PoseFunction& i, const PoseFunction& j,
                                     const std::vector<AxodePoint>& points, const std::vector<double>& u);

// A planar fold (sorce_profile.hpp) as two 3D poses: the normal plane is (x, y), z is the
// fold direction (the fold frame of sorce_closure.hpp); left = body i, right = body j, with
// first and second derivatives from the Jets. Its axode is the fold's centrode pair: s_ij =
// (s_left, 0), s_ji = (s_right, 0), q = +-e_z, pitch 0.
struct SpatialPosePair {
  SpatialPose left, right;
};
SpatialPosePair fold_spatial_poses(const FoldMotion& motion, double t);

}  // namespace rigidfold::sorce
