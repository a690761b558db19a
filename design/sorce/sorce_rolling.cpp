#include "design/sorce/sorce_rolling.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <algorithm>
#include <cstdint>

#include "design/sorce/sorce_fold_report.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

// Arc length from u = 0: Gauss-Kronrod (61 points) on each of 64 equal cells, accumulated
// once, plus the partial cell up to u. Adaptive to depth 3 only: on a 1/64 cell a smooth
// speed needs no split (the error estimate is roundoff), the depth serves near-cusps.
class ArcLength {
 public:
  explicit ArcLength(const PlanarCurve& c) : c_(c), cumulative_(kCells + 1, 0.0) {
    for (int k = 0; k < kCells; ++k)
      cumulative_[static_cast<std::size_t>(k) + 1] = cumulative_[static_cast<std::size_t>(k)] + piece(static_cast<double>(k) / kCells, static_cast<double>(k + 1) / kCells);
  }
  double operator()(double u) const {
    if (u <= 0.0) return 0.0;
    if (u >= 1.0) return cumulative_.back();
    const int k = std::min(kCells - 1, static_cast<int>(u * kCells));
    return cumulative_[static_cast<std::size_t>(k)] + piece(static_cast<double>(k) / kCells, u);
  }
  double total() const { return cumulative_.back(); }

 private:
  static constexpr int kCells = 64;
  double piece(double a, double b) const {
    if (b <= a) return 0.0;
    auto speed = [this](double s) { return c_(s).d1.norm(); };
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(speed, a, b, 3, 1e-12);
  }
  const PlanarCurve& c_;
  std::vector<double> cumulative_;
};

// Unit tangent, with the limit direction where the speed vanishes at an end: below the
// report's pivot tolerance (sorce_fold_report.hpp, relative to the curves' speed), where a
// pivot's s' is round-off (a spline path leaves |s'| ~ 1e-13 there) and its direction noise.
Vec2 unit_tangent(const CurvePoint& q, double u, double scale) {
  if (q.d1.norm() > ReportOptions{}.speed_tolerance * scale) return q.d1.normalized();
  const Vec2 lim = u >= 0.5 ? Vec2(-q.d2) : Vec2(q.d2);
  return lim.normalized();
}

}  // namespace

std::vector<RolledPose> roll_profiles(const PlanarCurve& left, const PlanarCurve& right,
                                      const std::function<Vec2(double)>& left_translation,
                                      const std::vector<double>& u_left) {
  for (std::size_t k = 0; k < u_left.size(); ++k) {
    const double u = u_left[k];
    if (!(u >= 0.0 && u <= 1.0) || (k > 0 && !(u > u_left[k - 1])))
      throw InputError("u_left", "samples must increase within [0, 1]");
  }
  const ArcLength left_length(left), right_length(right);
  const double total_right = right_length.total();
  // A speed scale for the pivot test: the larger speed of the two curves at their midpoints.
  const double scale = std::max({left(0.5).d1.norm(), right(0.5).d1.norm(), 1e-300});
  std::vector<RolledPose> out;
  double previous = 0.0;
  for (std::size_t k = 0; k < u_left.size(); ++k) {
    RolledPose r;
    r.u_left = u_left[k];
    r.arc_length = left_length(r.u_left);
    // Matched arc length (equal lengths at the far end are clamped onto u = 1).
    if (r.arc_length <= 0.0) {
      r.u_right = 0.0;
    } else if (r.arc_length >= total_right) {
      r.u_right = 1.0;
    } else {
      std::uintmax_t iterations = 200;
      auto f = [&](double u) { return right_length(u) - r.arc_length; };
      const boost::math::tools::eps_tolerance<double> tol(48);  // u to ~1e-14 relative
      const auto [lo, hi] = boost::math::tools::toms748_solve(f, 0.0, 1.0, -r.arc_length, total_right - r.arc_length, tol, iterations);
      r.u_right = 0.5 * (lo + hi);
    }
    const CurvePoint pl = left(r.u_left), pr = right(r.u_right);
    const Vec2 tl = unit_tangent(pl, r.u_left, scale), tr = unit_tangent(pr, r.u_right, scale);
    // R(gamma) tr = tl.
    double g = std::atan2(tr.x() * tl.y() - tr.y() * tl.x(), tr.dot(tl));
    if (k > 0) g += 2 * kPi * std::round((previous - g) / (2 * kPi));
    previous = g;
    r.gamma = g;
    Eigen::Matrix2d R;
    R << std::cos(g), -std::sin(g), std::sin(g), std::cos(g);
    r.right_translation = pl.p + left_translation(r.u_left) - R * pr.p;
    out.push_back(r);
  }
  return out;
}

PlanarCurve left_profile_curve(const FoldMotion& m) {
  return [m](double t) {
    const ProfilePoint p = profile_point(m, t);
    return CurvePoint{p.s_left, p.ds_left, p.dds_left};
  };
}

PlanarCurve right_profile_curve(const FoldMotion& m) {
  return [m](double t) {
    const ProfilePoint p = profile_point(m, t);
    return CurvePoint{p.s_right, p.ds_right, p.dds_right};
  };
}

RollingRecovery rolling_recovery(const FoldMotion& m, const PlanarCurve& right, const std::vector<double>& ts) {
  const auto rolled = roll_profiles(left_profile_curve(m), right, [&](double t) { return Vec2(0.0, m.z_left(t)[0]); }, ts);
  RollingRecovery e;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const FoldPoses poses = fold_poses(m, ts[k]);
    e.gamma = std::max(e.gamma, std::abs(rolled[k].gamma - poses.right.theta));
    e.translation = std::max(e.translation, (rolled[k].right_translation - poses.right.r).norm());
    e.parameter = std::max(e.parameter, std::abs(rolled[k].u_right - ts[k]));
  }
  return e;
}

RollingRecovery rolling_recovery(const FoldMotion& m, int samples) {
  if (samples < 2) throw InputError("samples", "need at least 2");
  std::vector<double> ts;
  for (int k = 0; k < samples; ++k) ts.push_back(static_cast<double>(k) / (samples - 1));
  return rolling_recovery(m, right_profile_curve(m), ts);
}

}  // namespace rigidfold::sorce
