#include "design/waterbomb/split_fold_kinematics.hpp"

#include <cmath>
#include <string>

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

namespace {
// The argument of eq. (3.16): cos f.
double cos_f(int n, double b, double theta) {
  const double beta = 2.0 * kPi / n;
  const double ct = std::cos(theta), st = std::sin(theta);
  const double d = std::acos(std::fmin(1.0, ct * ct + st * st * std::cos(beta)));
  const double xi = std::acos(std::fmax(-1.0, std::fmin(1.0, std::tan(d / 2) / std::tan(theta))));
  const double cb2 = std::cos(b / 2), sb2 = std::sin(b / 2);
  return cb2 * cb2 * std::cos(d) + std::sin(b) * std::sin(d) * std::sin(xi) +
         sb2 * sb2 * (std::cos(xi) * std::cos(xi) - std::cos(d) * std::sin(xi) * std::sin(xi));
}
}  // namespace

SplitFoldRange split_fold_range(int n, double b) {
  split_fold_angles_printed(n, b, kPi / 2 - 0.1);  // checks n and b
  // Golden section for the maximum of cos f on (0, pi/2).
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 1e-9, hi = kPi / 2 - 1e-9;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = cos_f(n, b, x1), f2 = cos_f(n, b, x2);
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    if (f1 < f2) {
      lo = x1; x1 = x2; f1 = f2;
      x2 = lo + g * (hi - lo); f2 = cos_f(n, b, x2);
    } else {
      hi = x2; x2 = x1; f2 = f1;
      x1 = hi - g * (hi - lo); f1 = cos_f(n, b, x1);
    }
  }
  SplitFoldRange r;
  // Just above the contact: below it (3.19) returns the reflected, non-physical gamma_v, and
  // the golden section places the maximum only to ~1e-8 rad.
  r.theta_min = 0.5 * (lo + hi) + 1e-7;
  // The printed forms may break down before that contact (b large against alpha: an acos
  // argument leaves [-1, 1], or (3.21)'s atan jumps): walk from flat toward each end on a
  // grid, requiring the forms to be defined and the angle that moves monotonically on that
  // side (gamma_m below flat, gamma_v above) to keep moving the same way; the first grid
  // point that fails bounds the range, bisected to 1e-12 rad.
  auto angles = [&](double theta, FoldPair* out) {
    try {
      *out = split_fold_angles_printed(n, b, theta);
      return std::isfinite(out->gamma_m) && std::isfinite(out->gamma_v);
    } catch (const InputError&) {
      return false;
    }
  };
  constexpr int kWalk = 4096;
  {
    FoldPair prev, cur;
    double good = kPi / 2 - 1e-6;
    angles(good, &prev);
    for (int i = 1; i <= kWalk; ++i) {
      const double t = kPi / 2 - 1e-6 - (kPi / 2 - 1e-6 - r.theta_min) * i / kWalk;
      // Below flat gamma_m falls as theta falls.
      if (angles(t, &cur) && cur.gamma_m <= prev.gamma_m) {
        good = t;
        prev = cur;
        continue;
      }
      double bad = t;
      for (int it = 0; it < 60 && good - bad > 1e-12; ++it) {
        const double mid = 0.5 * (good + bad);
        FoldPair m;
        (angles(mid, &m) && m.gamma_m <= prev.gamma_m ? good : bad) = mid;
      }
      r.theta_min = good;
      r.lower_is_contact = false;
      break;
    }
  }
  // Far side: the mirror of the theta* state, (gamma_m, gamma_v) = (-gamma_v*, -gamma_m*).
  // Matched on gamma_v = -gamma_m(theta*): gamma_m is smooth at theta* while gamma_v has a
  // square-root onset there, so gamma_v(theta*) is not resolved from theta* in double.
  const double target = -split_fold_angles_printed(n, b, r.theta_min).gamma_m;
  double a = kPi / 2 + 1e-9, c = kPi - 1e-9;
  {
    FoldPair prev, cur;
    double good = kPi / 2 + 1e-6;
    angles(good, &prev);
    for (int i = 1; i <= kWalk; ++i) {
      const double t = kPi / 2 + 1e-6 + (kPi / 2 - 2e-6) * i / kWalk;
      const bool ok = angles(t, &cur) && cur.gamma_v >= prev.gamma_v;
      if (ok && cur.gamma_v < target) {
        good = t;
        prev = cur;
        continue;
      }
      if (ok) {  // the mirror contact lies in (good, t]
        a = good;
        c = t;
        break;
      }
      double bad = t;
      for (int it = 0; it < 60 && bad - good > 1e-12; ++it) {
        const double mid = 0.5 * (good + bad);
        FoldPair m;
        (angles(mid, &m) && m.gamma_v >= prev.gamma_v ? good : bad) = mid;
      }
      r.theta_max = good;
      r.upper_is_contact = false;
      return r;
    }
  }
  for (int it = 0; it < 200 && c - a > 1e-15; ++it) {
    const double mid = 0.5 * (a + c);
    FoldPair m;
    if (!angles(mid, &m)) {
      c = mid;  // past the printed forms' own domain: beyond the contact
      continue;
    }
    (m.gamma_v < target ? a : c) = mid;
  }
  r.theta_max = 0.5 * (a + c);
  return r;
}

FoldPair split_fold_angles(int n, double b, double theta) {
  const SplitFoldRange r = split_fold_range(n, b);
  if (!std::isfinite(theta) || theta < r.theta_min || theta > r.theta_max)
    throw InputError("theta", "outside the split-fold model's contact limits [" + std::to_string(to_degrees(r.theta_min)) +
                                  ", " + std::to_string(to_degrees(r.theta_max)) + "] deg (non-adjacent facets touch)");
  return split_fold_angles_printed(n, b, theta);
}

}  // namespace rigidfold::waterbomb
