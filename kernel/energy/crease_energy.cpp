#include "kernel/energy/crease_energy.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold {

namespace {
void require_size(const CreaseSprings& s, const Eigen::VectorXd& rho) {
  if (s.stiffness.size() != s.rest_angles.size() || rho.size() != s.stiffness.size())
    throw std::invalid_argument("crease_energy: stiffness, rest angles and fold angles need one entry per edge");
}
}  // namespace

CreaseSprings make_crease_springs(const CreasePattern& pattern, const Eigen::VectorXd& stiffness,
                                  const Eigen::VectorXd& rest_angles) {
  const int m = pattern.num_edges();
  if (stiffness.size() != m)
    throw InputError("stiffness", "needs one value per edge (" + std::to_string(m) + "), got " +
                                      std::to_string(stiffness.size()));
  if (rest_angles.size() != m)
    throw InputError("rest_angles", "needs one value per edge (" + std::to_string(m) + "), got " +
                                        std::to_string(rest_angles.size()));
  for (int e = 0; e < m; ++e) {
    if (!std::isfinite(stiffness[e]) || stiffness[e] < 0.0)
      throw InputError("stiffness[" + std::to_string(e) + "]",
                       "must be a finite number >= 0, got " + std::to_string(stiffness[e]));
    // Equality allowed: a crease folded flat onto itself rests at +-pi.
    if (!std::isfinite(rest_angles[e]) || std::fabs(rest_angles[e]) > kPi)
      throw InputError("rest_angles[" + std::to_string(e) + "]",
                       "must be a finite angle in [-180, 180] deg, got " + std::to_string(to_degrees(rest_angles[e])) +
                           " deg");
  }
  return CreaseSprings{stiffness, rest_angles};
}

double crease_energy(const CreaseSprings& springs, const Eigen::VectorXd& edge_angles) {
  require_size(springs, edge_angles);
  const Eigen::ArrayXd d = (edge_angles - springs.rest_angles).array();
  return 0.5 * (springs.stiffness.array() * d * d).sum();
}

Eigen::VectorXd crease_energy_gradient(const CreaseSprings& springs, const Eigen::VectorXd& edge_angles) {
  require_size(springs, edge_angles);
  return (springs.stiffness.array() * (edge_angles - springs.rest_angles).array()).matrix();
}

Eigen::SparseMatrix<double> crease_energy_hessian(const CreaseSprings& springs) {
  const Eigen::Index m = springs.stiffness.size();
  Eigen::SparseMatrix<double> H(m, m);
  H.reserve(Eigen::VectorXi::Constant(m, 1));
  for (Eigen::Index e = 0; e < m; ++e) H.insert(e, e) = springs.stiffness[e];
  H.makeCompressed();
  return H;
}

}  // namespace rigidfold
