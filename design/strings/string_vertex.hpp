#pragma once
// One Miura vertex of an origami string, in closed form (seed 000, with the corrections of
// docs/DESIGN.md: K3 = (K2/cos th)^2 + (K1/sin th)^2, psi = atan(f_y / f_x), a_x != 1 root).
//
// The double-precision state (string_vertex_state) comes from the kernel's closed form,
// kernel/vertex/miura_vertex.hpp (same frames and signs). string_vertex_frame is the same
// formula templated on the scalar, because the string fits need ceres::Jet derivatives of
// the whole output frame; tests/design/string_kinematics_test.cpp checks the two agree.
//
// Geometry (flat pattern seen from +z, spine along +x):
//   c  incoming spinal crease (from the previous vertex to this one), direction -x
//   a  outgoing spinal crease, direction +x
//   b  top peripheral crease (y > 0 side), at angle alpha1 from a:  (cos a1,  sin a1)
//   d  bottom peripheral crease (y < 0),   at angle alpha2 from a:  (cos a2, -sin a2)
//   alpha1, alpha2 in (0, pi/2) (radians): both peripheral creases lean toward a.
// Input frame C (attached to crease c): x along the spine direction arriving at the vertex,
//   y toward the top side, the xz plane bisecting the dihedral at c, z = x cross y.
//   theta: the two faces at c are turned by +theta (top) and -theta (bottom) about x, so
//   the fold angle of c is rho_c = 2 theta (FOLD sign: theta > 0 valley).
// Output frame A (attached to crease a), defined the same way for a: x along a, y toward
//   the top side, xz bisecting the dihedral at a; its half fold angle theta_out satisfies
//   rho_a = 2 theta_out. For every Miura vertex theta_out = -theta exactly (tested), which
//   is how one actuation is transmitted along a string.
// Deflections (seed 000 eq. 38-39): the outgoing direction a expressed in frame C is
//   proportional to f = (f_x, f_y, f_z);  phi = atan2(f_z, f_x) (about -y, toward +z),
//   psi = atan(f_y / f_x) (about z, toward the top side). phi has the sign of theta;
//   psi has the sign of cot(alpha1) - cot(alpha2).
// theta limit (seed 000 eq. 40, with the ratio taken <= 1):
//   theta_limit = pi/2 - acos(tan(min(a1,a2)) / tan(max(a1,a2))) / 2; at |theta| ->
//   theta_limit the peripheral crease next to the smaller alpha folds to +-pi.
#include <Eigen/Core>
#include <cmath>

namespace rigidfold::design {

// Closed-form frame of a Miura vertex, templated for automatic differentiation.
// Inputs: alpha1, alpha2 (radians, in (0, pi/2)), theta (radians, |theta| < theta_limit).
// Outputs: R (row-major 3x3, R[3*r + c]): columns are the axes of frame A expressed in
//          frame C; phi, psi (radians) as above.
// Near-flat safe: f is scaled by sin^2(theta), so theta -> 0 gives R -> I smoothly.
template <class T>
void string_vertex_frame(const T& alpha1, const T& alpha2, const T& theta, T R[9], T* phi = nullptr,
                         T* psi = nullptr) {
  using std::atan;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  using std::tan;
  const T cot1 = T(1) / tan(alpha1), cot2 = T(1) / tan(alpha2);
  const T K1 = (cot1 + cot2) / T(2), K2 = (cot1 - cot2) / T(2);
  const T s = sin(theta), c = cos(theta);
  // f * sin^2(theta): finite at theta = 0 where f itself blows up.
  const T fx = K2 * K2 * s * s / (c * c) + K1 * K1 - s * s;
  const T fy = T(2) * K2 * s * s / c;
  const T fz = T(2) * K1 * s;
  const T fn = sqrt(fx * fx + fy * fy + fz * fz);
  const T a[3] = {fx / fn, fy / fn, fz / fn};
  const T b[3] = {cos(alpha1), sin(alpha1) * c, sin(alpha1) * s};
  const T d[3] = {cos(alpha2), -sin(alpha2) * c, sin(alpha2) * s};
  const T ab = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const T ad = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
  T t[3], w[3], y[3];
  for (int k = 0; k < 3; ++k) {
    t[k] = b[k] - ab * a[k];  // top face at a, direction away from a
    w[k] = d[k] - ad * a[k];  // bottom face at a
  }
  const T tn = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  const T wn = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  for (int k = 0; k < 3; ++k) y[k] = t[k] / tn - w[k] / wn;  // bisector of the dihedral at a, toward the top
  const T yn = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
  for (int k = 0; k < 3; ++k) y[k] = y[k] / yn;
  const T z[3] = {a[1] * y[2] - a[2] * y[1], a[2] * y[0] - a[0] * y[2], a[0] * y[1] - a[1] * y[0]};
  for (int r = 0; r < 3; ++r) {
    R[3 * r + 0] = a[r];
    R[3 * r + 1] = y[r];
    R[3 * r + 2] = z[r];
  }
  if (phi) *phi = atan2(fz, fx);
  if (psi) *psi = atan(fy / fx);
}

struct StringVertexState {
  double phi = 0, psi = 0;           // deflections (radians), see above
  Eigen::Matrix3d rotation;          // frame A axes in frame C (columns)
  double theta_out = 0;              // half fold angle of a in frame A (= -theta)
  // Fold angles (radians, FOLD sign) of the four creases, each edge oriented away from
  // the vertex along the spine (c: previous vertex -> this one, a: this one -> next)
  // and from the vertex to the strip boundary for b and d.
  double rho_c = 0, rho_a = 0, rho_b = 0, rho_d = 0;
  double theta_limit = 0;            // radians
};

// theta_limit(alpha1, alpha2) as above (radians). alpha in (0, pi/2).
double string_theta_limit(double alpha1, double alpha2);

// The full state of one vertex (closed form). Inputs as string_vertex_frame.
StringVertexState string_vertex_state(double alpha1, double alpha2, double theta);

// Per-vertex closed-form inverse. Given theta (radians, != 0) and the wanted outgoing
// spine direction `dir` in frame C (any non-zero length), returns the unique (alpha1,
// alpha2) (radians) from seed 000 eq. (13), (16):
//     cot(alpha1) = (a_y cos th + a_z sin th) / (1 - a_x),
//     cot(alpha2) = (-a_y cos th + a_z sin th) / (1 - a_x).
// For a given theta the answer is unique; over theta the solutions form a one-parameter
// family (the string fixes theta, see string_inverse.hpp). Returns false (alphas left
// unspecified, set to NaN) when no alpha in (0, pi/2) gives this direction at this theta:
// the direction must satisfy a_z sin th > |a_y| cos th (a cone about +-z of half-angle
// |theta| in the yz plane).
bool string_vertex_inverse_direction(const Eigen::Vector3d& dir, double theta, double& alpha1, double& alpha2);

// Same from the deflections (phi, psi) (radians, |psi| < pi/2): dir = (cos phi,
// cos phi tan psi, sin phi).
bool string_vertex_inverse(double phi, double psi, double theta, double& alpha1, double& alpha2);

}  // namespace rigidfold::design
