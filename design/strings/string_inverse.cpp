#include "design/strings/string_inverse.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "design/strings/string_vertex.hpp"

namespace rigidfold::design {

std::vector<double> transmitted_thetas(double theta0, int n) {
  std::vector<double> t(n);
  for (int i = 0; i < n; ++i) t[i] = i % 2 == 0 ? theta0 : -theta0;
  return t;
}

namespace {

// Distance of the vertex to every bound (radians); < 0 when a bound is violated.
double vertex_margin(double a1, double a2, double theta, const StringBounds& b) {
  const double lim = string_theta_limit(a1, a2);
  return std::min({a1 - b.alpha_min, b.alpha_max - a1, a2 - b.alpha_min, b.alpha_max - a2,
                   lim - b.theta_margin - std::fabs(theta)});
}

}  // namespace

DeflectionDesign design_from_deflections(const std::vector<double>& phi, const std::vector<double>& psi,
                                         const std::vector<double>& theta, const StringBounds& bounds) {
  if (phi.size() != psi.size() || phi.size() != theta.size())
    throw std::invalid_argument("design_from_deflections: phi, psi and theta need one value per vertex");
  DeflectionDesign d;
  d.feasible = true;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    VertexDesign v;
    v.theta = theta[i];
    if (!(theta[i] != 0)) {
      v.reason = "theta = 0 (flat): every alpha gives phi = psi = 0";
    } else if (!string_vertex_inverse(phi[i], psi[i], theta[i], v.alpha1, v.alpha2)) {
      v.reason = "no alpha in (0, 90) deg gives this (phi, psi) at this theta (phi must have the sign of theta and "
                 "the direction must lie within |theta| of the bisector plane's normal)";
    } else if (vertex_margin(v.alpha1, v.alpha2, theta[i], bounds) < 0) {
      v.reason = std::fabs(theta[i]) > string_theta_limit(v.alpha1, v.alpha2) - bounds.theta_margin
                     ? "|theta| beyond the vertex's theta limit minus the margin"
                     : "alpha outside [alpha_min, alpha_max]";
    } else {
      v.feasible = true;
      const StringVertexState s = string_vertex_state(v.alpha1, v.alpha2, theta[i]);
      v.phi_error = s.phi - phi[i];
      v.psi_error = s.psi - psi[i];
    }
    d.feasible = d.feasible && v.feasible;
    d.vertices.push_back(v);
  }
  return d;
}

Eigen::Matrix3d initial_frame(const Eigen::Vector3d& d, double roll) {
  const Eigen::Vector3d x = d.normalized();
  Eigen::Vector3d ref = Eigen::Vector3d::UnitY();
  if (x.cross(ref).norm() < 1e-6) ref = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d y0 = (ref - ref.dot(x) * x).normalized();
  const Eigen::Vector3d y = std::cos(roll) * y0 + std::sin(roll) * x.cross(y0);
  Eigen::Matrix3d F;
  F.col(0) = x;
  F.col(1) = y;
  F.col(2) = x.cross(y);
  return F;
}

namespace {

struct Walk {
  CurveDesign design;
  int reached = 0;  // vertices feasible before the first failure
};

// Sequential closed form for one (theta0, roll). Infeasible vertices get alphas clamped
// into the bounds so that the walk (and an NLopt start) can go on.
// stop_at_failure: return at the first infeasible vertex (the grid search only ranks).
Walk walk(const std::vector<Eigen::Vector3d>& dirs, const std::vector<double>& lengths, double theta0, double roll,
          const StringBounds& b, bool stop_at_failure) {
  const int n = static_cast<int>(dirs.size()) - 1;
  Walk w;
  CurveDesign& c = w.design;
  c.theta0 = theta0;
  c.roll = roll;
  c.string.lengths = lengths;
  c.string.width = 0;
  c.pose.frame = initial_frame(dirs[0], roll);
  c.alpha_margin = std::numeric_limits<double>::infinity();
  c.feasible = true;
  Eigen::Matrix3d F = c.pose.frame;
  const double cot_lo = 1 / std::tan(b.alpha_max), cot_hi = 1 / std::tan(b.alpha_min);
  for (int i = 0; i < n; ++i) {
    VertexDesign v;
    v.theta = i % 2 == 0 ? theta0 : -theta0;
    const Eigen::Vector3d local = F.transpose() * dirs[i + 1];
    v.feasible = string_vertex_inverse_direction(local, v.theta, v.alpha1, v.alpha2);
    if (!v.feasible) v.reason = "outgoing direction outside the vertex's reachable cone at this theta";
    if (v.feasible && vertex_margin(v.alpha1, v.alpha2, v.theta, b) < 0) {
      v.feasible = false;
      v.reason = "alpha or theta outside the bounds";
    }
    if (v.feasible) {
      c.alpha_margin = std::min(c.alpha_margin, vertex_margin(v.alpha1, v.alpha2, v.theta, b));
    } else {
      if (c.feasible) c.first_infeasible = i;
      c.feasible = false;
      c.alpha_margin = -1;
      if (stop_at_failure) return w;
      // Clamp: same formulas as the inverse with the cotangents kept in the bounds.
      const double yz2 = local.y() * local.y() + local.z() * local.z();
      const Eigen::Vector3d a = local.normalized();
      const double omx = yz2 > 0 ? std::max(1 - a.x(), 1e-12) : 1.0;
      const double st = std::sin(v.theta), ct = std::cos(v.theta);
      double c1 = (a.y() * ct + a.z() * st) / omx, c2 = (-a.y() * ct + a.z() * st) / omx;
      if (!std::isfinite(c1)) c1 = cot_lo;
      if (!std::isfinite(c2)) c2 = cot_lo;
      v.alpha1 = std::atan(1 / std::clamp(c1, cot_lo, cot_hi));
      v.alpha2 = std::atan(1 / std::clamp(c2, cot_lo, cot_hi));
      if (std::fabs(v.theta) >= string_theta_limit(v.alpha1, v.alpha2) - b.theta_margin)
        v.alpha1 = v.alpha2 = 0.5 * (v.alpha1 + v.alpha2);  // symmetric: limit pi/2
    }
    if (c.feasible) w.reached = i + 1;
    c.string.alpha1.push_back(v.alpha1);
    c.string.alpha2.push_back(v.alpha2);
    F = F * string_vertex_state(v.alpha1, v.alpha2, v.theta).rotation;
    c.vertices.push_back(v);
  }
  return w;
}

}  // namespace

CurveDesign design_from_curve(const std::vector<Eigen::Vector3d>& points, const CurveDesignOptions& o) {
  if (points.size() < 3) throw std::invalid_argument("points: a string of N >= 1 vertices needs N + 2 >= 3 points");
  std::vector<Eigen::Vector3d> dirs;
  std::vector<double> lengths;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (!points[k].allFinite() || !points[k + 1].allFinite())
      throw std::invalid_argument("points[" + std::to_string(k) + "]: must be finite");
    const Eigen::Vector3d d = points[k + 1] - points[k];
    const double len = d.norm();
    if (!(len >= o.bounds.min_segment))
      throw std::invalid_argument("points[" + std::to_string(k + 1) + "]: segment shorter than the minimum segment length");
    dirs.push_back(d / len);
    lengths.push_back(len);
  }
  const double theta_max = std::numbers::pi / 2 - o.bounds.theta_margin;
  std::vector<double> thetas, rolls;
  if (o.theta0) {
    thetas.push_back(*o.theta0);
  } else {
    for (int j = 0; j < o.theta_samples; ++j) {
      const double t = theta_max * (j + 0.5) / o.theta_samples;
      thetas.push_back(t);
      thetas.push_back(-t);
    }
  }
  if (o.roll) rolls.push_back(*o.roll);
  else
    for (int j = 0; j < o.roll_samples; ++j) rolls.push_back(-std::numbers::pi + 2 * std::numbers::pi * j / o.roll_samples);
  int best_reached = -1;
  double best_margin = -1, best_theta = thetas[0], best_roll = rolls[0];
  long cell = 0;
  const long cells = static_cast<long>(thetas.size() * rolls.size());
  for (double t : thetas)
    for (double r : rolls) {
      report_progress(o.progress, [&] {
        return "string design: closed-form grid, cell " + std::to_string(++cell) + " of " + std::to_string(cells) +
               " (" + std::to_string(points.size()) + " points)";
      });
      const Walk w = walk(dirs, lengths, t, r, o.bounds, true);
      if (w.reached > best_reached || (w.reached == best_reached && w.design.alpha_margin > best_margin)) {
        best_reached = w.reached;
        best_margin = w.design.alpha_margin;
        best_theta = t;
        best_roll = r;
      }
    }
  Walk best = walk(dirs, lengths, best_theta, best_roll, o.bounds, false);
  best.design.pose.start = points[0];
  return best.design;
}

}  // namespace rigidfold::design
