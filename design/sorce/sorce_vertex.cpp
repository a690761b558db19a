#include "design/sorce/sorce_vertex.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/vertex/flat_foldable_multipliers.hpp"

namespace rigidfold::sorce {

double fold_angle_multiplier(const VertexSectors& sectors) {
  try {
    validate_flat_foldable(sectors);
  } catch (const std::invalid_argument& e) {
    throw InputError("sectors", e.what());
  }
  const double den = std::sin((sectors[0] - sectors[1]) / 2);
  if (std::abs(den) < 1e-9) throw InputError("sectors", "alpha_1 = alpha_2: mu is infinite (folds 1 and 3 stay flat)");
  return std::sin((sectors[0] + sectors[1]) / 2) / den;
}

std::array<ScalarFunction, 4> vertex_fold_angles(const VertexSectors& sectors, VertexParameterization kind, double sign) {
  if (sign != 1.0 && sign != -1.0) throw InputError("sign", "must be +1 or -1");
  const double mu = fold_angle_multiplier(sectors);
  double k_major = 1.0, k_minor = 1.0 / mu;  // eqs 24, 25
  if (kind == VertexParameterization::kSymmetric) {  // eq 35
    k_major = std::sqrt(std::abs(mu));
    k_minor = (mu > 0 ? 1.0 : -1.0) / k_major;
  }
  ScalarFunction major = kind == VertexParameterization::kMajorLinear ? linear_fold(sign * kPi) : tan_half_fold(sign * k_major);
  return {tan_half_fold(sign * k_minor), major, tan_half_fold(-sign * k_minor), major};
}

SorceVertex sorce_vertex(const VertexSectors& sectors, const std::array<ScalarFunction, 4>& gamma,
                         const std::array<ScalarFunction, 4>& offset, const std::array<double, 4>& thickness) {
  const std::array<VectorFunction, 4> no_split{};
  return sorce_vertex(sectors, gamma, offset, thickness, no_split);
}

SorceVertex sorce_vertex(const VertexSectors& sectors, const std::array<ScalarFunction, 4>& gamma,
                         const std::array<ScalarFunction, 4>& offset, const std::array<double, 4>& thickness,
                         const std::array<VectorFunction, 4>& split) {
  SorceVertex v;
  v.sectors = sectors;
  v.gamma = gamma;
  v.offset = offset;
  for (int j = 0; j < 4; ++j) {
    const int left = (j + 3) % 4, right = j;
    if (!gamma[j] || !offset[left] || !offset[right]) throw InputError("fold " + std::to_string(j + 1), "missing gamma or offset");
    FoldMotion& f = v.folds[j];
    f.gamma = gamma[j];
    f.z_left = offset[left];
    f.z_right = offset[right];
    f.d = split[j];
    f.thickness_left = thickness[left];
    f.thickness_right = thickness[right];
  }
  return v;
}

std::array<VectorFunction, 4> collinear_split(const VertexSectors& sectors, const std::array<ScalarFunction, 4>& gamma,
                                              const ScalarFunction& d) {
  if (std::abs(sectors[0] + sectors[1] - kPi) > 1e-9)
    throw InputError("sectors", "folds 1 and 3 are not collinear (alpha_1 + alpha_2 != 180 deg)");
  std::array<VectorFunction, 4> split;
  split[0] = split_offset_along_half_angle(d, gamma[0]);  // eq 58
  split[2] = split_offset_along_half_angle(d, gamma[2]);  // eq 59
  return split;
}

SorceVertex circular_split_vertex(const VertexSectors& sectors, VertexParameterization kind, double r) {
  if (!(r > 0.0 && std::isfinite(r))) throw InputError("r", "must be a finite length > 0");
  const auto gamma = vertex_fold_angles(sectors, kind);
  const ScalarFunction z = circular_offset(r, gamma[1]);  // eqs 62, 63 (gamma_4 = gamma_2)
  const ScalarFunction d = circular_split_offset(r, gamma[2], gamma[1]);  // eq 69
  return sorce_vertex(sectors, gamma, {z, z, z, z}, {2 * r, 2 * r, 2 * r, 2 * r}, collinear_split(sectors, gamma, d));
}

}  // namespace rigidfold::sorce
