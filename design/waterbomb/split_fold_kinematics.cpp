#include "design/waterbomb/split_fold_kinematics.hpp"

#include <cmath>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::waterbomb {

namespace {
double checked_acos(double v, const char* what) {
  // A rounding step past +-1 is clamped; anything further is outside the model.
  if (!(std::fabs(v) <= 1.0 + 1e-12)) throw InputError("theta", std::string("outside the split-fold model's range (") + what + ")");
  return std::acos(std::fmax(-1.0, std::fmin(1.0, v)));
}
}  // namespace

FoldPair split_fold_angles_printed(int n, double b, double theta) {
  sector_angle(n);  // checks n
  if (!std::isfinite(b) || !(b > 0.0) || !(b < kPi / n)) throw InputError("b", "the split width must lie in (0, 180/n) deg");
  if (!std::isfinite(theta) || !(theta > 0.0) || !(theta < kPi)) throw InputError("theta", "must lie in (0, 180) deg");
  const double a = (kPi - n * b) / n;  // (3.13)
  const double beta = 2.0 * kPi / n;   // (3.14)
  const double ct = std::cos(theta), st = std::sin(theta);
  const double d = checked_acos(ct * ct + st * st * std::cos(beta), "d");              // (3.17)
  const double xi = checked_acos(std::tan(d / 2) / std::tan(theta), "xi");             // (3.18)
  const double cb2 = std::cos(b / 2), sb2 = std::sin(b / 2);
  const double f = checked_acos(cb2 * cb2 * std::cos(d) + std::sin(b) * std::sin(d) * std::sin(xi) +
                                    sb2 * sb2 * (std::cos(xi) * std::cos(xi) - std::cos(d) * std::sin(xi) * std::sin(xi)),
                                "f");                                                   // (3.16)
  const double gm = -checked_acos(std::sin(f / 2) / (std::sin(a) * cb2) - std::tan(b / 2) / std::tan(a),
                                  "gamma_m");                                           // (3.15)
  const double phi = kPi - checked_acos(sb2 / (std::sin(a) * std::cos(f / 2)) - std::tan(f / 2) / std::tan(a), "phi");  // (3.20)
  const double k1 = std::cos(d) * std::cos(f) * cb2, k2 = cb2, k3 = std::sin(d) * std::cos(f) * sb2;  // (3.25)-(3.27)
  const double k4 = std::cos(d) * std::sin(f) * sb2, k5 = std::sin(d) * std::sin(f) * cb2;            // (3.28)-(3.29)
  const double k6 = std::sin(d) * std::sin(f);                                                         // (3.30)
  const double h1 = k1 - k2 + std::sin(xi) * k3, h2 = -k4 + std::sin(xi) * k5;                         // (3.22)-(3.23)
  const double h3 = (theta <= kPi / 2 ? 1.0 : -1.0) * std::cos(xi) * k6;                               // (3.24)
  const double disc = h3 * h3 - h1 * h1 + h2 * h2;
  if (!(disc >= -1e-12)) throw InputError("theta", "outside the split-fold model's range (eta)");
  const double eta = 2.0 * std::atan((-h3 + std::sqrt(std::fmax(disc, 0.0))) / (h1 - h2));  // (3.21)
  const double gv = theta <= kPi / 2 ? phi - eta : phi + eta;                                // (3.19)
  return {gm, gv};
}

}  // namespace rigidfold::waterbomb
