// Example: inverse design of an origami string (a strip of Miura vertices). A known string is
// folded forward; its spine points become the design target; the closed-form design
// (design/strings/string_inverse.hpp) must give back the same pattern angles.
//   design_string
// Exit 0 when the design is feasible and recovers every alpha to 1e-9 rad, 1 otherwise.
#include <cmath>
#include <iostream>
#include <vector>

#include "design/strings/string_inverse.hpp"
#include "design/strings/string_kinematics.hpp"
#include "kernel/math/angle_units.hpp"

int main() {
  using namespace rigidfold;
  using namespace rigidfold::design;
  MiuraString known;
  for (int k = 0; k < 6; ++k) {
    known.alpha1.push_back(to_radians(40.0 + 3.0 * k));
    known.alpha2.push_back(to_radians(55.0 - 2.0 * k));
  }
  known.lengths.assign(known.size() + 1, 1.0);
  const double theta0 = to_radians(30.0);
  const StringState folded = string_forward(known, theta0);

  CurveDesignOptions options;
  options.theta0 = theta0;  // the fold state the target was taken at; the roll is searched
  const CurveDesign design = design_from_curve(folded.spine, options);
  double worst = 0;
  for (int k = 0; k < known.size(); ++k)
    worst = std::max({worst, std::fabs(design.string.alpha1[k] - known.alpha1[k]),
                      std::fabs(design.string.alpha2[k] - known.alpha2[k])});
  std::cout << "design " << (design.feasible ? "feasible" : "infeasible") << " at theta0 "
            << to_degrees(design.theta0) << " deg, roll " << to_degrees(design.roll)
            << " deg; largest alpha error against the known string " << worst << " rad\n";
  return design.feasible && worst <= 1e-9 ? 0 : 1;
}
