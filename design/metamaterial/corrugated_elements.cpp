#include "design/metamaterial/corrugated_elements.hpp"
#include "kernel/math/angle_units.hpp"

#include <ceres/jet.h>

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

namespace rigidfold::metamaterial {
namespace {

using Jet = ceres::Jet<double, 1>;

void check(const CorrugatedElementParams& p) {
  if (!(p.alpha > 0 && p.alpha < kPi)) throw std::invalid_argument("corrugated element: alpha must lie in (0, pi)");
  if (!(p.beta > 0 && p.beta < kPi)) throw std::invalid_argument("corrugated element: beta must lie in (0, pi)");
  if (!(p.l > 0) || !std::isfinite(p.l)) throw std::invalid_argument("corrugated element: l must be > 0");
}

template <typename T>
struct Dims {
  T W, L, H, theta;
};

// Element 1 (3-24), literally, with atan2 for the arctan of (3-24c).
template <typename T>
Dims<T> element1(const CorrugatedElementParams& p, const T& phi) {
  using std::abs;
  using std::acos;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const double ca = std::cos(p.alpha), sa = std::sin(p.alpha), cb = std::cos(p.beta), sb = std::sin(p.beta);
  const T angle = acos(-cb * ca + sb * sa * cos(phi));            // A1A2A3
  Dims<T> d;
  d.W = 2.0 * p.l * sin(angle / 2.0);
  const T c_bpb = (-ca - cb * cos(angle)) / (sb * sin(angle));  // cos B2PB2'
  const T s_bpb = sqrt(1.0 - c_bpb * c_bpb);                     // B2PB2' in [0, pi]
  const double pb2 = p.l * sb;
  d.H = pb2 * s_bpb;
  const T pb2p = pb2 * c_bpb;
  const double pa2 = p.l * cb;
  const T a2b2p = sqrt(pb2p * pb2p + pa2 * pa2);
  const T pa2b2p = atan2(pb2p, T(pa2));
  // The chain gives the signed projection (negative when PA2 = l cos(beta) < 0 under atan2,
  // where the printed arctan would flip the cosine instead): the dimension is its magnitude.
  d.L = abs(2.0 * a2b2p * cos(pa2b2p - angle / 2.0));
  d.theta = phi;
  return d;
}

template <typename T>
Dims<T> element3_at(const CorrugatedElementParams& p, const T& theta);

// Element 3 (3-26, 3-27) with W = 4 B5B4' cos(B1B5B4').
template <typename T>
Dims<T> element3(const CorrugatedElementParams& p, const T& phi) {
  using std::atan;
  using std::tan;
  const T theta = 2.0 * atan(tan(phi / 2.0) * (std::cos((p.beta + p.alpha) / 2) / std::cos((p.beta - p.alpha) / 2)));
  return element3_at(p, theta);
}

// Element 3 (3-27) at the dihedral theta of B4B5.
template <typename T>
Dims<T> element3_at(const CorrugatedElementParams& p, const T& theta) {
  using std::abs;
  using std::acos;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const double ca = std::cos(p.alpha), sa = std::sin(p.alpha), cb = std::cos(p.beta), sb = std::sin(p.beta);
  Dims<T> d;
  d.theta = theta;
  const T angle = acos(cb * ca + sb * sa * cos(d.theta));  // A5B5C5
  d.L = 2.0 * p.l * sin(angle / 2.0);
  const T c_bpb = (-cb + ca * cos(angle)) / (sa * sin(angle));  // cos B4PB4'
  const T s_bpb = sqrt(1.0 - c_bpb * c_bpb);
  const double pb4 = p.l * sa;
  d.H = 2.0 * pb4 * s_bpb;
  const double pb5 = -p.l * ca;
  const T pb4p = pb4 * c_bpb;
  const T b5b4p = sqrt(pb4p * pb4p + pb5 * pb5);
  const T pb5b4p = atan2(pb4p, T(pb5));
  d.W = abs(4.0 * b5b4p * cos(angle / 2.0 - pb5b4p));  // magnitude, as for element 1's L
  return d;
}

template <typename T>
Dims<T> dims(CorrugatedElement e, const CorrugatedElementParams& p, const T& phi) {
  switch (e) {
    case CorrugatedElement::kElement1: return element1(p, phi);
    case CorrugatedElement::kElement2: {
      Dims<T> d = element1(p, phi);
      d.H = 2.0 * d.H;
      d.L = 2.0 * d.L;
      return d;
    }
    case CorrugatedElement::kElement3: return element3(p, phi);
  }
  throw std::invalid_argument("corrugated element: unknown element");
}

}  // namespace

double element3_theta(const CorrugatedElementParams& p, double phi) {
  check(p);
  return element3(p, phi).theta;
}

namespace {
// The state from the dimensions and their derivatives along the input (dual numbers).
CorrugatedElementState state_of(const Dims<Jet>& d, double phi) {
  CorrugatedElementState s;
  s.phi = phi;
  s.theta = d.theta.a;
  s.W = d.W.a;
  s.L = d.L.a;
  s.H = d.H.a;
  s.dW = d.W.v[0];
  s.dL = d.L.v[0];
  s.dH = d.H.v[0];
  s.nu_in = -(s.dL / s.L) / (s.dW / s.W);
  s.nu_out = -(s.dH / s.H) / (s.dW / s.W);
  return s;
}
}  // namespace

CorrugatedElementState corrugated_element(CorrugatedElement e, const CorrugatedElementParams& p, double phi) {
  check(p);
  if (!(phi >= 0 && phi <= kPi)) throw std::invalid_argument("corrugated element: phi must lie in [0, pi]");
  return state_of(dims(e, p, Jet(phi, 0)), phi);
}

CorrugatedElementState corrugated_element3_at_theta(const CorrugatedElementParams& p, double theta) {
  check(p);
  if (!(theta >= 0 && theta <= kPi)) throw std::invalid_argument("corrugated element: theta must lie in [0, pi]");
  CorrugatedElementState s = state_of(element3_at(p, Jet(theta, 0)), NAN);
  s.theta = theta;
  return s;
}

CorrugatedHeightMaximum corrugated_height_maximum(CorrugatedElement e, const CorrugatedElementParams& p, double lo,
                                                  double hi) {
  auto f = [&](double phi) { return corrugated_element(e, p, phi).dH; };
  const double flo = f(lo), fhi = f(hi);
  if (!(lo < hi && flo > 0 && fhi < 0))
    throw std::invalid_argument("corrugated element: dH/dphi must go from > 0 at lo to < 0 at hi (a maximum)");
  std::uintmax_t iterations = 200;
  const auto [a, b] =
      boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, boost::math::tools::eps_tolerance<double>(52), iterations);
  CorrugatedHeightMaximum m;
  m.phi = 0.5 * (a + b);
  m.height = corrugated_element(e, p, m.phi).H;
  return m;
}

}  // namespace rigidfold::metamaterial
