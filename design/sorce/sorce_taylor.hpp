#pragma once
// Internal to design/sorce: Jets as truncated Taylor series in Boost.Math autodiff, so that
// formulas composed of them (profiles, circular offsets) carry exact derivatives in t.
#include <boost/math/differentiation/autodiff.hpp>

#include <cstddef>

#include "design/sorce/sorce_function.hpp"

namespace rigidfold::sorce::detail {

template <std::size_t N>
using Taylor = boost::math::differentiation::autodiff_fvar<double, N>;

// The series f(t + h) truncated at order N <= 3, as a function of the autodiff variable h
// (at h = 0): f + f' h + f'' h^2 / 2 + f''' h^3 / 6.
template <std::size_t N>
Taylor<N> series(const Jet& f) {
  static_assert(N <= 3, "a Jet carries three derivatives");
  const auto h = boost::math::differentiation::make_fvar<double, N>(0.0);
  return f[0] + h * (f[1] + h * (f[2] / 2.0 + h * (f[3] / 6.0)));
}

// The series of f'(t + h) truncated at order N <= 2.
template <std::size_t N>
Taylor<N> derivative_series(const Jet& f) {
  static_assert(N <= 2, "a Jet's derivative carries two derivatives");
  const auto h = boost::math::differentiation::make_fvar<double, N>(0.0);
  return f[1] + h * (f[2] + h * (f[3] / 2.0));
}

// Back to a Jet (orders above N left 0).
template <std::size_t N>
Jet to_jet(const Taylor<N>& x) {
  Jet j{};
  for (std::size_t k = 0; k <= N && k < 4; ++k) j[k] = x.derivative(k);
  return j;
}

}  // namespace rigidfold::sorce::detail
