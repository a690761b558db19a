#include "kernel/energy/crease_stiffness.hpp"

#include <cmath>
#include <string>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold {

namespace {
void require_positive(double value, const char* place) {
  if (!std::isfinite(value) || !(value > 0.0))
    throw InputError(place, "must be a finite number > 0, got " + std::to_string(value));
}
void require_nonnegative(double value, const char* place) {
  if (!std::isfinite(value) || value < 0.0)
    throw InputError(place, "stiffness must be a finite number >= 0, got " + std::to_string(value));
}
}  // namespace

double flexure_stiffness(double youngs_modulus, double width, double thickness, double length) {
  require_positive(youngs_modulus, "youngs_modulus");
  require_positive(width, "width");
  require_positive(thickness, "thickness");
  require_positive(length, "length");
  // Second moment of the strip's cross-section about its neutral axis, then k = E I / l.
  const double second_moment = width * thickness * thickness * thickness / 12.0;
  const double k = youngs_modulus * second_moment / length;
  if (!std::isfinite(k) || !(k > 0.0))
    throw InputError("thickness", "the stiffness E b h^3 / (12 l) is not a finite positive number");
  return k;
}

Eigen::VectorXd stiffness_by_assignment(const CreasePattern& pattern, const StiffnessByAssignment& k) {
  require_nonnegative(k.mountain, "stiffness.mountain");
  require_nonnegative(k.valley, "stiffness.valley");
  require_nonnegative(k.unassigned, "stiffness.unassigned");
  Eigen::VectorXd out = Eigen::VectorXd::Zero(pattern.num_edges());
  for (int e = 0; e < pattern.num_edges(); ++e) {
    switch (pattern.assignments[e]) {
      case Assignment::Mountain: out[e] = k.mountain; break;
      case Assignment::Valley: out[e] = k.valley; break;
      case Assignment::Unassigned: out[e] = k.unassigned; break;
      default: break;  // B, C: not hinges; F, J: held flat, no spring to strain
    }
  }
  return out;
}

}  // namespace rigidfold
