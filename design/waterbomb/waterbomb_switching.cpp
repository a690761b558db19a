#include "design/waterbomb/waterbomb_switching.hpp"

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "design/waterbomb/waterbomb_force.hpp"
#include "design/waterbomb/waterbomb_loaded_path.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold::waterbomb {

SwitchingForce switching_force(const WaterbombSprings& springs, double theta0, double r) {
  if (!(theta0 >= 0.0 && theta0 < kPi / 2)) throw InputError("theta0", "the rest state must lie before flat (theta0 < 90 deg)");
  if (!(r > 0.0 && std::isfinite(r))) throw InputError("r", "must be a finite length > 0");
  auto force = [&](double th) { return waterbomb_force(springs, theta0, r, th, th == kPi / 2 ? -1 : 0).force; };
  // F = 0 at the rest state; sin(theta) = 0 at theta0 = 0, so start the scan just after it.
  const double start = theta0 > 0.0 ? theta0 : 1e-9;
  constexpr int kGrid = 1024;
  SwitchingForce best{force(kPi / 2), kPi / 2, true};
  for (int i = 0; i < kGrid; ++i) {
    const double th = start + (kPi / 2 - start) * i / kGrid;
    const double f = force(th);
    if (f > best.force) best = {f, th, false};
  }
  if (!best.at_flat) {
    // Refine the interior maximum between the grid neighbours (Brent, to half the digits in
    // theta, which gives the maximum's value to full precision).
    const double h = (kPi / 2 - start) / kGrid;
    const double lo = std::max(start, best.theta - h), hi = std::min(kPi / 2, best.theta + h);
    std::uintmax_t iterations = 200;
    const auto [th, neg] = boost::math::tools::brent_find_minima([&](double t) { return -force(t); }, lo, hi,
                                                                 std::numeric_limits<double>::digits / 2, iterations);
    if (-neg > best.force) best = {-neg, th, false};
  }
  return best;
}

SwitchingForce switching_force_checked(int n, double theta0, double k_m, double k_v) {
  const WaterbombSprings springs = springs_at_rest_theta(n, theta0, k_m, k_v);
  const double r = std::cos(kPi / n);
  SwitchingForce sw = switching_force(springs, theta0, r);
  const double at = sw.at_flat ? kPi / 2 - 1e-4 : sw.theta;
  const LoadedPoint q = waterbomb_loaded_path(n, theta0, k_m, k_v, {at}).points.at(0);
  sw.general_force = q.force;
  sw.general_gap = std::fabs(q.force - q.force_closed_form);
  if (!q.converged || !(sw.general_gap <= 1e-9 * std::max(1.0, std::fabs(q.force_closed_form))))
    throw NoAnswerError("the general model does not confirm the switching force (reaction force " + round_trip_text(q.force) +
                            " against " + round_trip_text(q.force_closed_form) + " at theta = " +
                            round_trip_text(to_degrees(at)) + " deg)",
                        sw.general_gap);
  return sw;
}

double mountain_stiffness_for_switching_force(int n, double theta0, double k_v, double target, double r) {
  return mountain_stiffness_for_force(
      [&](double k_m) { return switching_force(springs_at_rest_theta(n, theta0, k_m, k_v), theta0, r).force; }, k_v, target);
}

double mountain_stiffness_for_force(const std::function<double(double)>& switching_force_of, double k_v, double target) {
  if (!(target > 0.0 && std::isfinite(target))) throw InputError("target", "the switching force must be a finite number > 0");
  if (!(k_v > 0.0 && std::isfinite(k_v))) throw InputError("k_v", "must be a finite number > 0");
  auto f = [&](double k_m) { return switching_force_of(k_m) - target; };
  const double at_zero = f(0.0);
  if (at_zero > 0.0)
    throw NoAnswerError("even k_m = 0 switches at " + round_trip_text(at_zero + target) + ", above the target " +
                            round_trip_text(target),
                        at_zero);
  double hi = k_v;
  double f_hi = f(hi);
  while (f_hi < 0.0) {
    hi *= 4.0;
    if (hi > 1e12 * k_v) throw NoAnswerError("no k_m up to 1e12 k_v reaches the target switching force", target);
    f_hi = f(hi);
  }
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      f, 0.0, hi, at_zero, f_hi, [](double x, double y) { return std::fabs(x - y) <= 1e-13 * std::max(1.0, std::fabs(y)); },
      iterations);
  const double k_m = 0.5 * (a + b);
  // The answer's own check: its switching force is the target.
  const double miss = std::fabs(f(k_m));
  if (!(miss <= 1e-9 * target))
    throw NoAnswerError("the solved k_m switches " + round_trip_text(miss) + " away from the target", miss);
  return k_m;
}

}  // namespace rigidfold::waterbomb
