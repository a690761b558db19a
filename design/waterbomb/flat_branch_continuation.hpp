#pragma once
// Natural continuation of a loaded waterbomb (plain or split fold) from its flat state along
// the branch waterbomb_flat_crossing chose, used by waterbomb_loaded_path and split_fold_curve.
//
// The height control h = r cos t is parametrised by t (the closed forms' theta, radians; the
// far side is t > pi/2). The first start is the chosen ray to first order, x = ray (h / dh/ds);
// later starts are a secant through the last two solutions in t, not in h: the fold angles are
// smooth in t up to the limit, while near t -> pi dh/dt = -r sin t -> 0 and a secant in h
// overshoots. Between requested t, hidden steps of at most max_height_step * r in height and
// max_angle_step in t. Once a solve fails, every later request fails too (no jumping over a
// gap onto another branch).
//
// Solve: a callable (t, start, is_sample) -> (converged, x) that holds the height r cos t
// from `start` (unknowns of the closure system, radians); is_sample says whether the
// requested t (not a hidden step) is solved, e.g. to compute its stability only there.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace rigidfold::waterbomb {

struct FlatBranchSolve {
  bool converged = false;
  Eigen::VectorXd x;  // the solution's unknowns when converged
};

template <class Solve>
class FlatBranchContinuation {
 public:
  // ray_unknowns: the chosen ray as unknowns; height_rate: its dh/ds (< 0); r: the height scale.
  FlatBranchContinuation(Eigen::VectorXd ray_unknowns, double height_rate, double r, double max_height_step,
                         double max_angle_step, Solve solve)
      : ray_(std::move(ray_unknowns)), rate_(height_rate), r_(r), max_dh_(max_height_step * r),
        max_dt_(max_angle_step), solve_(std::move(solve)),
        x_prev_(Eigen::VectorXd::Zero(ray_.size())), x_prev2_(x_prev_) {}

  // Continues to t (increasing over calls, > pi/2) through hidden steps, then solves t as a
  // sample. Returns the solve's result; {false} once any solve has failed.
  FlatBranchSolve advance_to(double t) {
    while (!failed_) {
      const double next = std::min({t, std::acos(std::clamp((h_prev_ - max_dh_) / r_, -1.0, 1.0)), t_prev_ + max_dt_});
      if (next >= t) break;
      step(next, false);
    }
    if (failed_) return {};
    return step(t, true);
  }
  bool failed() const { return failed_; }

 private:
  FlatBranchSolve step(double t, bool sample) {
    const double h = r_ * std::cos(t);
    const Eigen::VectorXd start = first_ ? Eigen::VectorXd(ray_ * (h / rate_))
                                         : Eigen::VectorXd(x_prev_ + (x_prev_ - x_prev2_) * ((t - t_prev_) / (t_prev_ - t_prev2_)));
    FlatBranchSolve q = solve_(t, start, sample);
    if (!q.converged) {
      failed_ = true;
      return q;
    }
    x_prev2_ = x_prev_;
    t_prev2_ = t_prev_;
    x_prev_ = q.x;
    h_prev_ = h;
    t_prev_ = t;
    first_ = false;
    return q;
  }

  Eigen::VectorXd ray_;
  double rate_, r_, max_dh_, max_dt_;
  Solve solve_;
  Eigen::VectorXd x_prev_, x_prev2_;
  double h_prev_ = 0.0, t_prev_ = std::numbers::pi / 2, t_prev2_ = std::numbers::pi / 2;
  bool first_ = true, failed_ = false;
};

}  // namespace rigidfold::waterbomb
