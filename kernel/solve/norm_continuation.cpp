#include "kernel/solve/norm_continuation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kernel/solve/amplitude_search.hpp"
#include "kernel/solve/newton_projection.hpp"

namespace rigidfold {

NormContinuationResult continue_by_norm(const ClosureSystem& sys, const Eigen::VectorXd& x0,
                                        const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                        const NormContinuationOptions& opt,
                                        const std::function<bool(const Eigen::VectorXd&)>& accept) {
  const int n = sys.num_unknowns();
  if (x0.size() != n || lower.size() != n || upper.size() != n)
    throw std::invalid_argument("continue_by_norm: x0 and bounds must have one entry per unknown");
  const double s0 = x0.norm();
  if (!(s0 > 0)) throw std::invalid_argument("continue_by_norm: the start must be a folded point (x0 != 0)");
  if (!(opt.target_size > 0) || !std::isfinite(opt.target_size))
    throw std::invalid_argument("continue_by_norm: the target size must be positive and finite");

  if (!opt.sign_floor.empty() && static_cast<int>(opt.sign_floor.size()) != n)
    throw std::invalid_argument("continue_by_norm: sign_floor must be empty or have one entry per unknown");
  if (!(opt.sign_margin >= 0)) throw std::invalid_argument("continue_by_norm: the sign margin must be >= 0");
  // The corrector's box at size s: the caller's bounds, tightened by the letters' margin.
  auto box = [&](double size, Eigen::VectorXd& lo, Eigen::VectorXd& hi) {
    lo = lower;
    hi = upper;
    for (int i = 0; i < static_cast<int>(opt.sign_floor.size()); ++i) {
      if (opt.sign_floor[i] > 0) lo[i] = std::max(lo[i], opt.sign_margin * size);
      if (opt.sign_floor[i] < 0) hi[i] = std::min(hi[i], -opt.sign_margin * size);
    }
  };

  NormContinuationResult out;
  const bool outward = opt.target_size > s0;
  Eigen::VectorXd x = x0;
  double s = s0;
  double h = opt.initial_relative_step;
  out.last_size = s;
  while (out.points < opt.max_points) {
    const double xmax = x.cwiseAbs().maxCoeff();
    const double step = std::min({h, opt.max_relative_step, opt.max_angle_step / xmax});
    if (step < opt.min_relative_step) {
      out.reason = "the relative step fell below " + std::to_string(opt.min_relative_step);
      return out;
    }
    double next = outward ? s * (1 + step) : s / (1 + step);
    const bool last = outward ? next >= opt.target_size : next <= opt.target_size;
    AmplitudeSearchOptions ao;
    ao.amplitude = next;
    ao.tolerance = opt.tolerance;
    ao.max_iterations = opt.corrector_iterations;
    ao.stall_window = 0;
    Eigen::VectorXd lo, hi;
    box(next, lo, hi);
    const AmplitudeSearchResult ar = amplitude_search(sys, x * (next / s), lo, hi, ao);
    out.factorizations += ar.factorizations;
    if (!ar.converged) {
      ++out.rejected_steps;
      h = step / 2;
      continue;
    }
    // Polish: Levenberg-Marquardt stops just under the tolerance, which near flat (sigma_min
    // ~ the fold) leaves the point ~1e-10 off the manifold along its soft modes; minimum-norm
    // Newton steps on the closure (the creases on the box held) end near round-off.
    NewtonOptions nopt;
    nopt.tolerance = opt.tolerance * 1e-3;
    nopt.max_iterations = 2;
    for (int i = 0; i < n; ++i)
      if (ar.x[i] <= lo[i] || ar.x[i] >= hi[i]) nopt.held_unknowns.push_back(i);
    const NewtonResult polished = newton_project(sys, ar.x, nopt);
    out.factorizations += polished.factorizations;
    // The polish moves the size by about its step (~ residual / sigma_min): the point's own
    // size is the parameter from here on.
    const bool better = polished.residual_history.back() < polished.residual_history.front();
    x = better ? polished.x : ar.x;
    s = x.norm();
    ++out.points;
    out.last_size = s;
    h = step * 1.5;
    if (accept(x)) {
      out.reason = "stopped by the caller";
      out.reached = last;
      return out;
    }
    if (last) {
      out.reached = true;
      out.reason = "reached the target size";
      return out;
    }
  }
  out.reason = "reached the point limit (" + std::to_string(opt.max_points) + ")";
  return out;
}

}  // namespace rigidfold
