#pragma once
// A flat-foldable degree-4 vertex with SORCE joints (seed 002 sections 5, 7, 10, 11).
//
// Seed numbering (digest section 1): sectors alpha_1..alpha_4 (array index 0..3) counter-
// clockwise; fold j (index j - 1) lies between sector alpha_{j-1} (its left panel) and
// alpha_j (its right panel), fold 1 between alpha_4 and alpha_1. Panel i is sector alpha_i.
// Fold j is the kernel's crease j - 1 and alpha_j the kernel's alpha_{j-1}
// (kernel/vertex/flat_foldable_multipliers.hpp), so the kernel checks flat-foldability.
//
// Folding path (mode kEqual13 of the kernel: gamma_4 = gamma_2, gamma_3 = -gamma_1, eq 21):
//   tan(gamma_2 / 2) = mu tan(gamma_1 / 2),  mu = sin((alpha_1 + alpha_2)/2) / sin((alpha_1 - alpha_2)/2)
// (eqs 22, 23, signed; the sign of mu is the kernel's), parameterized as
//   kMajorLinear (eqs 24, 25): gamma_2 = gamma_4 = pi t,   gamma_1 = -gamma_3 = 2 atan(tan(pi t/2) / mu)
//   kSymmetric   (eq 35):      gamma_2 = gamma_4 = 2 atan(sqrt|mu| tan(pi t/2)),
//                              gamma_1 = -gamma_3 = 2 atan(sgn(mu) tan(pi t/2) / sqrt|mu|)
// each times `sign` (+1: folds 2 and 4 valleys; -1 the mirror branch).
// Angles radians; lengths the caller's unit.
#include <array>

#include "design/sorce/sorce_profile.hpp"

namespace rigidfold::sorce {

using VertexSectors = std::array<double, 4>;  // alpha_1..alpha_4, radians

enum class VertexParameterization {
  kMajorLinear,  // eqs 24-25
  kSymmetric,    // eq 35
};

// eq 23. Throws InputError("sectors") unless flat-foldable (kernel validate_flat_foldable,
// tolerance 1e-9 rad) and alpha_1 != alpha_2 (mu infinite: folds 1, 3 stay flat).
double fold_angle_multiplier(const VertexSectors& sectors);

// gamma_1..gamma_4 (t) as above; sign = +1 or -1.
std::array<ScalarFunction, 4> vertex_fold_angles(const VertexSectors& sectors, VertexParameterization kind,
                                                 double sign = 1.0);

struct SorceVertex {
  VertexSectors sectors{};
  std::array<ScalarFunction, 4> gamma;   // fold angles
  std::array<ScalarFunction, 4> offset;  // z_i(t) of panel i (sector alpha_i)
  std::array<FoldMotion, 4> folds;       // fold j: left panel alpha_{j-1}, right alpha_j
};

// Assembles the four folds' motions: fold j gets gamma_j, z_left = offset of panel j - 1
// (panel 4 for fold 1), z_right = offset of panel j, the panels' thicknesses and split[j]
// (empty: not split).
SorceVertex sorce_vertex(const VertexSectors& sectors, const std::array<ScalarFunction, 4>& gamma,
                         const std::array<ScalarFunction, 4>& offset, const std::array<double, 4>& thickness,
                         const std::array<VectorFunction, 4>& split);
// No fold split. (An overload, not a "= {}" default argument: clang 14 then leaves
// std::function's default constructor undefined at link time in the sanitizer build.)
SorceVertex sorce_vertex(const VertexSectors& sectors, const std::array<ScalarFunction, 4>& gamma,
                         const std::array<ScalarFunction, 4>& offset, const std::array<double, 4>& thickness);

// A vertex split along its collinear folds 1 and 3 (alpha_1 + alpha_2 = pi, e.g. the
// bird's-foot vertex), the 3D offset perpendicular to the plane of folds 1 and 3 with
// scalar size d(t): in the folds' normal planes d_1 = d u(gamma_1/2), d_3 = d u(gamma_3/2)
// (eqs 58, 59). Throws InputError("sectors") if folds 1 and 3 are not collinear (1e-9 rad).
std::array<VectorFunction, 4> collinear_split(const VertexSectors& sectors, const std::array<ScalarFunction, 4>& gamma,
                                              const ScalarFunction& d);

// Circular joints by construction (section 11, eqs 62-69) on a vertex split along folds 1
// and 3: every panel offset z_i = -r tan(gamma_2/4) (folds 2 and 4 circular CORE joints of
// radius r, eqs 62, 63), and d(t) of eq 69 (with gamma_split = gamma_3) so that fold 3 is a
// circular joint of radius r as well; fold 1 takes the same d (eq 58) and is what results.
// r = half the panel thickness; every panel gets thickness 2 r.
SorceVertex circular_split_vertex(const VertexSectors& sectors, VertexParameterization kind, double r);

}  // namespace rigidfold::sorce
