#include "design/sorce/sorce_path_spline.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
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

PathSpline path_spline(const MotionBranch& branch, int num_edges) {
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
  for (int e = 0; e < num_edges; ++e) {
    const Eigen::VectorXd row = path.samples.row(e).transpose();
    path.rho.push_back(quintic_spline(std::vector<double>(row.data(), row.data() + row.size())));
  }
  return path;
}

}  // namespace rigidfold::sorce
