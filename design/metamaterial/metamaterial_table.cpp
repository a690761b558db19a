#include "design/metamaterial/metamaterial_table.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "design/metamaterial/line_plot_svg.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold::metamaterial {
namespace {


CorrugatedElement element_of(MetamaterialUnit u) {
  switch (u) {
    case MetamaterialUnit::kElement1: return CorrugatedElement::kElement1;
    case MetamaterialUnit::kElement2: return CorrugatedElement::kElement2;
    case MetamaterialUnit::kElement3: return CorrugatedElement::kElement3;
    case MetamaterialUnit::kSquareTwist: break;
  }
  throw std::invalid_argument("metamaterial: not a corrugated element");
}

// The unit's closed forms at one fold angle (no checks).
MetamaterialRow evaluate(const MetamaterialParams& p, double fold) {
  MetamaterialRow r;
  r.fold = fold;
  if (p.unit == MetamaterialUnit::kSquareTwist) {
    const SquareTwistUnitState s = square_twist_unit(p.square_twist, fold);
    r.second_angle = s.phi;
    r.x = s.L, r.y = s.S, r.H = s.H;
    r.dx = s.dL, r.dy = s.dS, r.dH = s.dH;
    r.nu_in = s.nu_SL, r.nu_out = s.nu_HL;
    return r;
  }
  const CorrugatedElement e = element_of(p.unit);
  const CorrugatedElementState s = corrugated_element(e, p.element, kPi - fold);
  r.second_angle = e == CorrugatedElement::kElement3 ? s.theta : s.phi;
  r.x = s.W, r.y = s.L, r.H = s.H;
  // d/dfold = -d/dphi (fold = pi - phi); the ratios are ratios of derivatives, unchanged.
  r.dx = -s.dW, r.dy = -s.dL, r.dH = -s.dH;
  r.nu_in = s.nu_in, r.nu_out = s.nu_out;
  return r;
}

// Numerator and denominator derivatives of a ratio nu = -(dA/A)/(dB/B).
double numerator(const MetamaterialParams& p, const MetamaterialRow& r, bool out) {
  if (out) return r.dH;
  return p.unit == MetamaterialUnit::kSquareTwist ? r.dx : r.dy;  // dL
}
double denominator(const MetamaterialParams& p, const MetamaterialRow& r, bool out) {
  if (p.unit == MetamaterialUnit::kSquareTwist) return out ? r.dx : r.dy;  // nu_HL: dL; nu_SL: dS
  return r.dx;                                                            // dW
}

double constraint_residual(const MetamaterialParams& p, const MetamaterialRow& r) {
  if (p.unit == MetamaterialUnit::kSquareTwist) {
    const double a = p.square_twist.alpha, t = r.fold, f = r.second_angle;
    return std::fabs(-std::cos(a) * std::cos(t) + std::cos(a) * std::cos(f) - std::sin(a) * std::sin(t) * std::sin(f));
  }
  if (p.unit == MetamaterialUnit::kElement3) {
    const double al = p.element.alpha, be = p.element.beta, phi = kPi - r.fold, th = r.second_angle;
    // (3-26) times cos(theta/2) cos(phi/2): bounded near flat, where tan(phi/2) is not.
    return std::fabs(std::sin(th / 2) * std::cos(phi / 2) * std::cos((be - al) / 2) -
                     std::sin(phi / 2) * std::cos(th / 2) * std::cos((be + al) / 2));
  }
  return 0.0;
}

// max over the three dimensions of |d - fd| / max(1, |d|), fd the 5-point central difference
// with step h, taken as the smaller discrepancy of h = min(1e-4, distance to the ends / 4) and
// h / 4: near flat and the fold limit the derivatives are steep (truncation ~(h / distance)^4
// wants the small step) while the closed forms' acos lose digits (round-off ~eps^(1/2) / h
// wants the large one).
double derivative_error(const MetamaterialParams& p, const MetamaterialRow& r) {
  auto at = [&](double h) {
    const MetamaterialRow m2 = evaluate(p, r.fold - 2 * h), m1 = evaluate(p, r.fold - h);
    const MetamaterialRow p1 = evaluate(p, r.fold + h), p2 = evaluate(p, r.fold + 2 * h);
    auto fd = [&](double MetamaterialRow::*f) { return (m2.*f - 8 * (m1.*f) + 8 * (p1.*f) - p2.*f) / (12 * h); };
    const double ex = std::fabs(r.dx - fd(&MetamaterialRow::x)) / std::max(1.0, std::fabs(r.dx));
    const double ey = std::fabs(r.dy - fd(&MetamaterialRow::y)) / std::max(1.0, std::fabs(r.dy));
    const double eh = std::fabs(r.dH - fd(&MetamaterialRow::H)) / std::max(1.0, std::fabs(r.dH));
    return std::max({ex, ey, eh});
  };
  const double h = std::min({1e-4, r.fold / 4, (kPi - r.fold) / 4});
  return std::min(at(h), at(h / 4));
}

std::string angle_text(double fold) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g deg", to_degrees(fold));
  return buf;
}

// The root of f on [lo, hi] (f(lo), f(hi) of opposite signs) to round-off.
double refine(const std::function<double(double)>& f, double lo, double hi, double flo, double fhi) {
  if (flo == 0) return lo;
  if (fhi == 0) return hi;
  std::uintmax_t iterations = 200;
  const auto [a, b] =
      boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (a + b);
}

bool opposite(double a, double b) { return (a > 0 && b < 0) || (a < 0 && b > 0); }

}  // namespace

std::string unit_name(MetamaterialUnit unit) {
  switch (unit) {
    case MetamaterialUnit::kSquareTwist: return "square-twist";
    case MetamaterialUnit::kElement1: return "element1";
    case MetamaterialUnit::kElement2: return "element2";
    case MetamaterialUnit::kElement3: return "element3";
  }
  return "?";
}

std::vector<std::string> dimension_names(MetamaterialUnit unit) {
  if (unit == MetamaterialUnit::kSquareTwist) return {"L", "S", "H"};
  return {"W", "L", "H"};
}

std::vector<std::string> ratio_names(MetamaterialUnit unit) {
  if (unit == MetamaterialUnit::kSquareTwist) return {"nu_SL", "nu_HL"};
  return {"nu_in", "nu_out"};
}

MetamaterialTable metamaterial_table(const MetamaterialParams& given) {
  // Computed and checked at unit length (a = 1 or l = 1: the closed forms are homogeneous of
  // degree 1 in the lengths), scaled back at the end, so that tiny or huge units get the
  // checks they get at size 1.
  MetamaterialParams params = given;
  double length = 1.0;
  if (given.unit == MetamaterialUnit::kSquareTwist) {
    length = given.square_twist.a;
    if (!(length > 0) || !std::isfinite(length)) throw std::invalid_argument("metamaterial: a must be > 0");
    params.square_twist.a = 1.0;
    params.square_twist.b = given.square_twist.b / length;
    params.square_twist.c = given.square_twist.c / length;
  } else {
    length = given.element.l;
    if (!(length > 0) || !std::isfinite(length)) throw std::invalid_argument("metamaterial: l must be > 0");
    params.element.l = 1.0;
  }
  if (params.samples < 3 || params.samples > 100000)
    throw std::invalid_argument("metamaterial: samples must be between 3 and 100000");
  if (params.unit == MetamaterialUnit::kElement3 &&
      std::fabs(std::cos((params.element.beta + params.element.alpha) / 2)) < 1e-12)
    throw std::invalid_argument("metamaterial: element 3 with alpha + beta = pi is locked ((3-26) pins theta at 0)");
  MetamaterialTable t;
  t.params = params;
  const int n = params.samples;
  t.rows.reserve(n);
  for (int k = 1; k <= n; ++k) {
    const double fold = kPi * k / (n + 1);
    MetamaterialRow r = evaluate(params, fold);
    const double vals[] = {r.second_angle, r.x, r.y, r.H, r.dx, r.dy, r.dH, r.nu_in, r.nu_out};
    for (double v : vals)
      if (!std::isfinite(v)) throw NoAnswerError("metamaterial: a closed form is not finite at fold " + angle_text(fold));
    r.constraint_residual = constraint_residual(params, r);
    if (!(r.constraint_residual <= kConstraintTolerance))
      throw NoAnswerError("metamaterial: constraint residual above 1e-12 at fold " + angle_text(fold),
                          r.constraint_residual);
    r.derivative_error = derivative_error(params, r);
    if (!(r.derivative_error <= kDerivativeTolerance))
      throw NoAnswerError("metamaterial: analytic derivative differs from the finite difference at fold " +
                              angle_text(fold),
                          r.derivative_error);
    if (params.unit == MetamaterialUnit::kSquareTwist) {
      const double sl = square_twist_nu_SL_printed(params.square_twist, r.fold, r.second_angle);
      const double hl = square_twist_nu_HL_printed(params.square_twist, r.fold, r.second_angle);
      const double e = std::max(std::fabs(sl - r.nu_in) / std::max(1.0, std::fabs(r.nu_in)),
                                std::fabs(hl - r.nu_out) / std::max(1.0, std::fabs(r.nu_out)));
      if (!(e <= kDerivativeTolerance))
        throw NoAnswerError("metamaterial: Poisson's ratios differ from the printed (3-32) at fold " + angle_text(fold), e);
    }
    t.max_constraint_residual = std::max(t.max_constraint_residual, r.constraint_residual);
    t.max_derivative_error = std::max(t.max_derivative_error, r.derivative_error);
    t.rows.push_back(r);
  }

  // Stationary points of H: zeros of dH/dfold between rows. Maxima of equal height (to 1e-12
  // relative) keep the smaller fold.
  std::vector<double> stationary;
  for (int k = 0; k + 1 < n; ++k) {
    const MetamaterialRow &a = t.rows[k], &b = t.rows[k + 1];
    if (!opposite(a.dH, b.dH)) continue;
    const double fold = refine([&](double x) { return evaluate(params, x).dH; }, a.fold, b.fold, a.dH, b.dH);
    stationary.push_back(fold);
    if (a.dH > 0) {  // a maximum
      const double h = evaluate(params, fold).H;
      if (!t.has_height_maximum || h > t.height_maximum + 1e-12 * std::fabs(t.height_maximum)) {
        t.has_height_maximum = true;
        t.height_maximum = h;
        t.height_maximum_fold = fold;
      }
    }
  }
  t.height_stationary_points = static_cast<int>(stationary.size());
  if (params.unit == MetamaterialUnit::kSquareTwist) {
    // The closed form's own finder (4096 intervals): its maximum must be one of the table's
    // stationary points, and as high as the table's.
    const SquareTwistHeightMaximum lib = square_twist_height_maximum(params.square_twist);
    double miss = INFINITY;
    for (double f : stationary) miss = std::min(miss, std::fabs(f - lib.theta));
    if (!t.has_height_maximum || !(miss <= 1e-9) ||
        !(std::fabs(lib.height - t.height_maximum) <= 1e-12 * std::fabs(lib.height)))
      throw NoAnswerError("metamaterial: the sampled height maximum misses square_twist_height_maximum at theta " +
                              angle_text(lib.theta) + " (sample more finely)",
                          miss);
  }

  // A dimension that stays at round-off level (element 1 or 2 with alpha = beta: L = 0
  // throughout) leaves the ratios built on it undefined (NaN, no sign changes).
  double biggest = 0, mx = 0, my = 0, mh = 0;
  for (const auto& r : t.rows) {
    mx = std::max(mx, std::fabs(r.x)), my = std::max(my, std::fabs(r.y)), mh = std::max(mh, std::fabs(r.H));
    biggest = std::max({biggest, mx, my, mh});
  }
  const double floor = 1e-12 * biggest;
  t.nu_in_defined = mx > floor && my > floor;
  t.nu_out_defined = mx > floor && mh > floor;
  for (auto& r : t.rows) {
    if (!t.nu_in_defined) r.nu_in = std::nan("");
    if (!t.nu_out_defined) r.nu_out = std::nan("");
  }

  // Sign changes of the two ratios.
  const std::string names[2] = {"nu_in", "nu_out"};
  for (int which = 0; which < 2; ++which) {
    const bool out = which == 1;
    if (!(out ? t.nu_out_defined : t.nu_in_defined)) continue;
    auto nu = [&](const MetamaterialRow& r) { return out ? r.nu_out : r.nu_in; };
    for (int k = 0; k + 1 < n; ++k) {
      const MetamaterialRow &a = t.rows[k], &b = t.rows[k + 1];
      if (!opposite(nu(a), nu(b))) continue;
      MetamaterialSignChange c;
      c.ratio = names[which];
      c.negative_after = nu(b) < 0;
      const double na = numerator(params, a, out), nb = numerator(params, b, out);
      const double da = denominator(params, a, out), db = denominator(params, b, out);
      if (opposite(na, nb)) {
        c.kind = "zero";
        c.fold = refine([&](double x) { return numerator(params, evaluate(params, x), out); }, a.fold, b.fold, na, nb);
        // A derivative that jumps rather than passes through 0: a dimension |.| at its corner.
        if (std::fabs(numerator(params, evaluate(params, c.fold), out)) > 1e-6 * std::max(std::fabs(na), std::fabs(nb)))
          c.kind = "corner";
      } else if (opposite(da, db)) {
        c.kind = "pole";
        c.fold = refine([&](double x) { return denominator(params, evaluate(params, x), out); }, a.fold, b.fold, da, db);
      } else {
        c.kind = "dimension";
        double lo = a.fold, hi = b.fold;
        const double slo = nu(a);
        for (int i = 0; i < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++i) {
          const double mid = 0.5 * (lo + hi), v = nu(evaluate(params, mid));
          if ((v > 0) == (slo > 0)) lo = mid;
          else hi = mid;
        }
        c.fold = 0.5 * (lo + hi);
      }
      t.sign_changes.push_back(c);
    }
  }
  t.params = given;
  t.height_maximum *= length;
  for (auto& r : t.rows) {
    r.x *= length, r.y *= length, r.H *= length;
    r.dx *= length, r.dy *= length, r.dH *= length;
  }
  std::sort(t.sign_changes.begin(), t.sign_changes.end(),
            [](const MetamaterialSignChange& a, const MetamaterialSignChange& b) { return a.fold < b.fold; });
  return t;
}

std::string metamaterial_csv(const MetamaterialTable& t) {
  const auto d = dimension_names(t.params.unit);
  const auto nu = ratio_names(t.params.unit);
  std::string s = "fold_deg,second_angle_deg";
  for (const auto& x : d) s += "," + x;
  for (const auto& x : d) {
    s += ",d";
    s += x;
    s += "_per_rad";
  }
  for (const auto& x : nu) s += "," + x;
  s += ",constraint_residual,derivative_error\n";
  char buf[64];
  auto num = [&](double v) {
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return std::string(buf);
  };
  for (const auto& r : t.rows) {
    const double v[] = {to_degrees(r.fold), to_degrees(r.second_angle), r.x, r.y, r.H, r.dx, r.dy, r.dH,
                        r.nu_in, r.nu_out, r.constraint_residual, r.derivative_error};
    for (std::size_t i = 0; i < std::size(v); ++i) {
      if (i) s += ",";
      s += num(v[i]);
    }
    s += "\n";
  }
  return s;
}

namespace {

std::string fold_label(MetamaterialUnit unit) {
  return unit == MetamaterialUnit::kSquareTwist ? "fold angle theta (deg)" : "fold angle rho = 180 - phi of A2B2 (deg)";
}

std::vector<double> folds_deg(const MetamaterialTable& t) {
  std::vector<double> x;
  for (const auto& r : t.rows) x.push_back(to_degrees(r.fold));
  return x;
}

}  // namespace

std::string metamaterial_dimensions_svg(const MetamaterialTable& t) {
  LinePlot p;
  p.title = unit_name(t.params.unit) + ": dimensions";
  p.x_label = fold_label(t.params.unit);
  p.y_label = t.params.unit == MetamaterialUnit::kSquareTwist ? "length (unit of a)" : "length (unit of l)";
  const auto names = dimension_names(t.params.unit);
  const auto x = folds_deg(t);
  double MetamaterialRow::*fields[] = {&MetamaterialRow::x, &MetamaterialRow::y, &MetamaterialRow::H};
  for (int k = 0; k < 3; ++k) {
    PlotSeries s{names[k], x, {}};
    for (const auto& r : t.rows) s.y.push_back(r.*fields[k]);
    p.series.push_back(s);
  }
  return line_plot_svg(p);
}

std::string metamaterial_ratios_svg(const MetamaterialTable& t) {
  LinePlot p;
  p.title = unit_name(t.params.unit) + ": Poisson's ratios";
  p.x_label = fold_label(t.params.unit);
  p.y_label = "Poisson's ratio";
  p.clip_quantile = 0.02;
  const auto names = ratio_names(t.params.unit);
  const auto x = folds_deg(t);
  double MetamaterialRow::*fields[] = {&MetamaterialRow::nu_in, &MetamaterialRow::nu_out};
  for (int k = 0; k < 2; ++k) {
    PlotSeries s{names[k], x, {}};
    for (const auto& r : t.rows) s.y.push_back(r.*fields[k]);
    p.series.push_back(s);
  }
  return line_plot_svg(p);
}

}  // namespace rigidfold::metamaterial
