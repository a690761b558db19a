#include "design/strings/string_fit_nlopt.hpp"

#include <ceres/jet.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <numbers>
#include <stdexcept>

#include "design/nlopt/nlopt_result_name.hpp"
#include "design/strings/string_vertex.hpp"
#include "kernel/math/so3.hpp"

namespace rigidfold::design {

void curve_errors(const MiuraString& s, double theta0, const StringPose& pose, const std::vector<Eigen::Vector3d>& points,
                  double& max_error, double& rms_error, std::vector<double>* per_point) {
  const StringState st = string_forward(s, theta0, pose);
  if (st.spine.size() != points.size()) throw std::invalid_argument("curve_errors: N + 2 points needed");
  max_error = 0;
  double sum = 0;
  if (per_point) per_point->clear();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double e = (st.spine[k] - points[k]).norm();
    max_error = std::max(max_error, e);
    sum += e * e;
    if (per_point) per_point->push_back(e);
  }
  rms_error = std::sqrt(sum / points.size());
}

namespace {

using Jet3 = ceres::Jet<double, 3>;

struct Problem {
  int n = 0;
  std::vector<Eigen::Vector3d> Q;
  Eigen::Matrix3d F_seed;
  double scale = 1;  // 1 / (Lbar^2 (N + 1))
  StringBounds bounds;
  bool per_vertex_constraints = true;
  int evaluations = 0;
  const ProgressSink* progress = nullptr;
  std::string stage;

  int i_theta() const { return 2 * n; }
  int i_w() const { return 2 * n + 1; }
  int i_len() const { return 2 * n + 4; }
  int size() const { return 3 * n + 5; }

  // Objective and (when grad is non-empty) its gradient.
  double evaluate(const std::vector<double>& x, std::vector<double>& grad) {
    ++evaluations;
    if (progress)
      report_progress(*progress, [&] {
        return "string design: NLopt " + stage + ", evaluation " + std::to_string(evaluations) + " (" +
               std::to_string(n) + " vertices)";
      });
    const bool want = !grad.empty();
    const double theta0 = x[i_theta()];
    const Eigen::Vector3d w(x[i_w()], x[i_w() + 1], x[i_w() + 2]);
    std::vector<Eigen::Matrix3d> F(n + 1), R(n);
    std::vector<std::array<Eigen::Vector3d, 3>> omega_loc(want ? n : 0);  // d R_i R_i^T per (a1, a2, theta)
    std::vector<Eigen::Vector3d> P(n + 2);
    F[0] = so3_exp(w) * F_seed;
    P[0] = Q[0];
    for (int i = 0; i < n; ++i) {
      const double th = i % 2 == 0 ? theta0 : -theta0;
      if (want) {
        Jet3 a1(x[2 * i], 0), a2(x[2 * i + 1], 1), t(th, 2), Rj[9];
        string_vertex_frame(a1, a2, t, Rj);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) R[i](r, c) = Rj[3 * r + c].a;
        for (int q = 0; q < 3; ++q) {
          Eigen::Matrix3d dR;
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) dR(r, c) = Rj[3 * r + c].v[q];
          const Eigen::Matrix3d S = dR * R[i].transpose();  // skew for an exact rotation
          omega_loc[i][q] = skew_part_vector(S);
        }
      } else {
        double Rd[9];
        string_vertex_frame(x[2 * i], x[2 * i + 1], th, Rd);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) R[i](r, c) = Rd[3 * r + c];
      }
      P[i + 1] = P[i] + x[i_len() + i] * F[i].col(0);
      F[i + 1] = F[i] * R[i];
    }
    P[n + 1] = P[n] + x[i_len() + n] * F[n].col(0);
    double f = 0;
    std::vector<Eigen::Vector3d> r(n + 2);
    for (int k = 0; k <= n + 1; ++k) {
      r[k] = P[k] - Q[k];
      f += r[k].squaredNorm();
    }
    f *= scale;
    if (!want) return f;
    // Suffix sums S_m = sum_{k>=m} r_k, C_m = sum_{k>=m} P_k x r_k.
    std::vector<Eigen::Vector3d> Ssum(n + 3, Eigen::Vector3d::Zero()), Csum(n + 3, Eigen::Vector3d::Zero());
    for (int k = n + 1; k >= 0; --k) {
      Ssum[k] = Ssum[k + 1] + r[k];
      Csum[k] = Csum[k + 1] + P[k].cross(r[k]);
    }
    std::fill(grad.begin(), grad.end(), 0.0);
    const double s2 = 2 * scale;
    for (int i = 0; i < n; ++i) {
      // Turning R_i rotates the points after V_i (P_{i+2}..) about V_i = P_{i+1}.
      const Eigen::Vector3d moment = Csum[i + 2] - P[i + 1].cross(Ssum[i + 2]);
      for (int q = 0; q < 3; ++q) {
        const double g = s2 * (F[i] * omega_loc[i][q]).dot(moment);
        if (q < 2) grad[2 * i + q] += g;
        else grad[i_theta()] += i % 2 == 0 ? g : -g;
      }
    }
    const Eigen::Matrix3d J = so3_left_jacobian(w);
    const Eigen::Vector3d moment0 = Csum[1] - P[0].cross(Ssum[1]);
    for (int q = 0; q < 3; ++q) grad[i_w() + q] = s2 * J.col(q).dot(moment0);
    for (int j = 0; j <= n; ++j) grad[i_len() + j] = s2 * F[j].col(0).dot(Ssum[j + 1]);
    return f;
  }
};

double objective(const std::vector<double>& x, std::vector<double>& grad, void* data) {
  return static_cast<Problem*>(data)->evaluate(x, grad);
}

// Vector constraint: one per vertex, tan^4(|theta0| + m) sin^2(a2 - a1) - sin^2(a1 + a2) <= 0.
void theta_constraints(unsigned m, double* result, unsigned nx, const double* x, double* grad, void* data) {
  const auto* p = static_cast<const Problem*>(data);
  const int n = p->n;
  const double th = x[p->i_theta()];
  const double te = std::fabs(th) + p->bounds.theta_margin;
  const double t2 = std::tan(te) * std::tan(te);
  const double dt2 = 2 * std::tan(te) / (std::cos(te) * std::cos(te)) * (th >= 0 ? 1.0 : -1.0);  // d tan^2 / d theta0
  if (grad) std::fill(grad, grad + static_cast<std::size_t>(m) * nx, 0.0);
  for (int i = 0; i < n; ++i) {
    const double a1 = x[2 * i], a2 = x[2 * i + 1];
    const double sd = std::sin(a2 - a1), ss = std::sin(a1 + a2), cd = std::cos(a2 - a1), cs = std::cos(a1 + a2);
    result[i] = t2 * t2 * sd * sd - ss * ss;
    if (grad) {
      double* g = grad + static_cast<std::size_t>(i) * nx;
      g[2 * i] = t2 * t2 * 2 * sd * cd * (-1) - 2 * ss * cs;
      g[2 * i + 1] = t2 * t2 * 2 * sd * cd - 2 * ss * cs;
      g[p->i_theta()] = 2 * t2 * dt2 * sd * sd;
    }
  }
}

nlopt::algorithm algorithm_from_name(const std::string& name) {
  if (name == "LD_SLSQP") return nlopt::LD_SLSQP;
  if (name == "LD_MMA") return nlopt::LD_MMA;
  if (name == "LD_CCSAQ") return nlopt::LD_CCSAQ;
  if (name == "LN_COBYLA") return nlopt::LN_COBYLA;
  if (name == "GN_ISRES") return nlopt::GN_ISRES;
  throw std::invalid_argument("algorithm: unknown NLopt algorithm '" + name +
                              "' (LD_SLSQP, LD_MMA, LD_CCSAQ, LN_COBYLA; global GN_ISRES)");
}

// Runs one NLopt stage from x (in place). Returns the result code name. Roundoff-limited
// stops (nlopt::roundoff_limited) keep the best point NLopt found.
std::string run_stage(Problem& p, nlopt::algorithm alg, std::vector<double>& x, const std::vector<double>& lo,
                      const std::vector<double>& hi, int max_eval, double max_time, double ftol, double xtol) {
  nlopt::opt opt(alg, p.size());
  opt.set_lower_bounds(lo);
  opt.set_upper_bounds(hi);
  opt.set_min_objective(objective, &p);
  if (p.per_vertex_constraints) opt.add_inequality_mconstraint(theta_constraints, &p, std::vector<double>(p.n, 1e-14));
  opt.set_maxeval(max_eval);
  opt.set_maxtime(max_time);
  opt.set_ftol_rel(ftol);
  opt.set_xtol_rel(xtol);
  opt.set_stopval(1e-30);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::clamp(x[k], lo[k], hi[k]);
  double f = 0;
  try {
    return nlopt_result_name(opt.optimize(x, f));
  } catch (const nlopt::roundoff_limited&) {
    return "ROUNDOFF_LIMITED";
  } catch (const nlopt::forced_stop&) {
    return "FORCED_STOP";
  }
}

}  // namespace

NloptFitResult fit_string_to_curve(const std::vector<Eigen::Vector3d>& points, const NloptFitOptions& o) {
  const CurveDesign seed = design_from_curve(points, o.seed);  // validates the points
  const StringBounds& b = o.seed.bounds;
  Problem p;
  p.n = static_cast<int>(points.size()) - 2;
  p.Q = points;
  p.F_seed = seed.pose.frame;
  p.bounds = b;
  double total = 0, longest = 0;
  for (double L : seed.string.lengths) {
    total += L;
    longest = std::max(longest, L);
  }
  const double Lbar = total / (p.n + 1);
  p.scale = 1 / (Lbar * Lbar * (p.n + 1));
  const std::string local_name = o.algorithm == "auto" ? (p.n <= 50 ? "LD_SLSQP" : "LD_CCSAQ") : o.algorithm;
  const nlopt::algorithm local = algorithm_from_name(local_name);
  std::vector<double> x(p.size()), lo(p.size()), hi(p.size());
  for (int i = 0; i < p.n; ++i) {
    x[2 * i] = o.closed_form_seed ? seed.string.alpha1[i] : std::numbers::pi / 4;
    x[2 * i + 1] = o.closed_form_seed ? seed.string.alpha2[i] : std::numbers::pi / 4;
  }
  x[p.i_theta()] = seed.theta0;
  for (int j = 0; j <= p.n; ++j) x[p.i_len() + j] = seed.string.lengths[j];
  for (int i = 0; i < 2 * p.n; ++i) {
    lo[i] = b.alpha_min;
    hi[i] = b.alpha_max;
  }
  p.per_vertex_constraints = o.theta_constraints == "per_vertex" || (o.theta_constraints == "auto" && p.n <= 30);
  if (!p.per_vertex_constraints && o.theta_constraints != "box" && o.theta_constraints != "auto")
    throw std::invalid_argument("theta_constraints: must be per_vertex, box or auto");
  const double theta_box = p.per_vertex_constraints ? std::numbers::pi / 2 - b.theta_margin - 1e-6
                                                    : string_theta_limit(b.alpha_min, b.alpha_max) - b.theta_margin;
  lo[p.i_theta()] = -theta_box;
  hi[p.i_theta()] = -lo[p.i_theta()];
  for (int q = 0; q < 3; ++q) {
    lo[p.i_w() + q] = -std::numbers::pi;
    hi[p.i_w() + q] = std::numbers::pi;
  }
  for (int j = 0; j <= p.n; ++j) {
    lo[p.i_len() + j] = b.min_segment;
    hi[p.i_len() + j] = std::max(10 * longest, 2 * b.min_segment);
  }
  NloptFitResult res;
  res.seed_feasible = seed.feasible;
  x[p.i_theta()] = std::clamp(x[p.i_theta()], lo[p.i_theta()], hi[p.i_theta()]);
  res.algorithm = local_name;
  p.progress = &o.seed.progress;
  if (o.global) {
    p.stage = "GN_ISRES (global)";
    res.status = run_stage(p, algorithm_from_name("GN_ISRES"), x, lo, hi, o.global_evaluations, o.max_time, 0, 0);
    res.algorithm = "GN_ISRES + " + local_name;
  }
  // A reachable target's seed is already exact: NLopt only confirms it (stopval).
  p.stage = local_name;
  res.status = run_stage(p, local, x, lo, hi, o.max_evaluations, o.max_time, o.ftol_rel, o.xtol_rel);
  res.evaluations = p.evaluations;
  for (int i = 0; i < p.n; ++i) {
    res.string.alpha1.push_back(x[2 * i]);
    res.string.alpha2.push_back(x[2 * i + 1]);
  }
  for (int j = 0; j <= p.n; ++j) res.string.lengths.push_back(x[p.i_len() + j]);
  res.string.width = 0;
  res.theta0 = x[p.i_theta()];
  res.pose.start = points[0];
  res.pose.frame = so3_exp(Eigen::Vector3d(x[p.i_w()], x[p.i_w() + 1], x[p.i_w() + 2])) * p.F_seed;
  res.mean_segment = Lbar;
  // The theta constraint may be violated by NLopt's tolerance: the forward check is strict.
  try {
    curve_errors(res.string, res.theta0, res.pose, points, res.max_error, res.rms_error, &res.point_errors);
  } catch (const std::invalid_argument& e) {
    res.max_error = res.rms_error = std::numeric_limits<double>::infinity();
    res.binding.push_back(std::string("forward check failed: ") + e.what());
  }
  res.reachable = res.max_error <= o.tolerance * Lbar;
  const double tol = 1e-7;
  for (int i = 0; i < p.n; ++i) {
    const double a[2] = {x[2 * i], x[2 * i + 1]};
    for (int s = 0; s < 2; ++s) {
      const std::string name = std::string(s == 0 ? "alpha1[" : "alpha2[") + std::to_string(i) + "]";
      if (a[s] - b.alpha_min < tol) res.binding.push_back(name + " = alpha_min");
      if (b.alpha_max - a[s] < tol) res.binding.push_back(name + " = alpha_max");
    }
    if (p.per_vertex_constraints && string_theta_limit(a[0], a[1]) - b.theta_margin - std::fabs(res.theta0) < tol)
      res.binding.push_back("theta limit (minus margin) at vertex " + std::to_string(i));
  }
  if (!p.per_vertex_constraints && theta_box - std::fabs(res.theta0) < tol) res.binding.push_back("theta box bound");
  for (int j = 0; j <= p.n; ++j)
    if (x[p.i_len() + j] - b.min_segment < tol * Lbar) res.binding.push_back("lengths[" + std::to_string(j) + "] = min_segment");
  return res;
}

}  // namespace rigidfold::design
