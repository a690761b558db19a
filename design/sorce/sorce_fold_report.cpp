#include "design/sorce/sorce_fold_report.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Root of f on [a, b] with f(a), f(b) of opposite signs, to ~1e-15 in t.
double refine_root(const std::function<double(double)>& f, double a, double b) {
  std::uintmax_t iterations = 200;
  const auto tol = [](double lo, double hi) { return std::abs(hi - lo) <= 1e-15; };
  const auto [lo, hi] = boost::math::tools::toms748_solve(f, a, b, tol, iterations);
  return 0.5 * (lo + hi);
}

// Argmin of f on [a, b] (Brent, to half the digits in t).
std::pair<double, double> refine_min(const std::function<double(double)>& f, double a, double b) {
  std::uintmax_t iterations = 200;
  return boost::math::tools::brent_find_minima(f, a, b, std::numeric_limits<double>::digits / 2, iterations);
}

double offset_rate(const FoldMotion& m, double t) {
  double r = std::max(std::abs(m.z_left(t)[1]), std::abs(m.z_right(t)[1]));
  if (m.d) {
    const VectorJet d = m.d(t);
    r = std::max({r, std::abs(d[0][1]), std::abs(d[1][1])});
  }
  return r;
}

// Spans where c(t) < 0, from the sampled signs, boundaries refined where c is finite.
std::vector<Span> negative_spans(const std::vector<double>& ts, const std::vector<double>& c,
                                 const std::function<double(double)>& f) {
  std::vector<Span> spans;
  const std::size_t n = ts.size();
  std::size_t k = 0;
  auto boundary = [&](std::size_t i) {  // between samples i and i+1, sign change
    const double a = c[i], b = c[i + 1];
    if (std::isfinite(a) && std::isfinite(b)) return refine_root(f, ts[i], ts[i + 1]);
    return 0.5 * (ts[i] + ts[i + 1]);
  };
  while (k < n) {
    if (!(c[k] < 0.0)) {
      ++k;
      continue;
    }
    Span s;
    s.begin = k == 0 ? ts[0] : boundary(k - 1);
    while (k < n && c[k] < 0.0) ++k;
    s.end = k == n ? ts[n - 1] : boundary(k - 1);
    spans.push_back(s);
  }
  return spans;
}

double protrusion(const std::vector<double>& ts, const std::vector<double>& y, double thickness,
                  const std::function<double(double)>& height) {
  if (!(thickness > 0.0)) return 0.0;
  const auto kmax = static_cast<std::size_t>(std::max_element(y.begin(), y.end()) - y.begin());
  const auto kmin = static_cast<std::size_t>(std::min_element(y.begin(), y.end()) - y.begin());
  auto refined = [&](std::size_t k, double sgn) {
    const double a = ts[k == 0 ? 0 : k - 1], b = ts[std::min(k + 1, ts.size() - 1)];
    const auto [t, v] = refine_min([&](double s) { return -sgn * height(s); }, a, b);
    (void)t;
    return std::max(sgn * y[k], -v);
  };
  const double top = refined(kmax, 1.0), bottom = -refined(kmin, -1.0);
  return std::max({0.0, top - thickness / 2, -thickness / 2 - bottom});
}

// The profile at t, moved 1e-9 off a point where gamma' = 0 exactly (the refinements below
// may land on one; those points are reported as ill-behaved or stationary instead).
ProfilePoint point_at(const FoldMotion& m, double t) {
  if (m.gamma(t)[1] == 0.0) t += t < 0.5 ? 1e-9 : -1e-9;
  return profile_point(m, t);
}

}  // namespace

FoldReport fold_report(const FoldMotion& m, const ReportOptions& options) {
  if (options.samples < 3) throw InputError("samples", "need at least 3");
  FoldReport r;
  const int n = options.samples;
  std::vector<double> ts(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) ts[static_cast<std::size_t>(k)] = static_cast<double>(k) / (n - 1);

  // gamma' zeros: exact sampled zeros and sign changes (TOMS 748).
  auto dgamma = [&](double t) { return m.gamma(t)[1]; };
  std::vector<double> dg(ts.size());
  for (std::size_t k = 0; k < ts.size(); ++k) dg[k] = dgamma(ts[k]);
  std::vector<double> zeros;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    if (dg[k] == 0.0) zeros.push_back(ts[k]);
    if (k + 1 < ts.size() && dg[k] * dg[k + 1] < 0.0) zeros.push_back(refine_root(dgamma, ts[k], ts[k + 1]));
  }
  for (double t : zeros) (offset_rate(m, t) > 1e-12 ? r.ill_behaved : r.stationary).push_back(t);
  const bool defined_everywhere = zeros.empty();

  std::vector<double> tp, cl, cr, yl, yr, speed;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    if (dg[k] == 0.0) continue;
    const ProfilePoint p = profile_point(m, ts[k]);
    tp.push_back(ts[k]);
    cl.push_back(p.convexity_left);
    cr.push_back(p.convexity_right);
    yl.push_back(p.s_left.y());
    yr.push_back(p.s_right.y());
    speed.push_back(p.ds_left.norm());
    const RollingResidual res = rolling_residual(m, ts[k]);
    r.max_rolling_residual = std::max(r.max_rolling_residual, res.rolling);
    r.max_contact_residual = std::max(r.max_contact_residual, res.contact);
  }
  if (tp.size() < 3) return r;

  r.s0 = initial_contact_offset(m);
  if (dg.front() != 0.0 && dg.back() != 0.0) r.ends = end_points(m);

  r.min_turn_radius = kInf;
  r.max_speed = *std::max_element(speed.begin(), speed.end());
  r.min_speed = *std::min_element(speed.begin(), speed.end());
  const double slow = options.speed_tolerance * r.max_speed;
  auto speed_at = [&](double t) { return point_at(m, t).ds_left.norm(); };
  const std::size_t last = tp.size() - 1;
  // Pivots: the speed at an end, or its minimum over the first/last sample interval.
  r.pivot_at_start = speed[0] <= slow || refine_min(speed_at, tp[0], tp[1]).second <= slow;
  r.pivot_at_end = speed[last] <= slow || refine_min(speed_at, tp[last - 1], tp[last]).second <= slow;
  auto near_zero_rate = [&](double t) {
    for (double z : zeros)
      if (std::abs(t - z) <= 2.0 / (n - 1)) return true;
    return false;
  };
  // At a pivot the curvature diverges; rounding leaves |s'| ~ 1e-16 there, so the sampled end
  // convexity is noise, sign included. The concave spans take the sign of its limit, that of
  // the next sample in, where |s'| is not small (else the noise makes a span of width ~1e-8 at
  // the pivot). The extremes keep the infinity with its sampled sign, which the offset search
  // was tuned on (sorce_optimize_test.cpp: with the limit's sign, the search from linear
  // offsets on vertex A finds no feasible design).
  std::vector<double> span_cl = cl, span_cr = cr;
  auto diverge = [](double& c, double sign) { c = std::copysign(kInf, sign); };
  if (r.pivot_at_start) {
    diverge(span_cl.front(), cl[1]);
    diverge(span_cr.front(), cr[1]);
    diverge(cl.front(), cl.front());
    diverge(cr.front(), cr.front());
  }
  if (r.pivot_at_end) {
    diverge(span_cl.back(), cl[last - 1]);
    diverge(span_cr.back(), cr[last - 1]);
    diverge(cl.back(), cl.back());
    diverge(cr.back(), cr.back());
  }
  r.concave_left = negative_spans(tp, span_cl, [&](double t) { return point_at(m, t).convexity_left; });
  r.concave_right = negative_spans(tp, span_cr, [&](double t) { return point_at(m, t).convexity_right; });
  r.min_convexity_left = *std::min_element(cl.begin(), cl.end());
  r.max_convexity_left = *std::max_element(cl.begin(), cl.end());
  r.min_convexity_right = *std::min_element(cr.begin(), cr.end());
  r.max_convexity_right = *std::max_element(cr.begin(), cr.end());
  for (std::size_t k = 1; k < last; ++k) {
    if (!(speed[k] <= speed[k - 1] && speed[k] <= speed[k + 1])) continue;
    if (near_zero_rate(tp[k])) continue;  // reported as ill-behaved / stationary
    if (speed[k] == speed[k - 1] && speed[k] == speed[k + 1]) continue;  // flat run, not a minimum
    const auto [t, v] = refine_min(speed_at, tp[k - 1], tp[k + 1]);
    if (t <= tp[0] || t >= tp[last]) continue;
    // Radius of curvature at the speed minimum: a cusp blurred by the sampling or by the
    // data into a hairpin turn of negligible radius is as unprintable as an exact one.
    const ProfilePoint q = point_at(m, t);
    const double radius = 1.0 / std::max(std::abs(q.curvature_left), std::abs(q.curvature_right));
    r.min_turn_radius = std::min(r.min_turn_radius, radius);
    if (v <= slow || radius <= options.cusp_radius * r.max_speed) r.cusps.push_back(t);
  }

  r.protrusion_left = protrusion(tp, yl, m.thickness_left, [&](double t) { return point_at(m, t).s_left.y(); });
  r.protrusion_right = protrusion(tp, yr, m.thickness_right, [&](double t) { return point_at(m, t).s_right.y(); });

  if (r.ends.flat_folded_end) {
    const Jet g1 = m.gamma(1.0);
    const double dy = m.d ? m.d(1.0)[1][0] : 0.0;
    r.end_separation = -(m.z_left(1.0)[0] + m.z_right(1.0)[0]) + dy;
    const double side = g1[0] > 0.0 ? 1.0 : -1.0;
    r.stacks = side * r.end_separation >= (m.thickness_left + m.thickness_right) / 2 - 1e-12;
  }

  if (defined_everywhere) {
    using boost::math::quadrature::gauss_kronrod;
    auto len = [&](bool left) {
      auto f = [&](double t) {
        const ProfilePoint p = point_at(m, t);
        return (left ? p.ds_left : p.ds_right).norm();
      };
      return gauss_kronrod<double, 61>::integrate(f, 0.0, 1.0, 15, 1e-12);
    };
    r.arc_length_left = len(true);
    r.arc_length_right = len(false);
  } else {
    r.arc_length_left = r.arc_length_right = std::numeric_limits<double>::quiet_NaN();
  }
  return r;
}

double figure_of_merit(const std::vector<FoldReport>& folds, double epsilon) {
  if (!(epsilon >= 0.0)) throw InputError("epsilon", "must be >= 0");
  double hi = -kInf, lo = kInf;
  for (const FoldReport& f : folds) {
    hi = std::max({hi, f.max_convexity_left, f.max_convexity_right});
    lo = std::min({lo, f.min_convexity_left, f.min_convexity_right});
  }
  const double den = std::max(epsilon, lo);
  if (!std::isfinite(hi) || !(den > 0.0)) return kInf;
  return hi / den;
}

}  // namespace rigidfold::sorce
