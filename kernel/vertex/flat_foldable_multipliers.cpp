#include "kernel/vertex/flat_foldable_multipliers.hpp"
#include "kernel/math/angle_units.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rigidfold {

namespace {

// Below this a direction entry is rounding noise of sin/cos at an exact zero
// (e.g. cos(pi/2) = 6e-17): that crease stays flat in the mode.
constexpr double kZeroDirection = 1e-15;

double signed_ratio(double num, double den) {
  if (den != 0.0) return num / den;
  if (num == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return num > 0.0 ? std::numeric_limits<double>::infinity()
                   : -std::numeric_limits<double>::infinity();
}

std::array<double, 4> mode_direction(const std::array<double, 4>& sectors, FlatFoldMode mode) {
  const double d = 0.5 * (sectors[1] - sectors[0]);
  const double s = 0.5 * (sectors[1] + sectors[0]);
  std::array<double, 4> w{};
  if (mode == FlatFoldMode::kEqual13) {
    w = {std::sin(d), -std::sin(s), -std::sin(d), -std::sin(s)};
  } else {
    w = {std::cos(d), -std::cos(s), std::cos(d), std::cos(s)};
  }
  for (double& x : w) {
    if (std::abs(x) < kZeroDirection) x = 0.0;
  }
  return w;
}

}  // namespace

std::array<std::array<double, 4>, 2> flat_fold_directions(const std::array<double, 4>& sectors) {
  // Both calls inline here, so the compiler pairs sin and cos of d and of s (sincos).
  return {mode_direction(sectors, FlatFoldMode::kEqual13), mode_direction(sectors, FlatFoldMode::kEqual02)};
}

const char* to_string(FlatFoldMode mode) {
  return mode == FlatFoldMode::kEqual13 ? "equal13" : "equal02";
}

void validate_flat_foldable(const std::array<double, 4>& sectors, double tol) {
  for (int i = 0; i < 4; ++i) {
    if (!(sectors[i] > 0.0 && sectors[i] < kPi)) {
      std::ostringstream msg;
      msg << "flat-foldable vertex: sector " << i << " = " << sectors[i]
          << " rad is not in (0, pi)";
      throw std::invalid_argument(msg.str());
    }
  }
  for (int i = 0; i < 2; ++i) {
    const double excess = sectors[i] + sectors[i + 2] - kPi;
    if (!(std::abs(excess) <= tol)) {
      std::ostringstream msg;
      msg << "flat-foldable vertex: sector " << i << " + sector " << i + 2 << " - pi = "
          << excess << " rad (Kawasaki needs 0 within " << tol << ")";
      throw std::invalid_argument(msg.str());
    }
  }
}

FlatFoldMultipliers flat_fold_multipliers(const std::array<double, 4>& sectors,
                                          FlatFoldMode mode, double tol) {
  validate_flat_foldable(sectors, tol);
  FlatFoldMultipliers out;
  out.direction = mode_direction(sectors, mode);
  const auto& w = out.direction;
  for (int i = 0; i < 4; ++i) {
    out.step[i] = signed_ratio(w[(i + 1) % 4], w[i]);
    out.from_first[i] = signed_ratio(w[i], w[0]);
  }
  // The odd crease is the one entry of w whose sign differs from the other three;
  // with a zero entry one pair stays flat and no crease is odd.
  int positives = 0, negatives = 0;
  for (double x : w) {
    positives += x > 0.0;
    negatives += x < 0.0;
  }
  if (positives + negatives == 4 && (positives == 1 || negatives == 1)) {
    const bool odd_is_positive = positives == 1;
    for (int i = 0; i < 4; ++i) {
      if ((w[i] > 0.0) == odd_is_positive) out.odd_crease = i;
    }
  }
  return out;
}

std::array<double, 4> flat_fold_angles(const std::array<double, 4>& sectors, FlatFoldMode mode,
                                       double rho_driver, int driver, double tol) {
  if (driver < 0 || driver > 3) {
    throw std::invalid_argument("flat-foldable vertex: driving crease " +
                                std::to_string(driver) + " is not in 0..3");
  }
  validate_flat_foldable(sectors, tol);
  const std::array<double, 4> w = mode_direction(sectors, mode);
  if (w[driver] == 0.0) {
    throw std::invalid_argument(std::string("flat-foldable vertex: crease ") +
                                std::to_string(driver) + " stays flat in mode " +
                                to_string(mode) + " and cannot drive it");
  }
  const double rho = std::remainder(rho_driver, 2.0 * kPi);
  // tan(rho_i/2) = (w_i / w_driver) tan(rho/2), written with the half-angle sine and
  // cosine so that rho = +-pi (tan = infinity) needs no special case.
  const double sign = w[driver] > 0.0 ? 1.0 : -1.0;
  const double sh = std::sin(0.5 * rho), ch = std::cos(0.5 * rho);
  std::array<double, 4> out{};
  for (int i = 0; i < 4; ++i) {
    out[i] = 2.0 * std::atan2(sign * w[i] * sh, std::abs(w[driver]) * ch);
  }
  out[driver] = rho;
  return out;
}

}  // namespace rigidfold
