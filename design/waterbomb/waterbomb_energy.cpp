#include "design/waterbomb/waterbomb_energy.hpp"

#include <cmath>
#include <string>

#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::waterbomb {

const char* to_string(EquilibriumKind kind) {
  switch (kind) {
    case EquilibriumKind::kMinimum: return "minimum";
    case EquilibriumKind::kMaximum: return "maximum";
    case EquilibriumKind::kCuspMaximum: return "cusp maximum (flat state)";
    case EquilibriumKind::kCuspMinimum: return "cusp minimum (flat state)";
  }
  return "?";
}

WaterbombSprings springs_at_rest_theta(int n, double theta0, double k_m, double k_v) {
  const double limit = theta_limit(n);  // checks n
  if (!std::isfinite(theta0) || theta0 < 0.0 || theta0 > limit)
    throw InputError("theta0", "the rest angle must lie in [0, " + std::to_string(to_degrees(limit)) + "] deg, got " +
                                   std::to_string(to_degrees(theta0)) + " deg");
  if (!std::isfinite(k_m) || k_m < 0.0) throw InputError("k_m", "stiffness must be finite and >= 0");
  if (!std::isfinite(k_v) || k_v < 0.0) throw InputError("k_v", "stiffness must be finite and >= 0");
  if (k_m == 0.0 && k_v == 0.0) throw InputError("k_m", "at least one stiffness must be > 0");
  return WaterbombSprings{n, k_m, k_v, waterbomb_fold_angles(n, theta0)};
}

double waterbomb_energy(const WaterbombSprings& s, double theta) {
  const FoldPair g = waterbomb_fold_angles(s.n, theta);
  const double dm = g.gamma_m - s.rest.gamma_m, dv = g.gamma_v - s.rest.gamma_v;
  return 0.5 * s.n * (s.k_m * dm * dm + s.k_v * dv * dv);
}

double waterbomb_energy_slope(const WaterbombSprings& s, double theta, int side) {
  const FoldPair g = waterbomb_fold_angles(s.n, theta);
  const FoldPair d = waterbomb_fold_angle_derivatives(s.n, theta, side);
  return s.n * (s.k_m * (g.gamma_m - s.rest.gamma_m) * d.gamma_m + s.k_v * (g.gamma_v - s.rest.gamma_v) * d.gamma_v);
}

namespace {

PathEquilibrium make_state(const WaterbombSprings& s, EquilibriumKind kind, double theta) {
  PathEquilibrium e;
  e.kind = kind;
  e.theta = theta;
  e.angles = waterbomb_fold_angles(s.n, theta);
  e.energy = waterbomb_energy(s, theta);
  e.slope_residual = std::fabs(waterbomb_energy_slope(s, theta));
  return e;
}

// Root of the slope in [lo, hi] with slope(lo), slope(hi) of opposite signs, bisected until
// the bracket is two adjacent doubles; returns the end with the smaller |slope|.
// flo, fhi: the slopes at the ends (one-sided where an end is the flat state).
double bisect_slope(const WaterbombSprings& s, double lo, double hi, double flo, double fhi) {
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double fm = waterbomb_energy_slope(s, mid);
    if (fm == 0.0) return mid;
    if ((fm < 0.0) == (flo < 0.0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
      fhi = fm;
    }
  }
  return std::fabs(flo) <= std::fabs(fhi) ? lo : hi;
}

void scan_side(const WaterbombSprings& s, double a, double b, std::vector<PathEquilibrium>& out) {
  constexpr int kIntervals = 512;
  double t0 = a, f0 = waterbomb_energy_slope(s, a, +1);
  for (int i = 1; i <= kIntervals; ++i) {
    const double t1 = (i == kIntervals) ? b : a + (b - a) * i / kIntervals;
    // At the flat end use the one-sided slope of this side.
    const int side = (t1 == kPi / 2) ? -1 : +1;
    const double f1 = waterbomb_energy_slope(s, t1, side);
    if (i < kIntervals && f1 == 0.0) {  // an exact grid root: classify by its neighbours next step
      out.push_back(make_state(s, f0 < 0 ? EquilibriumKind::kMinimum : EquilibriumKind::kMaximum, t1));
    } else if ((f0 < 0.0 && f1 > 0.0) || (f0 > 0.0 && f1 < 0.0)) {
      // The slope is continuous inside one side of flat (a one-sided value at the flat
      // end), so a sign change brackets a root inside the interval.
      const double root = bisect_slope(s, t0, t1, f0, f1);
      out.push_back(make_state(s, f0 < 0.0 ? EquilibriumKind::kMinimum : EquilibriumKind::kMaximum, root));
    }
    t0 = t1;
    f0 = f1;
  }
}

}  // namespace

std::vector<PathEquilibrium> waterbomb_path_equilibria(const WaterbombSprings& s) {
  const double limit = theta_limit(s.n);
  const double flat = kPi / 2;
  std::vector<PathEquilibrium> out;
  // Contact limit at theta = 0: a minimum there if V rises away from it.
  if (waterbomb_energy_slope(s, 0.0) > 0.0) {
    PathEquilibrium e = make_state(s, EquilibriumKind::kMinimum, 0.0);
    e.at_validity_limit = true;
    out.push_back(e);
  }
  scan_side(s, 0.0, flat, out);
  {
    PathEquilibrium e = make_state(s, EquilibriumKind::kCuspMaximum, flat);
    e.slope_below = waterbomb_energy_slope(s, flat, -1);
    e.slope_above = waterbomb_energy_slope(s, flat, +1);
    e.slope_residual = 0.0;
    if (e.slope_below > 0.0 && e.slope_above < 0.0)
      out.push_back(e);
    else if (e.slope_below < 0.0 && e.slope_above > 0.0) {
      e.kind = EquilibriumKind::kCuspMinimum;
      out.push_back(e);
    }
  }
  scan_side(s, flat, limit, out);
  if (waterbomb_energy_slope(s, limit) < 0.0) {
    PathEquilibrium e = make_state(s, EquilibriumKind::kMinimum, limit);
    e.at_validity_limit = true;
    out.push_back(e);
  }
  return out;
}

}  // namespace rigidfold::waterbomb
