#pragma once
// Scalar and planar-vector functions of the synchronized fold parameter t in [0, 1] (seed
// 002, SORCE: t = 0 flat/unfolded, t = 1 fully folded), each carried with its first three
// derivatives in t. The rolling-contact profiles (sorce_profile.hpp) use gamma', z', d';
// their tangent and curvature need up to the third derivative, so every input function
// is a Jet of order 3, computed exactly (forward-mode Taylor arithmetic, Boost.Math
// autodiff) and never by finite differences: the end points t = 0, 1 are where the seed's
// tan(pi t / 2) parameterizations (eqs 25, 35) defeat naive differencing.
//
// Units: t dimensionless; angles radians (fold angle > 0 valley, docs/DESIGN.md); offsets in the
// caller's length unit.
#include <array>
#include <functional>
#include <vector>

namespace rigidfold::sorce {

// f(t), f'(t), f''(t), f'''(t).
using Jet = std::array<double, 4>;
using ScalarFunction = std::function<Jet(double t)>;
// A vector in the fold's normal plane (x, y), each component a Jet.
using VectorJet = std::array<Jet, 2>;
using VectorFunction = std::function<VectorJet(double t)>;

// f = c.
ScalarFunction constant_function(double c);
// f = end_value * t^power, power >= 1 (eq 27 linear offsets: power 1; eq 61 d(t) = 0.4 t^2).
ScalarFunction power_function(double end_value, int power);

// A polynomial sum_k c[k] t^k.
struct Polynomial {
  std::vector<double> c;
};
// The seed's offset bases (eq 37): B1 = (1 - t)^2 t, B2 = (1 - t) t, B3 = (1 - t) t^2.
// The OCR prints "4(1 - t) t^2" for B3; the digest reads the 4 as an OCR artefact. The
// eq 39 coefficients settle it (tests/sorce/sorce_seed_coefficients_test.cpp): with B3 as
// here one sign pattern makes all of vertex A's profiles convex as the seed says, with the
// 4 none does. b3_scale multiplies B3.
std::vector<Polynomial> seed_offset_bases(double b3_scale = 1.0);
// Offset with endpoint-preserving bases (eq 36): f = end_value * (t + sum_j b[j] B_j(t)).
// Every basis must vanish at t = 0 and t = 1 (|B(0)|, |B(1)| <= 1e-12), so f(0) = 0 and
// f(1) = end_value whatever b is. Throws InputError("bases") otherwise, InputError("b")
// when b has more entries than bases.
ScalarFunction basis_offset(double end_value, const std::vector<double>& b, const std::vector<Polynomial>& bases);

// Fold angle gamma = 2 atan2(k sin(pi t / 2), cos(pi t / 2)) = 2 atan(k tan(pi t / 2)):
// 0 at t = 0, pi sign(k) at t = 1, computed without tan so that t = 1 is exact. Eqs 24-25
// and 35 are of this form (k = 1, 1/mu, sqrt(mu), 1/sqrt(mu), with signs). k != 0.
ScalarFunction tan_half_fold(double k);
// The multiplier model's fold angle on the drive parameter, gamma = 2 atan(k tan(theta t / 2))
// = 2 atan2(k sin(theta t / 2), cos(theta t / 2)) for a drive that reaches theta at t = 1
// (|theta| <= pi; theta = pi is tan_half_fold(k)); k = 0 is a crease that stays flat.
ScalarFunction tan_half_path(double k, double theta);
// gamma = gamma_end * t (the circular CORE joint's eq 1 with gamma_end = pi).
ScalarFunction linear_fold(double gamma_end);

// Circular CORE offset (eqs 2, 62, 63): z = -r tan(gamma(t) / 4), r the arc radius (half
// the panel thickness). gamma must stay in (-2 pi, 2 pi).
ScalarFunction circular_offset(double r, ScalarFunction gamma);

// Split offset of a fold along the fold's half-angle direction (eqs 58, 59, 68):
// d(t) = d_scalar(t) * u(gamma(t) / 2), u(a) = (cos a, sin a).
VectorFunction split_offset_along_half_angle(ScalarFunction d_scalar, ScalarFunction gamma);
// The scalar split offset that makes a split fold (angle gamma_split) a circular CORE joint
// of radius r when both panels beside it carry the circular offsets of another fold
// (angle gamma_offsets), eq 69: d(t) = 2 r sin(gamma_split / 2) (tan(gamma_split / 4) -
// tan(gamma_offsets / 4)). Use with split_offset_along_half_angle(d, gamma_split).
ScalarFunction circular_split_offset(double r, ScalarFunction gamma_split, ScalarFunction gamma_offsets);

}  // namespace rigidfold::sorce
