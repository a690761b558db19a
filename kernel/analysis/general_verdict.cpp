#include "kernel/analysis/general_verdict.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/bordered_determinant.hpp"
#include "kernel/solve/portable_random.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace {

double inf_norm(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

// Assigned sign per edge: -1 M, +1 V, 0 otherwise (or when letters are ignored).
std::vector<int> assigned_signs(const CreasePattern& p, bool use) {
  std::vector<int> s(p.num_edges(), 0);
  if (!use) return s;
  for (int e = 0; e < p.num_edges(); ++e) s[e] = assigned_fold_sign(p.assignments[e]);
  return s;
}

// First M/V crease with the wrong sign beyond tol, or -1.
int wrong_sign(const Eigen::VectorXd& rho, const std::vector<int>& sign, double tol) {
  for (int e = 0; e < static_cast<int>(sign.size()); ++e)
    if (sign[e] != 0 && sign[e] * rho[e] < -tol) return e;
  return -1;
}

// Driving creases: free creases touching two interior vertices first, then one, then none;
// `count` of them spread evenly over that list.
std::vector<int> driving_creases(const ClosureSystem& sys, const Topology& t, int count) {
  std::vector<int> touches(sys.num_edges(), 0);
  for (int v : t.interior_vertices)
    for (int e : t.stars[v].fans[0].edges) ++touches[e];
  std::vector<int> list = sys.free_edges();
  std::stable_sort(list.begin(), list.end(), [&](int a, int b) { return touches[a] > touches[b]; });
  std::vector<int> out;
  const int n = static_cast<int>(list.size());
  for (int k = 0; k < std::min(count, n); ++k) {
    const int e = list[static_cast<std::size_t>(k) * n / std::min(count, n)];
    if (std::find(out.begin(), out.end(), e) == out.end()) out.push_back(e);
  }
  return out;
}

struct Tracer {
  const ClosureSystem& sys;
  const std::vector<int>& sign;
  const GeneralVerdictOptions& opt;
  int driving_edge;
  GeneralVerdict& out;
  Eigen::VectorXd start_rho;
  Eigen::VectorXd prev_rho;
  std::vector<bool> switched;
  // Bordered-determinant test for DOF-1 traces (bordered_determinant.hpp): a sign change
  // between consecutive points means the Jacobian lost rank in between (a candidate
  // bifurcation); a point where the DOF is not 1 is itself singular.
  BorderedDeterminantMonitor bordered;
  bool bordered_active = false;
  Eigen::VectorXd prev_x;
  int valid_points = 0;  // points of out.path with every letter respected

  void start_bordered(const Eigen::VectorXd& x, const Eigen::VectorXd& direction) {
    bordered_active = bordered.step(dense_jacobian(sys, x), direction).applicable;
    prev_x = x;
  }

  // Records the accepted point x; returns true to stop.
  bool accept(const Eigen::VectorXd& x) {
    const Eigen::VectorXd rho = sys.edges_from_unknowns(x);
    out.max_residual = std::max(out.max_residual, inf_norm(sys.residual(x)));
    if (out.path.empty()) {
      start_rho = rho;
      switched.assign(rho.size(), false);
    }
    out.path.push_back(rho);
    bool stop = false;
    bool invalid = false;
    // Sign changes relative to the start.
    if (out.path.size() > 1) {
      for (int e = 0; e < rho.size(); ++e) {
        if (switched[e] || std::abs(start_rho[e]) <= opt.zero_tolerance) continue;
        if (start_rho[e] * rho[e] < 0 && std::abs(rho[e]) > opt.zero_tolerance) {
          switched[e] = true;
          const double f = prev_rho[e] / (prev_rho[e] - rho[e]);
          SignSwitch s;
          s.crease = e;
          s.driving_value = prev_rho[driving_edge] + f * (rho[driving_edge] - prev_rho[driving_edge]);
          s.against_assignment = sign[e] != 0 && sign[e] * rho[e] < 0;
          out.sign_switches.push_back(s);
        }
      }
    }
    const int bad = wrong_sign(rho, sign, opt.zero_tolerance);
    if (bad >= 0) {
      out.stopped_by = "sign switch";
      out.stop_crease = bad;
      invalid = stop = true;
    }
    int big = 0;
    rho.cwiseAbs().maxCoeff(&big);
    if (!invalid && std::abs(rho[big]) >= opt.fold_limit) {
      out.stopped_by = "fold limit";
      out.stop_crease = big;
      stop = true;
      if (std::abs(rho[big]) > std::numbers::pi) invalid = true;  // past 180 deg: faces pass through each other
    }
    if (bordered_active && out.path.size() > 1) {
      const BorderedDeterminantMonitor::Step st = bordered.step(dense_jacobian(sys, x), x - prev_x);
      prev_x = x;
      if (!st.applicable || st.sign_changed) {
        // Not applicable: the DOF jumped at an accepted point (a singular point right here).
        SingularPoint sp;
        sp.angles = !st.applicable ? rho : Eigen::VectorXd(prev_rho + st.fraction * (rho - prev_rho));
        sp.driving_value = sp.angles[driving_edge];
        sp.max_fold = sp.angles.cwiseAbs().maxCoeff();
        out.singular_points.push_back(sp);
        if (out.stopped_by.empty()) out.stopped_by = "singular point";
        stop = true;
      }
    }
    if (!invalid) {
      valid_points = static_cast<int>(out.path.size());
      out.max_fold = std::max(out.max_fold, rho.cwiseAbs().maxCoeff());
    }
    prev_rho = rho;
    if (!stop && static_cast<int>(out.path.size()) >= opt.max_path_points) {
      out.stopped_by = "max points";
      stop = true;
    }
    return stop;
  }
};

}  // namespace

GeneralVerdict general_verdict(const CreasePattern& pattern, const Topology& topology,
                               const GeneralVerdictOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  GeneralVerdict out;
  auto finish = [&]() {
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  const ClosureSystem sys(pattern, topology);
  const int n = sys.num_unknowns();
  out.num_unknowns = n;
  const std::vector<int> sign = assigned_signs(pattern, opt.use_assignment);
  if (n == 0) {
    out.verdict = Verdict::kNotRigidlyFoldable;
    out.is_proof = true;
    out.reason = "no foldable crease";
    return finish();
  }

  // 1. Search.
  struct Candidate {
    Eigen::VectorXd x;
    int edge;
  };
  std::vector<Candidate> candidates;
  double least = std::numeric_limits<double>::infinity();
  Eigen::VectorXd least_x;
  SplitMix64 rng{opt.seed};
  const std::vector<int> drivers = driving_creases(sys, topology, opt.max_driving_creases);
  for (int e : drivers) {
    const int k = sys.unknown_of_edge(e);
    for (int s = 0; s < opt.starts_per_crease; ++s) {
      Eigen::VectorXd x0(n);
      for (int i = 0; i < n; ++i) {
        const double mag = opt.start_min + (opt.start_max - opt.start_min) * rng.uniform();
        const int sg = sign[sys.edge_of_unknown(i)];
        const double dir = sg != 0 ? sg : (rng.uniform() < 0.5 ? -1.0 : 1.0);
        x0[i] = dir * mag;
      }
      x0[k] = (sign[e] != 0 ? sign[e] : 1) * opt.held_value;
      NewtonOptions nopt;
      nopt.tolerance = opt.residual_tolerance;
      nopt.held_unknowns = {k};
      nopt.max_iterations = opt.least_squares_iterations;
      const NewtonResult nr = newton_project(sys, x0, nopt);
      ++out.starts_tried;
      if (!nr.converged) {
        const double res = inf_norm(sys.residual(nr.x));
        if (res < least) {
          least = res;
          least_x = nr.x;
        }
        continue;
      }
      ++out.starts_converged;
      const Eigen::VectorXd rho = sys.edges_from_unknowns(nr.x);
      const int bad = wrong_sign(rho, sign, opt.zero_tolerance);
      if (bad >= 0) {
        ++out.starts_wrong_sign;
        if (out.wrong_sign_crease < 0) out.wrong_sign_crease = bad;
        continue;
      }
      candidates.push_back({nr.x, e});
    }
  }

  if (candidates.empty()) {
    out.verdict = Verdict::kNotRigidlyFoldable;
    out.is_proof = false;
    std::ostringstream why;
    why << "no folded point found near flat (" << out.starts_tried << " starts, " << drivers.size()
        << " driving creases held at " << opt.held_value << " rad)";
    if (out.starts_wrong_sign > 0)
      why << "; " << out.starts_wrong_sign << " converged only against the assignment (e.g. crease "
          << out.wrong_sign_crease << ")";
    if (std::isfinite(least)) {
      out.least_residual = least;
      const Eigen::VectorXd r = sys.residual(least_x);
      for (int b = 0; b < sys.num_vertices(); ++b)
        out.worst_vertices.emplace_back(sys.vertex_of_block(b), r.segment(3 * b, 3).norm());
      std::sort(out.worst_vertices.begin(), out.worst_vertices.end(),
                [](const auto& a, const auto& b) { return a.second > b.second; });
      if (out.worst_vertices.size() > 5) out.worst_vertices.resize(5);
      why << "; least residual " << least;
      if (!out.worst_vertices.empty()) why << " (worst vertex " << out.worst_vertices[0].first << ")";
    }
    why << " - numerical evidence within the search, not a proof";
    out.reason = why.str();
    return finish();
  }

  // 2-4. Trace candidates until one certifies.
  GeneralVerdict best;
  bool have_best = false;
  const int ntrace = std::min<int>(opt.max_candidates_traced, static_cast<int>(candidates.size()));
  for (int c = 0; c < ntrace; ++c) {
    GeneralVerdict trial = out;
    const Candidate& cand = candidates[c];
    trial.driving_crease = cand.edge;
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys.evaluate(cand.x, r, J);
    const RankResult rk = jacobian_rank(J);
    trial.dof = rk.dof;
    Tracer tr{sys, sign, opt, cand.edge, trial, {}, {}, {}, BorderedDeterminantMonitor(), false, {}, 0};
    if (rk.dof == 1) {
      if (n <= opt.singular_detection_limit) tr.start_bordered(cand.x, cand.x);
      const ContinuationResult cr =
          continue_one_dof(sys, cand.x, cand.x, [&](const Eigen::VectorXd& x) { return tr.accept(x); },
                           opt.continuation);
      if (trial.stopped_by.empty()) trial.stopped_by = cr.reason;
    } else {
      const int k = sys.unknown_of_edge(cand.edge);
      const double dir = cand.x[k] >= 0 ? 1.0 : -1.0;
      Eigen::VectorXd x = cand.x;
      NewtonOptions nopt;
      nopt.tolerance = opt.residual_tolerance;
      nopt.held_unknowns = {k};
      bool stop = tr.accept(x);
      while (!stop) {
        // Predictor: scale the whole point with the driving crease (keeps its shape and
        // signs); the corrector then moves it the least distance back onto the manifold.
        const double target = std::abs(x[k]) + opt.driven_step >= opt.fold_limit
                                  ? dir * opt.fold_limit
                                  : x[k] + dir * opt.driven_step;
        Eigen::VectorXd x0 = x * (target / x[k]);
        const NewtonResult nr = newton_project(sys, x0, nopt);
        if (!nr.converged) {
          trial.stopped_by = "corrector failed";
          break;
        }
        x = nr.x;
        stop = tr.accept(x);
      }
    }
    if (tr.valid_points > 0) {
      trial.certificate_angles = trial.path[tr.valid_points - 1];
      trial.certificate_mismatch =
          place_faces(pattern, topology, trial.certificate_angles, reference_fold_angles(pattern, topology))
              .relative_mismatch();
    }
    const bool ok = trial.max_fold >= opt.certificate_fold && trial.certificate_mismatch >= 0 &&
                    trial.certificate_mismatch <= opt.mismatch_tolerance;
    if (ok) {
      trial.verdict = Verdict::kRigidlyFoldable;
      trial.is_proof = false;
      std::ostringstream why;
      why << "traced a folding path to max |rho| = " << trial.max_fold << " rad (DOF " << trial.dof
          << ", max residual " << trial.max_residual << ", placement mismatch " << trial.certificate_mismatch
          << "); stopped by " << trial.stopped_by;
      trial.reason = why.str();
      out = std::move(trial);
      return finish();
    }
    if (!have_best || trial.max_fold > best.max_fold) {
      best = std::move(trial);
      have_best = true;
    }
  }
  out = std::move(best);
  out.verdict = Verdict::kUndecided;
  std::ostringstream why;
  why << "folded points found near flat but no trace reached " << opt.certificate_fold
      << " rad (best " << out.max_fold << ", stopped by " << out.stopped_by << ")";
  out.reason = why.str();
  return finish();
}

}  // namespace rigidfold
