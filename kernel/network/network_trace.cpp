#include "kernel/network/network_trace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "kernel/solve/portable_random.hpp"

namespace rigidfold {

NetworkConfiguration find_network_configuration(const NetworkClosure& system, int input, double value,
                                                const Eigen::VectorXd& guess, const NetworkSearchOptions& options) {
  const int n = system.num_unknowns();
  if (input < -1 || input >= n) throw std::invalid_argument("find_network_configuration: input joint out of range");
  if (guess.size() != 0 && guess.size() != n) throw std::invalid_argument("find_network_configuration: guess has the wrong size");
  NetworkNewtonOptions newton = options.newton;
  newton.held.clear();
  if (input >= 0) newton.held.push_back(input);
  NetworkConfiguration best;
  best.residual = std::numeric_limits<double>::infinity();
  SplitMix64 rng{options.seed};
  for (int s = 0; s <= options.max_starts; ++s) {
    Eigen::VectorXd q0(n);
    if (s == 0) {
      if (guess.size() == 0) continue;
      q0 = guess;
    } else {
      for (int j = 0; j < n; ++j) q0[j] = (2.0 * rng.uniform() - 1.0) * std::numbers::pi;
    }
    if (input >= 0) q0[input] = value;
    ++best.starts;
    const NetworkNewtonResult res = network_project(system, q0, newton);
    const double rn = res.residual_history.back();
    // The converged flag rests on ||r||_inf; checked again here on a fresh evaluation.
    const double check = system.residual(res.q).lpNorm<Eigen::Infinity>();
    if (res.converged && check <= newton.tolerance) {
      best.found = true;
      best.q = res.q;
      best.residual = check;
      return best;
    }
    if (std::isfinite(rn) && rn < best.residual) best.residual = rn;
  }
  return best;
}

NetworkTrace trace_network(const NetworkClosure& system, const Eigen::VectorXd& q_start, int input, double end_value,
                           int steps, const NetworkTraceOptions& options) {
  const int n = system.num_unknowns();
  if (input < 0 || input >= n) throw std::invalid_argument("trace_network: input joint out of range");
  if (q_start.size() != n) throw std::invalid_argument("trace_network: q_start has the wrong size");
  if (steps < 1) throw std::invalid_argument("trace_network: steps must be >= 1");
  if (!std::isfinite(end_value)) throw std::invalid_argument("trace_network: end value not finite");
  const double r0 = system.residual(q_start).lpNorm<Eigen::Infinity>();
  if (!(r0 <= options.tolerance)) throw std::invalid_argument("trace_network: the start is not closed");

  NetworkTrace trace;
  auto add_point = [&](const Eigen::VectorXd& q, double residual) {
    NetworkTracePoint p;
    p.input = q[input];
    p.q = q;
    p.residual = residual;
    const RankResult rank = network_mobility(system, q, {}, options.rank_tolerance);
    p.dof = rank.dof;
    p.sigma_kept = rank.sigma_kept;
    p.sigma_dropped = rank.sigma_dropped;
    trace.points.push_back(std::move(p));
  };
  add_point(q_start, r0);

  NetworkNewtonOptions newton;
  newton.tolerance = options.tolerance;
  newton.held = {input};
  Eigen::VectorXd q = q_start;
  const double start_value = q_start[input];
  for (int s = 1; s <= steps; ++s) {
    const double target = start_value + (end_value - start_value) * s / steps;
    double h = target - q[input];
    while (q[input] != target) {
      if (std::fabs(h) < options.min_substep) {
        trace.stop_reason = "motion limit or singular point near input ";
        trace.stop_reason += std::to_string(q[input]);
        trace.stop_reason += " rad: no closed configuration continues the path";
        return trace;
      }
      const bool last = std::fabs(target - q[input]) <= std::fabs(h);
      Eigen::VectorXd q0 = q;
      q0[input] = last ? target : q[input] + h;
      const NetworkNewtonResult res = network_project(system, q0, newton);
      ++trace.newton_runs;
      const double jump = (res.q - q).lpNorm<Eigen::Infinity>();
      const double check = res.converged ? system.residual(res.q).lpNorm<Eigen::Infinity>() : INFINITY;
      if (check <= options.tolerance && jump <= options.max_jump) {
        q = res.q;
        // Grow the increment back after a success.
        h = std::copysign(std::min(std::fabs(2.0 * h), std::fabs(target - q[input])), target - q[input]);
        if (q[input] == target) add_point(q, check);
      } else {
        h *= 0.5;
      }
    }
  }
  trace.complete = true;
  return trace;
}

int probe_input_motion(const NetworkClosure& system, const Eigen::VectorXd& q, int input, double delta, double tolerance) {
  if (input < 0 || input >= system.num_unknowns()) throw std::invalid_argument("probe_input_motion: input joint out of range");
  if (q.size() != system.num_unknowns()) throw std::invalid_argument("probe_input_motion: q has the wrong size");
  NetworkNewtonOptions newton;
  newton.tolerance = tolerance;
  newton.held = {input};
  int moved = 0;
  for (const double s : {1.0, -1.0}) {
    Eigen::VectorXd q0 = q;
    q0[input] += s * delta;
    const NetworkNewtonResult res = network_project(system, q0, newton);
    if (res.converged && system.residual(res.q).lpNorm<Eigen::Infinity>() <= tolerance) ++moved;
  }
  return moved;
}

}  // namespace rigidfold
