#pragma once
// Closed form of the asymmetric Miura vertex (seed 000, Kamrava et al.): the deflection
// angles phi, psi of the outgoing spinal crease, the motion limit theta_limit, the four
// fold angles and the frame-to-frame rotation, from the pattern angles alpha1, alpha2 and
// the fold parameter theta. All angles in radians.
//
// Geometry (seed Fig. 1/2, eqs. (5)-(10)). In the flat state the vertex lies in the
// xy-plane, seen from +z, with four creases leaving the origin:
//   a  outgoing spinal crease, direction angle 0        (+x)
//   b  peripheral crease,      direction angle alpha1   (y > 0 side)
//   c  incoming spinal crease, direction angle pi       (-x)
//   d  peripheral crease,      direction angle -alpha2  (y < 0 side)
// a and c are collinear when flat ("spinal"); alpha1 = angle(a, b), alpha2 = angle(a, d),
// both in (0, pi/2). Folding keeps c on the -x axis and rotates the panel b-c by +theta
// and the panel c-d by -theta about the x axis, so the xz-plane bisects the two panels at c:
//   b = (cos a1, sin a1 cos t, sin a1 sin t),   d = (cos a2, -sin a2 cos t, sin a2 sin t).
// theta is therefore HALF the fold angle of crease c.
//
// Incoming frame (the seed's xyz): x = -c (along the spine, towards a), z = bisector of the
// normals of the two panels at c, y = z x x (towards b's side). phi and psi are the
// seed's projection angles of the outgoing spinal direction a_hat in this frame:
//   phi = atan2(a_z, a_x)   angle of a_hat projected on the xz-plane, from +x towards +z
//                           (a rotation by -phi about +y); phi in (-pi, pi], sign of theta.
//   psi = arctan(a_y / a_x) angle of a_hat projected on the xy-plane, from +x towards +y
//                           (a rotation by +psi about +z); psi in [-pi/2, pi/2], > 0 when
//                           alpha1 < alpha2, even in theta, exactly 0 when alpha1 == alpha2.
// Together a_hat = (cos phi, cos phi tan psi, sin phi) / norm. Note: psi is the seed's
// definition (eq. 39 with the arctan, docs/DESIGN.md). It jumps from +-pi/2 to -+pi/2 where
// a_x changes sign (|phi| passes pi/2, which happens only when both alpha > pi/4); use
// spinal_out or miura_vertex_rotation there, they are continuous.
//
// Kernel view (vertex_closure.hpp). As a degree-4 vertex the creases in CCW order are
// a, b, c, d (index 0..3, see MiuraCrease) with sectors
//   alpha_0 = alpha1 (a-b), alpha_1 = pi - alpha1 (b-c), alpha_2 = pi - alpha2 (c-d),
//   alpha_3 = alpha2 (d-a),
// and the fold angles (valley > 0) are
//   rho_c = 2 theta,  rho_a = -2 theta  (exactly: cos rho_a = cos 2 theta follows from
//                                        a.b = cos a1, a.d = cos a2, b.d),
//   rho_b, rho_d with the sign of theta, 1 - cos rho_b = (1 - a_x) / sin^2 a1 and
//   1 - cos rho_d = (1 - a_x) / sin^2 a2.
// theta > 0 folds c, b, d valley and a mountain. The loop
// Rx(rho_a) Rz(alpha1) Rx(rho_b) Rz(pi-alpha1) Rx(rho_c) Rz(pi-alpha2) Rx(rho_d) Rz(alpha2)
// closes. This is the vertex's non-trivial branch (the seed's a_x != 1 root); the other
// branch through the flat state (a = +x, only a and c folded) is not returned.
//
// Motion limit. Rigid folding ends when the peripheral crease next to the smaller alpha
// folds completely (|rho| = pi, its two panels meet); beyond that the panels would pass
// through each other although the formula stays smooth. This gives
//   tan^2 theta_limit = sin(alpha1 + alpha2) / |sin(alpha2 - alpha1)|,
// the same as seed eq. (40) when alpha1 <= alpha2; eq. (40) as printed is NaN for
// alpha1 > alpha2 (acos of a ratio > 1): the ratio must be tan(min alpha) / tan(max alpha).
// theta_limit = pi/2 when alpha1 == alpha2 (a flat-foldable symmetric Miura vertex).
//
// Accuracy. The seed's eqs. (35)-(38) divide by sin theta and cos theta and subtract
// cot alpha1 - cot alpha2; here f is scaled by 4 sin^2 a1 sin^2 a2 sin^2 theta, which gives
//   G = ((q tan t)^2 + p^2 - (2 S sin t)^2,  4 S q sin t tan t,  4 S p sin t),
//   p = sin(a1 + a2), q = sin(a2 - a1), S = sin a1 sin a2,
// free of divisions by zero at theta = 0 and of the cancellation at alpha1 = alpha2
// (q is computed from a2 - a1 directly). phi, psi and the fold angles are accurate to a few
// ulps relative to their size from theta = 0 to theta_limit (tested against a 50-digit
// reference), for alpha in [1e-300 deg, pi/2): the pattern constants are divided by
// max(sin a1, sin a2) before any product, so a tiny alpha underflows nothing (as alpha1 -> 0
// the vertex tends to a straight line a-c with d flat: rho_b -> 4 theta, rho_d -> 0).
//
// Check. miura_vertex_checked verifies what the state claims before it is used as an
// answer: the closure residual |log R| of the four fold angles (vertex_closure.hpp) at most
// kMiuraClosureTolerance, rho_a = -2 theta and rho_c = 2 theta, rho_b and rho_d in [-pi, pi]
// with the sign of theta (0 at theta = 0). A state that fails is never returned.
#include <Eigen/Core>
#include <array>
#include <string_view>

namespace rigidfold {

// Kernel index (CCW from the outgoing spinal crease) of each crease of the Miura vertex.
enum MiuraCrease : int {
  kMiuraSpinalOut = 0,     // a
  kMiuraPeripheral1 = 1,   // b, at alpha1 from a
  kMiuraSpinalIn = 2,      // c
  kMiuraPeripheral2 = 3,   // d, at alpha2 from a (clockwise)
};

// Names used in JSON/CLI output, indexed by MiuraCrease.
constexpr std::array<std::string_view, 4> kMiuraCreaseNames{"spinal_out", "peripheral_1", "spinal_in",
                                                            "peripheral_2"};

struct MiuraVertexState {
  double phi = 0.0;          // deflection of a_hat in the xz-plane (rad), see above
  double psi = 0.0;          // deflection of a_hat in the xy-plane (rad), seed definition
  double theta = 0.0;        // the input (rad)
  double theta_limit = 0.0;  // motion limit, > 0 (rad)
  Eigen::Vector3d spinal_out = Eigen::Vector3d::UnitX();  // a_hat in the incoming frame (unit)
  // Folded unit crease directions a, b, c, d in the incoming frame, indexed by MiuraCrease.
  std::array<Eigen::Vector3d, 4> crease_directions;
  // Kernel fold angles (valley > 0) of a, b, c, d, indexed by MiuraCrease.
  std::array<double, 4> fold_angles{};
  // Sector angles of the vertex in kernel order: sector i between crease i and i+1.
  std::array<double, 4> sectors{};
  // Direction angles of the creases in the flat reference (from +x, CCW): 0, alpha1, pi,
  // 2 pi - alpha2. Place crease i at (cos, sin) of these to build the flat pattern.
  std::array<double, 4> flat_directions{};
};

// Motion limit of the vertex (rad): theta must satisfy |theta| <= theta_limit.
// Symmetric in alpha1, alpha2; pi/2 when alpha1 == alpha2; tends to pi/4 as min alpha -> 0.
// Throws std::invalid_argument unless both alphas are finite and in (0, pi/2).
double miura_theta_limit(double alpha1, double alpha2);

// Sector angles alpha1, pi - alpha1, pi - alpha2, alpha2 (kernel order, rad). No checks.
std::array<double, 4> miura_sectors(double alpha1, double alpha2);

// The vertex at fold parameter theta.
// Inputs:
//   alpha1, alpha2  pattern angles between a and b, a and d (rad), each in (0, pi/2)
//   theta           half the fold angle of the incoming spinal crease c (rad), valley > 0,
//                   |theta| <= miura_theta_limit(alpha1, alpha2)
// Output: MiuraVertexState (see above). theta = 0 gives the flat vertex (phi = psi = 0).
// Throws std::invalid_argument naming "alpha1", "alpha2" or "theta" on bad input.
MiuraVertexState miura_vertex(double alpha1, double alpha2, double theta);

// Closure tolerance of miura_vertex_checked (rad). The closed form reaches ~1e-15 over the
// whole domain (tests/vertex/miura_vertex_test.cpp); 1e-10 leaves room for the loop
// product's own rounding without passing a wrong branch (those miss by > 1e-3).
inline constexpr double kMiuraClosureTolerance = 1e-10;

// Closure residual |log R| (rad) of the state's fold angles about its sectors, and
// whether the sign claims above hold. Never throws.
struct MiuraVertexCheck {
  double closure_residual = 0.0;
  bool signs_ok = true;
  bool passed() const { return signs_ok && closure_residual <= kMiuraClosureTolerance; }
};
MiuraVertexCheck check_miura_vertex(const MiuraVertexState& state);

// miura_vertex, verified by check_miura_vertex. Throws std::invalid_argument as
// miura_vertex, and NoAnswerError (kernel/pattern/no_answer_error.hpp, with the residual)
// if the state fails its check.
MiuraVertexState miura_vertex_checked(double alpha1, double alpha2, double theta);

// Relative rotation between the spinal crease frames, R = [x_out y_out z_out] expressed in
// the incoming frame (columns are the outgoing frame's axes):
//   incoming frame  x = -c, z = bisector of the normals of panels b-c and c-d, y = z x x
//   outgoing frame  x = a_hat, z = bisector of the normals of panels d-a and a-b
//                   (unit, perpendicular to a_hat), y = z x x (towards panel a-b)
// So R e_x = a_hat (consistent with phi, psi above), R = I at theta = 0, and a vector with
// outgoing-frame coordinates v has incoming-frame coordinates R v.
// Chaining (Miura string): the outgoing frame is the incoming frame of a next vertex whose
// crease c is this crease a, oriented the same way (its b on the y > 0 side); that vertex
// then has theta' = rho_a / 2 = -theta, and R_total = R_1 R_2 ... R_n.
// In kernel terms R = Rx(-theta) Rot(d0, rho_d) Rx(-theta), d0 = (cos a2, -sin a2, 0).
// Inputs and throws as miura_vertex.
Eigen::Matrix3d miura_vertex_rotation(double alpha1, double alpha2, double theta);

}  // namespace rigidfold
