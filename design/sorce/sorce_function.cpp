#include "design/sorce/sorce_function.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "design/sorce/sorce_taylor.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

using boost::math::differentiation::make_fvar;

// Value and derivatives of p(t) by Horner's rule carried on the Taylor variable.
Jet polynomial_jet(const Polynomial& p, double t) {
  const auto x = make_fvar<double, 3>(t);
  auto y = make_fvar<double, 3>(0.0) * 0.0;
  for (auto it = p.c.rbegin(); it != p.c.rend(); ++it) y = y * x + *it;
  return detail::to_jet<3>(y);
}

double polynomial_value(const Polynomial& p, double t) {
  double y = 0.0;
  for (auto it = p.c.rbegin(); it != p.c.rend(); ++it) y = y * t + *it;
  return y;
}

}  // namespace

ScalarFunction constant_function(double c) {
  return [c](double) { return Jet{c, 0.0, 0.0, 0.0}; };
}

ScalarFunction power_function(double end_value, int power) {
  if (power < 1) throw InputError("power", "must be >= 1, so that f(0) = 0");
  Polynomial p;
  p.c.assign(static_cast<std::size_t>(power) + 1, 0.0);
  p.c.back() = end_value;
  return [p](double t) { return polynomial_jet(p, t); };
}

std::vector<Polynomial> seed_offset_bases(double b3_scale) {
  // (1-t)^2 t = t - 2t^2 + t^3;  (1-t) t = t - t^2;  (1-t) t^2 = t^2 - t^3.
  return {Polynomial{{0.0, 1.0, -2.0, 1.0}}, Polynomial{{0.0, 1.0, -1.0}},
          Polynomial{{0.0, 0.0, b3_scale, -b3_scale}}};
}

ScalarFunction basis_offset(double end_value, const std::vector<double>& b, const std::vector<Polynomial>& bases) {
  if (b.size() > bases.size()) throw InputError("b", std::to_string(b.size()) + " coefficients for " + std::to_string(bases.size()) + " bases");
  Polynomial sum{{0.0, 1.0}};  // t
  for (std::size_t j = 0; j < b.size(); ++j) {
    const Polynomial& B = bases[j];
    if (std::abs(polynomial_value(B, 0.0)) > 1e-12 || std::abs(polynomial_value(B, 1.0)) > 1e-12)
      throw InputError("bases", "basis " + std::to_string(j + 1) + " does not vanish at t = 0 and t = 1");
    if (sum.c.size() < B.c.size()) sum.c.resize(B.c.size(), 0.0);
    for (std::size_t k = 0; k < B.c.size(); ++k) sum.c[k] += b[j] * B.c[k];
  }
  for (double& c : sum.c) c *= end_value;
  return [sum](double t) { return polynomial_jet(sum, t); };
}

ScalarFunction tan_half_fold(double k) {
  if (!(k != 0.0 && std::isfinite(k))) throw InputError("k", "the tan-half multiplier must be finite and non-zero");
  return [k](double t) {
    const auto x = make_fvar<double, 3>(t);
    const auto a = (kPi / 2) * x;
    // atan2 keeps t = 1 exact (gamma = pi sign k) where tan(pi t / 2) overflows.
    const auto g = 2.0 * atan2(k * sin(a), cos(a));
    return detail::to_jet<3>(g);
  };
}

ScalarFunction tan_half_path(double k, double theta) {
  if (!std::isfinite(k)) throw InputError("k", "the tan-half multiplier must be finite");
  if (!(std::abs(theta) <= kPi) || theta == 0.0) throw InputError("theta", "the final drive must be in [-pi, pi] and not 0");
  if (k == 0.0) return constant_function(0.0);
  return [k, theta](double t) {
    const auto a = (theta / 2) * make_fvar<double, 3>(t);
    return detail::to_jet<3>(2.0 * atan2(k * sin(a), cos(a)));
  };
}

ScalarFunction linear_fold(double gamma_end) {
  return [gamma_end](double t) { return Jet{gamma_end * t, gamma_end, 0.0, 0.0}; };
}

ScalarFunction circular_offset(double r, ScalarFunction gamma) {
  return [r, gamma = std::move(gamma)](double t) {
    const auto g = detail::series<3>(gamma(t));
    return detail::to_jet<3>(-r * tan(g / 4.0));
  };
}

VectorFunction split_offset_along_half_angle(ScalarFunction d_scalar, ScalarFunction gamma) {
  return [d_scalar = std::move(d_scalar), gamma = std::move(gamma)](double t) {
    const auto d = detail::series<3>(d_scalar(t));
    const auto g = detail::series<3>(gamma(t));
    return VectorJet{detail::to_jet<3>(d * cos(g / 2.0)), detail::to_jet<3>(d * sin(g / 2.0))};
  };
}

ScalarFunction circular_split_offset(double r, ScalarFunction gamma_split, ScalarFunction gamma_offsets) {
  return [r, gs = std::move(gamma_split), go = std::move(gamma_offsets)](double t) {
    const auto g3 = detail::series<3>(gs(t));
    const auto g2 = detail::series<3>(go(t));
    return detail::to_jet<3>(2.0 * r * sin(g3 / 2.0) * (tan(g3 / 4.0) - tan(g2 / 4.0)));
  };
}

}  // namespace rigidfold::sorce
