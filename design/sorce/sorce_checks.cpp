#include "design/sorce/sorce_checks.hpp"

#include <cmath>

#include "kernel/math/number_text.hpp"

namespace rigidfold::sorce {

SorceCheckVerdict check_sorce(const CreasePattern& pattern, const PatternSorce& s) {
  constexpr double kRelative = 1e-9;
  constexpr double kRolled = 1e-8;
  Eigen::Vector3d lo = pattern.vertices.at(0), hi = lo;
  for (const Eigen::Vector3d& v : pattern.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const double size = (hi - lo).norm();
  const std::vector<std::pair<std::string, double>> figures{
      {"consistency", s.checks.consistency},  {"pitch", s.checks.pitch},
      {"closure_knots", s.checks.closure_knots}, {"contact_3d", s.checks.contact},
      {"rolling_residual", s.checks.rolling},    {"contact_residual", s.checks.contact_planar},
      {"rolled_gamma", s.checks.rolled_gamma},   {"rolled_translation", s.checks.rolled_translation}};
  SorceCheckVerdict v;
  for (const auto& [name, value] : figures) {
    const bool length = name == "contact_3d" || name == "rolling_residual" || name == "contact_residual" ||
                        name == "rolled_translation";
    const bool rolled = name == "rolled_gamma" || name == "rolled_translation";  // an integration, not a formula
    const double bound = (rolled ? kRolled : kRelative) * (length ? size : 1.0);
    v.bounds.emplace_back(name, bound);
    if (v.passed && !(value <= bound)) {  // NaN fails
      v.passed = false;
      v.worst = value;
      v.failure = name + " " + short_text(value) + " > " + short_text(bound);
    }
  }
  return v;
}

}  // namespace rigidfold::sorce
