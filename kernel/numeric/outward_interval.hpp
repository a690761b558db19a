#pragma once
// Closed intervals [lo, hi] of reals with outward rounding, for enclosures that are proofs
// (e.g. a loop gain that stays away from 1 for every pattern within a file's rounding,
// interval_loop_gain.hpp).
//
// Every operation evaluates its end points in the default round-to-nearest mode and then
// moves each end one floating-point number outward (std::nextafter). IEEE 754 +, -, *, / and
// sqrt are correctly rounded, so each computed end is within half a unit in the last place
// of the exact one and the widened interval contains the exact result. Why not
// Boost.Interval: on x86-64 it switches the FPU rounding mode (fesetround), which GCC and
// clang do not promise to respect without -frounding-math (they may fold or move the
// arithmetic across the switch); this type needs no mode switch at all.
//
// An operation whose result is unbounded (division by an interval holding 0, NaN inputs)
// gives the whole line, on which every test below answers "not proven".
#include <algorithm>
#include <cmath>
#include <limits>

namespace rigidfold {

struct OutwardInterval {
  double lo = 0.0;
  double hi = 0.0;

  OutwardInterval() = default;
  explicit OutwardInterval(double x) : lo(x), hi(x) {}
  OutwardInterval(double l, double h) : lo(l), hi(h) {}

  static OutwardInterval whole() {
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  }
  bool bounded() const { return std::isfinite(lo) && std::isfinite(hi) && lo <= hi; }
  bool contains(double x) const { return lo <= x && x <= hi; }
  bool excludes_zero() const { return bounded() && (lo > 0.0 || hi < 0.0); }
  // +1 or -1 when the sign is proven, 0 otherwise.
  int sign() const { return !excludes_zero() ? 0 : lo > 0.0 ? 1 : -1; }
  double width() const { return hi - lo; }
  double mid() const { return 0.5 * (lo + hi); }
};

namespace outward_detail {
inline double down(double x) { return std::nextafter(x, -std::numeric_limits<double>::infinity()); }
inline double up(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
inline OutwardInterval widened(double lo, double hi) {
  if (std::isnan(lo) || std::isnan(hi)) return OutwardInterval::whole();
  return {down(lo), up(hi)};
}
}  // namespace outward_detail

inline OutwardInterval operator+(const OutwardInterval& a, const OutwardInterval& b) {
  return outward_detail::widened(a.lo + b.lo, a.hi + b.hi);
}
inline OutwardInterval operator-(const OutwardInterval& a, const OutwardInterval& b) {
  return outward_detail::widened(a.lo - b.hi, a.hi - b.lo);
}
inline OutwardInterval operator-(const OutwardInterval& a) { return {-a.hi, -a.lo}; }  // exact
inline OutwardInterval operator*(const OutwardInterval& a, const OutwardInterval& b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  for (double x : p)
    if (std::isnan(x)) return OutwardInterval::whole();  // 0 * inf
  return outward_detail::widened(*std::min_element(p, p + 4), *std::max_element(p, p + 4));
}
inline OutwardInterval operator/(const OutwardInterval& a, const OutwardInterval& b) {
  if (!b.excludes_zero() || !a.bounded()) return OutwardInterval::whole();
  const double q[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  return outward_detail::widened(*std::min_element(q, q + 4), *std::max_element(q, q + 4));
}
// x^2, tight when the interval holds 0 (x * x would give a negative lower end).
inline OutwardInterval square(const OutwardInterval& a) {
  if (!a.bounded()) return OutwardInterval::whole();
  const double m = std::max(std::abs(a.lo), std::abs(a.hi));
  const double n = a.contains(0.0) ? 0.0 : std::min(std::abs(a.lo), std::abs(a.hi));
  return {n == 0.0 ? 0.0 : outward_detail::down(n * n), outward_detail::up(m * m)};
}
// sqrt over the non-negative part; the whole line when the interval is negative or unbounded.
inline OutwardInterval sqrt(const OutwardInterval& a) {
  if (!a.bounded() || a.hi < 0.0) return OutwardInterval::whole();
  const double l = a.lo <= 0.0 ? 0.0 : std::max(0.0, outward_detail::down(std::sqrt(a.lo)));
  return {l, outward_detail::up(std::sqrt(a.hi))};
}

}  // namespace rigidfold
