#include "design/sorce/sorce_path_spline.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

// m-th derivative (m = 0..3) of the centred cardinal quintic B-spline (support [-3, 3], knots
// at the integers), from its truncated-power form on |x| (it is even), which keeps only the
// three terms (3 - |x| - k)_+ , k = 0..2, so there is little cancellation.
double bspline5(double x, int m) {
  const double ax = std::abs(x);
  if (ax >= 3.0) return 0.0;
  static constexpr double kBinom[3] = {1.0, 6.0, 15.0};
  static constexpr double kFactorial[6] = {1.0, 1.0, 2.0, 6.0, 24.0, 120.0};
  double s = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double u = 3.0 - ax - k;
    if (u <= 0.0) break;
    s += (k % 2 == 0 ? 1.0 : -1.0) * kBinom[k] * std::pow(u, 5 - m);
  }
  s /= kFactorial[5 - m];
  // s carries (-1)^m against d^m/d|x|^m; and d^m/dx^m = (-1)^m d^m/d|x|^m for x < 0.
  return (m % 2 == 1 && x >= 0.0) ? -s : s;
}

// Weights w_k (k = 0..7) with sum_k w_k p(k) = p^(m)(0) for every polynomial of degree <= 7.
Eigen::Matrix<double, 8, 1> end_derivative_weights(int m) {
  Eigen::Matrix<double, 8, 8> vt;  // transpose of the Vandermonde matrix V(k, j) = k^j
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j) vt(j, k) = std::pow(static_cast<double>(k), j);
  Eigen::Matrix<double, 8, 1> rhs = Eigen::Matrix<double, 8, 1>::Zero();
  rhs(m) = m == 2 ? 2.0 : 1.0;
  return vt.fullPivLu().solve(rhs);
}

}  // namespace

ScalarFunction quintic_spline(const std::vector<double>& values) {
  const int n = static_cast<int>(values.size()) - 1;  // intervals
  if (n < 7) throw InputError("values", "a quintic spline with end derivatives needs at least 8 values");
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!std::isfinite(values[k])) throw InputError("values[" + std::to_string(k) + "]", "not finite");
  // Unknowns: coefficients c_j of B(x - j), j = -2..n+2 (index j + 2), x = n t.
  const int m = n + 5;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd b(m);
  for (int k = 0; k <= n; ++k) {
    for (int j = k - 2; j <= k + 2; ++j) a(k, j + 2) = bspline5(k - j, 0);
    b(k) = values[k];
  }
  // End conditions in x units: first and second derivatives at x = 0 and x = n.
  int row = n + 1;
  for (int order = 1; order <= 2; ++order) {
    const Eigen::Matrix<double, 8, 1> w = end_derivative_weights(order);
    double left = 0.0, right = 0.0;
    for (int k = 0; k < 8; ++k) {
      left += w(k) * values[k];
      right += w(k) * values[n - k];  // mirrored nodes: derivative of order `order` flips sign if odd
    }
    if (order % 2 == 1) right = -right;
    for (int j = -2; j <= 2; ++j) a(row, j + 2) = bspline5(0.0 - j, order);
    b(row++) = left;
    for (int j = n - 2; j <= n + 2; ++j) a(row, j + 2) = bspline5(static_cast<double>(n - j), order);
    b(row++) = right;
  }
  const Eigen::VectorXd c = a.partialPivLu().solve(b);
  // Each interval [i, i + 1] as a quintic in u = x - i (the uniform quintic B-spline basis
  // matrix), evaluated by Horner: a fixed polynomial per piece, so its derivatives carry no
  // cancellation between basis functions (quadrature of the profiles' arc length relies on a
  // smooth, noise-free integrand within each piece).
  static const Eigen::Matrix<double, 6, 6> kBasis = (Eigen::Matrix<double, 6, 6>() <<
      1, 26, 66, 26, 1, 0,
      -5, -50, 0, 50, 5, 0,
      10, 20, -60, 20, 10, 0,
      -10, 20, 0, -20, 10, 0,
      5, -20, 30, -20, 5, 0,
      -1, 5, -10, 10, -5, 1).finished() / 120.0;
  auto pieces = std::make_shared<Eigen::Matrix<double, 6, Eigen::Dynamic>>(6, n);
  for (int i = 0; i < n; ++i) {
    pieces->col(i) = kBasis * c.segment<6>(i);  // c_{i-2} .. c_{i+3}
    // The interpolation condition holds exactly at each piece's start (the solve leaves it to
    // round-off): the flat state is then exactly rho = 0 at t = 0, where the profiles' convexity
    // takes its sign from rho' (sorce_profile.hpp) and a stray -1e-17 would flip it.
    (*pieces)(0, i) = values[i];
  }
  return [pieces, n](double t) {
    const double x = t * n;
    const int i = std::clamp(static_cast<int>(std::floor(x)), 0, n - 1);
    const double u = x - i;
    const auto q = pieces->col(i);
    Jet jet{0.0, 0.0, 0.0, 0.0};
    for (int k = 5; k >= 0; --k) jet[0] = jet[0] * u + q(k);
    for (int k = 5; k >= 1; --k) jet[1] = jet[1] * u + k * q(k);
    for (int k = 5; k >= 2; --k) jet[2] = jet[2] * u + k * (k - 1) * q(k);
    for (int k = 5; k >= 3; --k) jet[3] = jet[3] * u + k * (k - 1) * (k - 2) * q(k);
    const double nn = n;
    jet[1] *= nn;  // d/dt = n d/dx
    jet[2] *= nn * nn;
    jet[3] *= nn * nn * nn;
    return jet;
  };
}

const char* to_string(PathParameter p) {
  switch (p) {
    case PathParameter::kArcLength: return "arc_length";
    case PathParameter::kHalfTangent: return "half_tangent";
    default: return "drive";
  }
}

namespace {

// g(tau) = ||rho'(tau)|| over all edges, and its integral by 8-point Gauss-Legendre on [a, b]
// (inside one knot interval the splines are polynomials, so g is smooth there).
double speed(const std::vector<ScalarFunction>& rho, double tau) {
  double s = 0.0;
  for (const ScalarFunction& f : rho) {
    const double d = f(tau)[1];
    s += d * d;
  }
  return std::sqrt(s);
}

double speed_integral(const std::vector<ScalarFunction>& rho, double a, double b) {
  static constexpr double kX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static constexpr double kW[4] = {0.3626837833783620, 0.3137066278886872, 0.2223810344533745, 0.1012285362903763};
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double s = 0.0;
  for (int i = 0; i < 4; ++i) s += kW[i] * (speed(rho, c - h * kX[i]) + speed(rho, c + h * kX[i]));
  return s * h;
}

// Root of the increasing f on [lo, hi] with f(lo) <= target <= f(hi): Newton steps kept inside
// the bracket (bisection when a step leaves it).
template <class F, class D>
double solve_increasing(F f, D df, double target, double lo, double hi) {
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double r = f(x) - target;
    if (r == 0.0) return x;
    (r > 0.0 ? hi : lo) = x;
    const double d = df(x);
    double next = d > 0.0 ? x - r / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-16 * std::max(1.0, std::abs(x))) return next;
    x = next;
  }
  return x;
}

// f(tau(t)) with its first three derivatives in t (chain rule).
Jet compose(const Jet& f, const Jet& tau) {
  return {f[0], f[1] * tau[1], f[2] * tau[1] * tau[1] + f[1] * tau[2],
          f[3] * tau[1] * tau[1] * tau[1] + 3.0 * f[2] * tau[1] * tau[2] + f[1] * tau[3]};
}

}  // namespace

PathSpline path_spline(const MotionBranch& branch, int num_edges, PathParameter parameter) {
  if (!branch.traced) throw InputError("branch", "not traced: " + branch.message);
  const int steps = static_cast<int>(branch.steps.size());
  if (steps < 7) throw InputError("branch", "needs at least 7 traced steps for a C^3 path (has " +
                                                std::to_string(steps) + ")");
  PathSpline path;
  path.drive = branch.drive;
  path.final_drive = branch.steps.back().drive;
  if (path.final_drive == 0.0 || !std::isfinite(path.final_drive))
    throw InputError("branch", "final drive angle is 0 or not finite");
  path.knots.resize(steps + 1);
  path.samples = Eigen::MatrixXd::Zero(num_edges, steps + 1);
  for (int k = 1; k <= steps; ++k) {
    const MotionStep& s = branch.steps[k - 1];
    const double expected = path.final_drive * k / steps;
    if (std::abs(s.drive - expected) > 1e-9 * std::abs(path.final_drive))
      throw InputError("branch.steps[" + std::to_string(k - 1) + "]",
                       "drive angles are not equal steps from the flat state");
    if (s.rho.size() != num_edges)
      throw InputError("branch.steps[" + std::to_string(k - 1) + "].rho", "one fold angle per edge expected");
    path.knots[k] = static_cast<double>(k) / steps;
    path.samples.col(k) = s.rho;
  }
  path.rho.reserve(num_edges);
  path.exact = static_cast<int>(branch.tan_half_ratio.size()) == num_edges;
  for (int e = 0; e < num_edges; ++e) {
    if (path.exact) {
      path.rho.push_back(tan_half_path(branch.tan_half_ratio[e], path.final_drive));
      continue;
    }
    const Eigen::VectorXd row = path.samples.row(e).transpose();
    path.rho.push_back(quintic_spline(std::vector<double>(row.data(), row.data() + row.size())));
  }
  path.parameter = parameter;
  // Arc length by the drive parameter tau (knots tau_k = k / steps).
  std::vector<double> cumulative(steps + 1, 0.0);
  for (int k = 0; k < steps; ++k)
    cumulative[k + 1] = cumulative[k] + speed_integral(path.rho, path.knots[k], path.knots[k + 1]);
  path.arc_length = cumulative[steps];
  if (parameter == PathParameter::kDrive) return path;

  const std::vector<ScalarFunction> by_drive = path.rho;
  // h(tau): the new parameter as a function of the drive parameter, increasing from 0 to 1.
  std::function<double(double)> h;
  if (parameter == PathParameter::kArcLength) {
    for (int k = 0; k <= 20 * steps; ++k)
      if (!(speed(path.rho, static_cast<double>(k) / (20 * steps)) > 1e-9 * path.arc_length))
        throw InputError("branch", "the path stops (||rho'|| = 0) near drive fraction " +
                                       std::to_string(static_cast<double>(k) / (20 * steps)) + ": no arc-length parameter");
    h = [&](double tau) {
      const int k = std::clamp(static_cast<int>(std::floor(tau * steps)), 0, steps - 1);
      return (cumulative[k] + speed_integral(by_drive, path.knots[k], tau)) / path.arc_length;
    };
  } else {
    std::vector<int> folding;
    for (int e = 0; e < num_edges; ++e)
      if (path.samples.row(e).cwiseAbs().maxCoeff() > 1e-9) folding.push_back(e);
    if (folding.empty()) throw InputError("branch", "no crease folds: no half-tangent parameter");
    auto mean_log = [folding, &by_drive](double tau) {
      double s = 0.0;
      for (int e : folding) s += std::log(std::abs(std::tan(0.5 * by_drive[e](tau)[0])));
      return s / static_cast<double>(folding.size());
    };
    const double end = std::atan(std::exp(mean_log(1.0)));
    h = [mean_log, end](double tau) { return tau <= 0.0 ? 0.0 : std::atan(std::exp(mean_log(tau))) / end; };
  }
  for (int k = 1; k <= 20 * steps; ++k) {
    const double a = h(static_cast<double>(k - 1) / (20 * steps)), b = h(static_cast<double>(k) / (20 * steps));
    if (!(b > a) || !std::isfinite(b))
      throw InputError("branch", std::string("the ") + to_string(parameter) +
                                     " parameter does not increase along the path near drive fraction " +
                                     std::to_string(static_cast<double>(k) / (20 * steps)) +
                                     " (a crease stops or turns back): use the drive parameter");
  }
  // tau at equal steps of the new parameter (bisection: h is increasing), then tau(t) as a
  // quintic spline through them.
  std::vector<double> tau(steps + 1, 0.0);
  tau[steps] = 1.0;
  for (int j = 1; j < steps; ++j) {
    const double target = static_cast<double>(j) / steps;
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
      const double mid = 0.5 * (lo + hi);
      (h(mid) < target ? lo : hi) = mid;
    }
    tau[j] = 0.5 * (lo + hi);
  }
  const ScalarFunction tau_of_t = quintic_spline(tau);
  for (int k = 0; k <= 20 * steps; ++k)
    if (!(tau_of_t(static_cast<double>(k) / (20 * steps))[1] > 0.0))
      throw InputError("branch", "the arc-length parameter is not monotone (spline of tau(t))");
  // Knots: the t where tau(t) is each sample's drive parameter, so rho(t_k) = the samples.
  std::vector<double> knots(steps + 1, 0.0);
  knots[steps] = 1.0;
  for (int k = 1; k < steps; ++k)
    knots[k] = solve_increasing([&](double t) { return tau_of_t(t)[0]; }, [&](double t) { return tau_of_t(t)[1]; },
                                path.knots[k], 0.0, 1.0);
  path.knots = knots;
  for (int e = 0; e < num_edges; ++e) {
    const ScalarFunction f = by_drive[e];
    path.rho[e] = [f, tau_of_t](double t) {
      const Jet tau_jet = tau_of_t(t);
      return compose(f(tau_jet[0]), tau_jet);
    };
  }
  return path;
}

std::string parameter_definition(const PathSpline& path) {
  const std::string made = !path.exact ? "quintic spline per crease"
                           : path.parameter == PathParameter::kDrive
                               ? "the multiplier model's exact fold angles"
                               : "the multiplier model's exact fold angles of the drive, splined in t";
  switch (path.parameter) {
    case PathParameter::kArcLength: return "t = arc length in fold-angle space / total, " + made;
    case PathParameter::kHalfTangent:
      return "tan(pi t/2) ~ geometric mean of |tan(rho/2)| over folding creases (seed eq 35 on one vertex), " + made;
    case PathParameter::kDrive: break;
  }
  return "t = drive / final drive, " + made;
}

}  // namespace rigidfold::sorce
