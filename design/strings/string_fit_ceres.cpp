#include "design/strings/string_fit_ceres.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "design/strings/string_vertex.hpp"

namespace rigidfold::design {

namespace {

double as_double(double v) { return v; }
template <int N>
double as_double(const ceres::Jet<double, N>& v) {
  return v.a;
}

struct DeflectionResidual {
  double theta, phi, psi;
  template <class T>
  bool operator()(const T* alpha, T* residual) const {
    // Beyond the motion limit the formula is smooth but the panels would pass through
    // each other: reject such a step.
    if (std::fabs(theta) >= string_theta_limit(as_double(alpha[0]), as_double(alpha[1])))
      return false;
    T R[9], ph, ps;
    string_vertex_frame(alpha[0], alpha[1], T(theta), R, &ph, &ps);
    residual[0] = ph - T(phi);
    residual[1] = ps - T(psi);
    return true;
  }
};

}  // namespace

TrajectoryFitResult fit_string_trajectories(const TrajectoryTarget& t, const StringBounds& b, int max_iterations,
                                            bool closed_form_start) {
  const int n = static_cast<int>(t.phi.size()), m = static_cast<int>(t.theta.size());
  if (n < 1 || m < 1) throw std::invalid_argument("trajectories: need at least one vertex and one theta sample");
  if (static_cast<int>(t.psi.size()) != n) throw std::invalid_argument("trajectories: phi and psi need one row per vertex");
  for (int j = 0; j < m; ++j)
    if (!std::isfinite(t.theta[j]) || t.theta[j] == 0)
      throw std::invalid_argument("theta[" + std::to_string(j) + "]: must be finite and nonzero");
  for (int i = 0; i < n; ++i) {
    if (static_cast<int>(t.phi[i].size()) != m || static_cast<int>(t.psi[i].size()) != m)
      throw std::invalid_argument("vertices[" + std::to_string(i) + "]: needs one phi and one psi per theta sample");
    for (int j = 0; j < m; ++j)
      if (!std::isfinite(t.phi[i][j]) || !std::isfinite(t.psi[i][j]))
        throw std::invalid_argument("vertices[" + std::to_string(i) + "]: phi/psi must be finite");
  }
  auto theta_of = [&](int i, int j) { return t.mode == ThetaMode::Transmitted && i % 2 == 1 ? -t.theta[j] : t.theta[j]; };
  std::vector<double> params(2 * n);
  // Start: closed form at the largest |theta| sample where it is feasible.
  std::vector<int> order(m);
  for (int j = 0; j < m; ++j) order[j] = j;
  std::sort(order.begin(), order.end(), [&](int a, int c) { return std::fabs(t.theta[a]) > std::fabs(t.theta[c]); });
  for (int i = 0; i < n; ++i) {
    double a1 = std::numbers::pi / 4, a2 = std::numbers::pi / 4;
    for (int j : order) {
      if (!closed_form_start) break;
      double c1, c2;
      if (string_vertex_inverse(t.phi[i][j], t.psi[i][j], theta_of(i, j), c1, c2) && c1 >= b.alpha_min && c1 <= b.alpha_max &&
          c2 >= b.alpha_min && c2 <= b.alpha_max) {
        a1 = c1;
        a2 = c2;
        break;
      }
    }
    params[2 * i] = a1;
    params[2 * i + 1] = a2;
  }
  ceres::Problem problem;
  for (int i = 0; i < n; ++i) {
    double* block = &params[2 * i];
    for (int j = 0; j < m; ++j)
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<DeflectionResidual, 2, 2>(
                                   new DeflectionResidual{theta_of(i, j), t.phi[i][j], t.psi[i][j]}),
                               nullptr, block);
    for (int k = 0; k < 2; ++k) {
      problem.SetParameterLowerBound(block, k, b.alpha_min);
      problem.SetParameterUpperBound(block, k, b.alpha_max);
    }
  }
  ceres::Solver::Options opt;
  opt.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  opt.max_num_iterations = max_iterations;
  opt.function_tolerance = 1e-16;
  opt.gradient_tolerance = 1e-16;
  opt.parameter_tolerance = 1e-15;
  opt.logging_type = ceres::SILENT;
  opt.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(opt, &problem, &summary);
  TrajectoryFitResult r;
  r.final_cost = summary.final_cost;
  r.iterations = static_cast<int>(summary.iterations.size()) - 1;
  r.converged = summary.termination_type == ceres::CONVERGENCE;
  r.report = summary.BriefReport();
  for (int i = 0; i < n; ++i) {
    r.alpha1.push_back(params[2 * i]);
    r.alpha2.push_back(params[2 * i + 1]);
    double sum = 0;
    for (int j = 0; j < m; ++j) {
      double res[2];
      if (!DeflectionResidual{theta_of(i, j), t.phi[i][j], t.psi[i][j]}(&params[2 * i], res)) {
        res[0] = res[1] = std::numeric_limits<double>::infinity();
      }
      sum += res[0] * res[0] + res[1] * res[1];
      r.max_residual = std::max({r.max_residual, std::fabs(res[0]), std::fabs(res[1])});
    }
    r.vertex_rms.push_back(std::sqrt(sum / (2 * m)));
    for (int s = 0; s < 2; ++s) {
      const double a = params[2 * i + s];
      const std::string name = std::string(s == 0 ? "alpha1[" : "alpha2[") + std::to_string(i) + "]";
      if (a - b.alpha_min < 1e-9) r.binding.push_back(name + " = alpha_min");
      if (b.alpha_max - a < 1e-9) r.binding.push_back(name + " = alpha_max");
    }
  }
  return r;
}

}  // namespace rigidfold::design
