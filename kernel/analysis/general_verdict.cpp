#include "kernel/analysis/general_verdict.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "kernel/analysis/flat_crease_push.hpp"
#include "kernel/analysis/path_watch.hpp"
#include "kernel/analysis/rounding_residual_bound.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/solve/amplitude_search.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/norm_continuation.hpp"
#include "kernel/solve/bordered_determinant.hpp"
#include "kernel/solve/portable_random.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {
namespace {

double inf_norm(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

// Assigned sign per edge (assigned_fold_sign), or all 0 when letters are ignored.
std::vector<int> assigned_signs(const CreasePattern& p, bool use) {
  std::vector<int> s(p.num_edges(), 0);
  if (use)
    for (int e = 0; e < p.num_edges(); ++e) s[e] = assigned_fold_sign(p.assignments[e]);
  return s;
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

// A pseudo-random start: |x_i| in [start_min, start_max] radians, the sign of every M/V
// crease following its letter, U creases either sign.
Eigen::VectorXd signed_start(const ClosureSystem& sys, const std::vector<int>& sign, const GeneralVerdictOptions& opt,
                             SplitMix64& rng) {
  Eigen::VectorXd x0(sys.num_unknowns());
  for (int i = 0; i < sys.num_unknowns(); ++i) {
    const double mag = opt.start_min + (opt.start_max - opt.start_min) * rng.uniform();
    const int sg = sign[sys.edge_of_unknown(i)];
    x0[i] = (sg != 0 ? sg : (rng.uniform() < 0.5 ? -1.0 : 1.0)) * mag;
  }
  return x0;
}

struct Tracer {
  const ClosureSystem& sys;
  const GeneralVerdictOptions& opt;
  TracedBranch& trace;
  PathWatch watch;
  // Bordered-determinant test for DOF-1 traces (bordered_determinant.hpp): a sign change
  // between consecutive points means the Jacobian lost rank in between (a candidate
  // bifurcation); a point where the DOF is not 1 is itself singular.
  std::vector<SingularPoint>& singular_points;
  BorderedDeterminantMonitor bordered{};
  bool bordered_active = false;
  Eigen::VectorXd prev_x{};
  Eigen::VectorXd prev_rho{};

  void start_bordered(const Eigen::VectorXd& x, const Eigen::VectorXd& direction) {
    bordered_active = bordered.step(dense_jacobian(sys, x), direction).applicable;
    prev_x = x;
  }

  void stop(StopReason why, int crease = -1) {
    if (trace.stopped_by != StopReason::kNone) return;
    trace.stopped_by = why;
    trace.stop_crease = crease;
  }

  // Records the accepted point x; returns true to stop.
  bool accept(const Eigen::VectorXd& x) {
    const Eigen::VectorXd rho = sys.edges_from_unknowns(x);
    trace.max_residual = std::max(trace.max_residual, inf_norm(sys.residual(x)));
    trace.path.push_back(rho);
    const PathWatch::Segment seg = watch.observe(rho);
    trace.sign_switches.insert(trace.sign_switches.end(), seg.switches.begin(), seg.switches.end());
    bool halt = false;
    bool invalid = false;
    const int bad = opt.use_assignment ? seg.first_against_letter : -1;
    if (bad >= 0) {
      stop(StopReason::kSignSwitch, bad);
      invalid = halt = true;
    }
    if (!invalid && seg.fold_limit_crease >= 0) {
      stop(StopReason::kFoldLimit, seg.fold_limit_crease);
      halt = true;
      if (std::abs(rho[seg.fold_limit_crease]) > std::numbers::pi) invalid = true;  // past 180 deg: faces pass through each other
    }
    if (bordered_active && trace.path.size() > 1) {
      const BorderedDeterminantMonitor::Step st = bordered.step(dense_jacobian(sys, x), x - prev_x);
      prev_x = x;
      if (!st.applicable || st.sign_changed) {
        // Not applicable: the DOF jumped at an accepted point (a singular point right here).
        SingularPoint sp;
        sp.angles = !st.applicable ? rho : Eigen::VectorXd(prev_rho + st.fraction * (rho - prev_rho));
        sp.driving_value = sp.angles[trace.driving_edge];
        sp.max_fold = sp.angles.cwiseAbs().maxCoeff();
        singular_points.push_back(sp);
        stop(StopReason::kSingularPoint);
        halt = true;
      }
    }
    if (!invalid) {
      trace.valid_points = static_cast<int>(trace.path.size());
      trace.max_fold = std::max(trace.max_fold, rho.cwiseAbs().maxCoeff());
    }
    prev_rho = rho;
    if (!halt && static_cast<int>(trace.path.size()) >= opt.max_path_points) {
      stop(StopReason::kMaxPoints);
      halt = true;
    }
    return halt;
  }
};

enum class TraceMethod { kOneDof, kFoldSize, kDrivingCrease };

// DOF > 1, by the fold's size (norm_continuation.hpp): first toward flat to 1/100 of the
// candidate's ||x||_2, every point keeping its letters (the first that does not ends that
// leg), then the path from there out through the candidate until the tracer stops it.
// Returns the size reached toward flat (radians).
double trace_by_fold_size(const ClosureSystem& sys, const Eigen::VectorXd& x0, const std::vector<int>& sign,
                          const GeneralVerdictOptions& opt, Tracer& tr,
                          const std::function<bool(const Eigen::VectorXd&)>& accept) {
  const int n = sys.num_unknowns();
  const Eigen::VectorXd lower = Eigen::VectorXd::Constant(n, -std::numbers::pi);
  const Eigen::VectorXd upper = Eigen::VectorXd::Constant(n, std::numbers::pi);
  NormContinuationOptions no;
  no.tolerance = opt.tolerances.residual;
  no.max_angle_step = opt.driven_step;
  no.max_points = opt.max_path_points / 2;
  no.target_size = x0.norm() / 100;
  if (opt.use_assignment)
    for (int i = 0; i < n; ++i) no.sign_floor.push_back(sign[sys.edge_of_unknown(i)]);
  std::vector<Eigen::VectorXd> inward;
  double reached = x0.norm();
  // The margin keeps the letters; a point that breaks one anyway (a crease moved past its
  // margin within the corrector's tolerance) ends the leg toward flat there.
  const NormContinuationResult in = continue_by_norm(sys, x0, lower, upper, no, [&](const Eigen::VectorXd& x) {
    if (first_crease_against_letter(sign, sys.edges_from_unknowns(x), opt.tolerances.sign_threshold) >= 0) return true;
    inward.push_back(x);
    reached = x.norm();
    return false;
  });
  tr.trace.linear_solver = "direct (CHOLMOD, Levenberg-Marquardt corrector at each fold size)";
  tr.trace.factorizations = in.factorizations;
  for (auto it = inward.rbegin(); it != inward.rend(); ++it)
    if (tr.accept(*it)) return reached;
  if (tr.accept(x0)) return reached;
  no.target_size = std::sqrt(static_cast<double>(n)) * std::numbers::pi;  // beyond any fold: the tracer stops first
  no.max_points = std::max(1, opt.max_path_points - static_cast<int>(tr.trace.path.size()));
  const NormContinuationResult outward = continue_by_norm(sys, x0, lower, upper, no, accept);
  tr.trace.factorizations += outward.factorizations;
  if (tr.trace.stopped_by == StopReason::kNone) {
    tr.stop(StopReason::kContinuationFailed);
    tr.trace.stop_message = "fold-size continuation: " + outward.reason;
  }
  return reached;
}

// DOF > 1, by a driving crease: it is stepped by driven_step and the rest Newton-projected.
void trace_by_driving_crease(const ClosureSystem& sys, const Eigen::VectorXd& x0, int k,
                             const GeneralVerdictOptions& opt, Tracer& tr,
                             const std::function<bool(const Eigen::VectorXd&)>& accept) {
  const double dir = x0[k] >= 0 ? 1.0 : -1.0;
  Eigen::VectorXd x = x0;
  NewtonOptions nopt;
  nopt.tolerance = opt.tolerances.residual;
  nopt.held_unknowns = {k};
  tr.trace.linear_solver = "direct (CHOLMOD, minimum-norm Newton with the driving crease held)";
  tr.trace.factorizations = 0;
  int newton_steps = 0, stale_steps = 0;  // above NewtonOptions::stale_factor_min_unknowns some steps reuse a factor
  bool stop = tr.accept(x);
  while (!stop) {
    // Predictor: scale the whole point with the driving crease (keeps its shape and
    // signs); the corrector then moves it the least distance back onto the manifold.
    const double limit = opt.tolerances.fold_limit();
    const double target = std::abs(x[k]) + opt.driven_step >= limit ? dir * limit : x[k] + dir * opt.driven_step;
    const Eigen::VectorXd xp = x * (target / x[k]);
    const NewtonResult nr = newton_project(sys, xp, nopt);
    tr.trace.factorizations += nr.factorizations;
    newton_steps += nr.iterations;
    stale_steps += nr.stale_steps;
    if (!nr.converged) {
      tr.stop(StopReason::kCorrectorFailed);
      break;
    }
    x = nr.x;
    stop = accept(x);
  }
  if (stale_steps > 0)
    tr.trace.linear_solver = "direct (CHOLMOD, minimum-norm Newton with the driving crease held); " +
                             std::to_string(stale_steps) + " of " + std::to_string(newton_steps) +
                             " Newton steps by CGLS preconditioned with the previous step's factor";
}

}  // namespace

const char* strict_verdict(const StrictnessReport& st) {
  if (st.strict) return "strictly foldable (certified: the certificate folds every M/V crease)";
  if (!st.strict_obstruction_vertices.empty()) return "not strictly foldable (proof: straight lettered lines cross)";
  return "undecided (a weak certificate only; no strict motion found, none ruled out)";
}

StrictnessReport strictness_at(const CreasePattern& pattern, const Eigen::VectorXd& rho) {
  StrictnessReport st;
  const double cut = st.flat_fraction * rho.cwiseAbs().maxCoeff();
  for (int e = 0; e < pattern.num_edges(); ++e)
    if (assigned_fold_sign(pattern.assignments[e]) != 0 && std::abs(rho[e]) <= cut) st.flat_lettered.push_back(e);
  st.strict = st.flat_lettered.empty();
  return st;
}

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
    bool far_from_flat = false;  // found at the pattern's scale: certified only by a path back toward flat
  };
  std::vector<Candidate> candidates;
  SplitMix64 rng{opt.seed};
  const std::vector<int> drivers = driving_creases(sys, topology, opt.max_driving_creases);
  for (int e : drivers) {
    const int k = sys.unknown_of_edge(e);
    for (int s = 0; s < opt.starts_per_crease; ++s) {
      report_progress(opt.progress, [&] {
        return "general search: start " + std::to_string(out.starts_tried + 1) + " of " +
               std::to_string(drivers.size() * opt.starts_per_crease) + " (" + std::to_string(n) + " unknowns)";
      });
      Eigen::VectorXd x0 = signed_start(sys, sign, opt, rng);
      x0[k] = (sign[e] != 0 ? sign[e] : 1) * opt.held_value;
      NewtonOptions nopt;
      nopt.tolerance = opt.tolerances.residual;
      nopt.held_unknowns = {k};
      nopt.max_iterations = opt.least_squares_iterations;
      nopt.stall_window = opt.least_squares_stall_window;
      const NewtonResult nr = newton_project(sys, x0, nopt);
      ++out.starts_tried;
      if (!nr.converged) continue;
      ++out.starts_converged;
      const Eigen::VectorXd rho = sys.edges_from_unknowns(nr.x);
      const int bad = first_crease_against_letter(sign, rho, opt.tolerances.sign_threshold);
      if (bad >= 0) {
        ++out.starts_wrong_sign;
        if (out.wrong_sign_crease < 0) out.wrong_sign_crease = bad;
        continue;
      }
      candidates.push_back({nr.x, e});
    }
  }

  // 5. No candidate: sign-respecting least squares at each amplitude (header, step 5).
  Eigen::VectorXd evidence_x;
  if (candidates.empty() && !drivers.empty()) {
    std::vector<int> bounds(n, 0);
    for (int i = 0; i < n; ++i) bounds[i] = sign[sys.edge_of_unknown(i)];
    SplitMix64 erng{opt.seed};
    std::vector<Eigen::VectorXd> unit_starts;  // one start per driving crease, magnitudes / start_max
    for (std::size_t d = 0; d < drivers.size(); ++d) {
      unit_starts.push_back(signed_start(sys, sign, opt, erng) / opt.start_max);
    }
    // Letters as bounds for the norm search (U: either side; at most a half turn).
    Eigen::VectorXd lower(n), upper(n);
    for (int i = 0; i < n; ++i) {
      lower[i] = bounds[i] > 0 ? 0.0 : -std::numbers::pi;
      upper[i] = bounds[i] < 0 ? 0.0 : std::numbers::pi;
    }
    // One start of the norm search (amplitude_search, ||x||_2 = amplitude, letters as bounds);
    // a converged point with its letters kept is a candidate. At the pattern's scale
    // (`at_patterns_scale`): lettered creases stepped in log|x|, and the candidate must be
    // traced back toward flat.
    auto norm_search_start = [&](double amplitude, int iterations, bool at_patterns_scale) {
      Eigen::VectorXd x0 = signed_start(sys, sign, opt, erng);
      x0 *= amplitude / x0.norm();
      AmplitudeSearchOptions ao;
      ao.amplitude = amplitude;
      ao.tolerance = opt.tolerances.residual;
      ao.max_iterations = iterations;
      ao.logarithmic = at_patterns_scale;
      const AmplitudeSearchResult ar = amplitude_search(sys, x0, lower, upper, ao);
      ++out.starts_tried;
      if (ar.converged &&
          first_crease_against_letter(sign, sys.edges_from_unknowns(ar.x), opt.tolerances.sign_threshold) < 0) {
        ++out.starts_converged;
        Eigen::Index k = 0;
        ar.x.cwiseAbs().maxCoeff(&k);
        candidates.push_back({ar.x, sys.edge_of_unknown(static_cast<int>(k)), at_patterns_scale});
      }
      return ar;
    };
    std::vector<Eigen::VectorXd> best_x;  // per amplitude: the state of the least residual
    for (double eps : opt.evidence_amplitudes) {
      AmplitudeEvidence ev;
      ev.amplitude = eps;
      ev.least_residual = std::numeric_limits<double>::infinity();
      Eigen::VectorXd best;
      for (std::size_t d = 0; d < drivers.size(); ++d) {
        const int e = drivers[d];
        const int k = sys.unknown_of_edge(e);
        report_progress(opt.progress, [&] {
          return "evidence search: sign-respecting least squares at fold amplitude " + progress_degrees(eps) +
                 " deg, start " + std::to_string(d + 1) + " of " + std::to_string(drivers.size());
        });
        Eigen::VectorXd x0 = unit_starts[d] * eps;
        x0[k] = (sign[e] != 0 ? sign[e] : 1) * eps;
        NewtonOptions nopt;
        nopt.tolerance = opt.tolerances.residual;
        nopt.held_unknowns = {k};
        nopt.max_iterations = opt.least_squares_iterations;
        nopt.stall_window = opt.least_squares_stall_window;
        nopt.sign_bounds = bounds;
        const NewtonResult nr = newton_project(sys, x0, nopt);
        ++out.starts_tried;
        const double res = inf_norm(sys.residual(nr.x));
        if (nr.converged &&
            first_crease_against_letter(sign, sys.edges_from_unknowns(nr.x), opt.tolerances.sign_threshold) < 0) {
          ++out.starts_converged;
          candidates.push_back({nr.x, e});
        }
        if (res < ev.least_residual) {
          ev.least_residual = res;
          ev.driving_edge = e;
          best = nr.x;
        }
      }
      // The norm search: no crease held, ||x||_2 = eps (a motion may leave every driving crease flat).
      for (int s = 0; s < opt.norm_search_starts && candidates.empty(); ++s) {
        report_progress(opt.progress, [&] {
          return "evidence search: norm-constrained least squares at fold amplitude " + progress_degrees(eps) +
                 " deg, start " + std::to_string(s + 1) + " of " + std::to_string(opt.norm_search_starts);
        });
        const AmplitudeSearchResult ar = norm_search_start(eps, opt.norm_search_iterations, false);
        if (ev.norm_search_residual < 0 || ar.closure_residual < ev.norm_search_residual)
          ev.norm_search_residual = ar.closure_residual;
        if (ar.closure_residual < ev.least_residual) {
          ev.least_residual = ar.closure_residual;
          ev.driving_edge = -1;
          best = ar.x;
        }
      }
      // Polish the best point when no bound holds it off the manifold (header, step 5).
      if (candidates.empty() && best.size() == n && ev.least_residual <= opt.polish_residual) {
        NewtonOptions popt;
        popt.tolerance = opt.tolerances.residual;
        popt.max_iterations = opt.polish_iterations;
        // Creases the search left on their bound (flat, against the side their letter
        // forbids) stay there: the polished point is then a weakly folded state.
        for (int i = 0; i < n; ++i)
          if (bounds[i] != 0 && best[i] == 0.0) popt.held_unknowns.push_back(i);
        const NewtonResult pr = newton_project(sys, best, popt);
        ++out.starts_tried;
        ev.polished = true;
        // A candidate only if it kept most of its size: Newton can slide a point of a rigid
        // pattern back to (next to) the flat state, which keeps every letter trivially.
        const bool kept_size = pr.x.norm() >= 0.5 * eps;
        const bool kept_letters =
            first_crease_against_letter(sign, sys.edges_from_unknowns(pr.x), opt.tolerances.sign_threshold) < 0;
        ev.polish_outcome = !pr.converged ? "did not close"
                            : !kept_size  ? "closed, but slid toward the flat state (size below half the amplitude)"
                            : !kept_letters ? "closed against a letter"
                                            : "closed with its letters kept: a candidate";
        if (pr.converged && kept_size && kept_letters) {
          ++out.starts_converged;
          ev.polish_converged = true;
          Eigen::Index k = 0;
          pr.x.cwiseAbs().maxCoeff(&k);
          candidates.push_back({pr.x, sys.edge_of_unknown(static_cast<int>(k))});
        }
      }
      if (out.evidence.empty()) evidence_x = best;  // the largest amplitude's: worst vertices
      out.evidence.push_back(ev);
      best_x.push_back(best);
      if (!candidates.empty()) break;
    }
    // The norm search once more at the pattern's own scale (header, step 5): a candidate if it
    // closes with its letters kept; never evidence.
    const double scaled = opt.scaled_norm_rms * std::sqrt(static_cast<double>(n));
    const double largest = opt.evidence_amplitudes.empty() ? 0.0 : opt.evidence_amplitudes.front();
    const bool run_scaled = scaled > largest && n <= opt.scaled_norm_max_unknowns;
    for (int s = 0; s < opt.scaled_norm_search_starts && candidates.empty() && run_scaled; ++s) {
      report_progress(opt.progress, [&] {
        return "norm-constrained least squares at the pattern's scale, ||rho||_2 = " + progress_degrees(scaled) +
               " deg, start " + std::to_string(s + 1) + " of " + std::to_string(opt.scaled_norm_search_starts);
      });
      const AmplitudeSearchResult ar = norm_search_start(scaled, opt.scaled_norm_search_iterations, true);
      ScaledNormSearch& sn = out.scaled_norm_search;
      ++sn.starts;
      sn.least_residual = sn.least_residual < 0 ? ar.closure_residual : std::min(sn.least_residual, ar.closure_residual);
      sn.amplitude = scaled;
    }
    // Does the rounding of the coordinates explain the least residual (header, step 5)?
    if (candidates.empty()) {
      for (std::size_t a = 0; a < out.evidence.size(); ++a) {
        if (best_x[a].size() != n) continue;
        const RoundingResidualCheck rc = rounding_explains_residual(pattern, topology, sys.edges_from_unknowns(best_x[a]),
                                                                   opt.coordinate_tolerance);
        out.evidence[a].explained_by_rounding = rc.explained;
        out.evidence[a].rounding_ratio = rc.worst_ratio;
      }
    }
  }

  if (candidates.empty()) {
    std::ostringstream why;
    why << "no folded point found near flat (" << out.starts_tried << " starts, " << drivers.size()
        << " driving creases held at " << opt.held_value << " rad, then sign-respecting least squares at";
    for (const AmplitudeEvidence& ev : out.evidence) why << " " << ev.amplitude;
    why << " rad, with the driving creases held and with the fold's norm fixed)";
    if (out.starts_wrong_sign > 0)
      why << "; " << out.starts_wrong_sign << " converged only against the assignment (e.g. crease "
          << out.wrong_sign_crease << ")";
    bool evidence = false;
    if (!out.evidence.empty() && std::isfinite(out.evidence[0].least_residual)) {
      out.least_residual = out.evidence[0].least_residual;
      const Eigen::VectorXd r = sys.residual(evidence_x);
      for (int b = 0; b < sys.num_vertices(); ++b)
        out.worst_vertices.emplace_back(sys.vertex_of_block(b), r.segment(3 * b, 3).norm());
      std::sort(out.worst_vertices.begin(), out.worst_vertices.end(),
                [](const auto& a, const auto& b) { return a.second > b.second; });
      if (out.worst_vertices.size() > 5) out.worst_vertices.resize(5);
      why << "; least residual";
      for (const AmplitudeEvidence& ev : out.evidence) why << " " << ev.least_residual << " at " << ev.amplitude;
      why << " rad";
      if (!out.worst_vertices.empty()) why << " (worst vertex " << out.worst_vertices[0].first << ")";
      const bool above_floor = out.least_residual >= opt.tolerances.evidence_floor;
      if (out.evidence.size() >= 2 && out.evidence[1].least_residual > 0) {
        out.growth_exponent = std::log(out.evidence[0].least_residual / out.evidence[1].least_residual) /
                              std::log(out.evidence[0].amplitude / out.evidence[1].amplitude);
        why << ", growing like amplitude^" << out.growth_exponent;
      }
      // The two largest amplitudes carry the evidence (a second-order obstruction, ~eps^2, falls
      // below the rounding's first-order gap, ~eps, at small enough eps).
      const auto judged_end = out.evidence.begin() + std::min<std::ptrdiff_t>(2, std::ssize(out.evidence));
      const auto found = std::find_if(out.evidence.begin(), judged_end,
                                      [](const AmplitudeEvidence& ev) { return ev.explained_by_rounding; });
      const auto explained = found == judged_end ? out.evidence.end() : found;
      evidence = above_floor && out.evidence.size() >= 2 && out.growth_exponent >= opt.min_growth_exponent &&
                 explained == out.evidence.end();
      if (explained != out.evidence.end())
        why << " - at " << explained->amplitude << " rad the rounding of the file's coordinates can explain it (every "
            << "vertex's gap within the one its sectors' rounding can cause there; the largest "
            << explained->rounding_ratio << " of it): no evidence either way";
      else if (!above_floor)
        why << " - below the evidence floor " << opt.tolerances.evidence_floor
            << ": the search stopped near its own threshold, which is no evidence either way";
      else if (!evidence)
        why << " - it does not grow with the fold as a geometric obstruction does: no evidence either way";
    }
    out.is_proof = false;
    if (evidence) {
      out.verdict = Verdict::kNotRigidlyFoldable;
      why << " - numerical evidence within the search, not a proof";
    } else {
      out.verdict = Verdict::kUndecided;
    }
    out.reason = why.str();
    return finish();
  }

  // 3. A candidate that leaves lettered creases flat is pushed off them first (header, step
  // 3): the strict point, when one is found, is traced before the weak one it came from.
  if (opt.use_assignment) {
    std::vector<Candidate> pushed;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (static_cast<int>(c) < opt.max_candidates_traced) {
        if (std::optional<Eigen::VectorXd> strict = push_off_flat_creases(sys, candidates[c].x, sign, opt.tolerances.residual,
                                                                                    StrictnessReport{}.flat_fraction))
          pushed.push_back({*strict, candidates[c].edge, candidates[c].far_from_flat});
      }
      pushed.push_back(candidates[c]);
    }
    candidates = std::move(pushed);
  }

  // 2-4. Trace candidates until one certifies.
  GeneralVerdict best;
  bool have_best = false;
  const int ntrace = std::min<int>(opt.max_candidates_traced, static_cast<int>(candidates.size()));
  auto certificate_progress = [&](int c, int count, int edge, const Eigen::VectorXd& x) {
    return "general model: tracing candidate " + std::to_string(c + 1) + " of " + std::to_string(count) + ", crease " +
           std::to_string(edge) + " at " + progress_degrees(x[sys.unknown_of_edge(edge)]) + " of " +
           progress_degrees(opt.tolerances.fold_limit()) + " deg";
  };
  for (int c = 0; c < ntrace; ++c) {
    const Candidate& cand = candidates[c];
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys.evaluate(cand.x, r, J);
    RankOptions ro;
    ro.relative_tolerance = opt.tolerances.rank_cut;
    const RankResult rk = jacobian_rank(J, ro);
    // DOF 1: the curve. DOF > 1: the fold's size first, then the older driving crease.
    // A candidate found at the pattern's scale, farther from flat: by the fold's size only
    // (the path must reach back toward flat).
    const std::vector<TraceMethod> methods =
        cand.far_from_flat ? std::vector<TraceMethod>{TraceMethod::kFoldSize}
        : rk.dof == 1      ? std::vector<TraceMethod>{TraceMethod::kOneDof}
                           : std::vector<TraceMethod>{TraceMethod::kFoldSize, TraceMethod::kDrivingCrease};
    for (TraceMethod method : methods) {
      GeneralVerdict trial = out;
      trial.trace.driving_edge = cand.edge;
      trial.trace.dof_at_departure = rk.dof;
      trial.trace.dof_method = rk.method;
      PathWatchOptions wo;
      wo.tolerances = opt.tolerances;
      trial.trace.valid_points = 0;  // points of the path with every letter respected
      Tracer tr{sys, opt, trial.trace, PathWatch(pattern, cand.edge, wo), trial.singular_points};
      auto accept = [&](const Eigen::VectorXd& x) {
        report_progress(opt.progress, [&] { return certificate_progress(c, ntrace, cand.edge, x); });
        return tr.accept(x);
      };
      double toward_flat = -1.0;  // kFoldSize: the size the path was continued back to
      if (method == TraceMethod::kOneDof) {
        if (n <= opt.singular_detection_limit) tr.start_bordered(cand.x, cand.x);
        const ContinuationResult cr = continue_one_dof(sys, cand.x, cand.x, accept, opt.continuation);
        trial.trace.linear_solver = cr.linear_solver;
        trial.trace.factorizations = cr.stats.factorizations;
        if (trial.trace.stopped_by == StopReason::kNone) {
          trial.trace.stopped_by = StopReason::kContinuationFailed;
          trial.trace.stop_message = cr.reason;
        }
      } else if (method == TraceMethod::kFoldSize) {
        toward_flat = trace_by_fold_size(sys, cand.x, sign, opt, tr, accept);
        trial.trace_method = "fold size (the 2-norm of the fold angles stepped, toward flat and out)";
        trial.traced_toward_flat_to = toward_flat;
      } else {
        trace_by_driving_crease(sys, cand.x, sys.unknown_of_edge(cand.edge), opt, tr, accept);
        trial.trace_method = "driving crease held, the rest projected";
      }
      if (trial.trace.valid_points > 0) {
        trial.certificate_angles = trial.trace.path[trial.trace.valid_points - 1];
        trial.certificate_mismatch =
            place_faces(pattern, topology, trial.certificate_angles, reference_fold_angles(pattern, topology),
                        /*with_vertices=*/false)
                .relative_mismatch();
      }
      if (!trial.trace.path.empty()) {
        trial.trace.driving_begin = trial.trace.path.front()[cand.edge];
        trial.trace.driving_end = trial.trace.path.back()[cand.edge];
      }
      // The fold-size path must also reach back toward flat to 1/100 of the candidate's size.
      const bool reached_flat_side =
          method != TraceMethod::kFoldSize || (toward_flat > 0 && toward_flat <= cand.x.norm() / 100 * (1 + 1e-6));
      const bool ok = reached_flat_side && trial.trace.max_fold >= opt.certificate_fold &&
                      trial.certificate_mismatch >= 0 && trial.certificate_mismatch <= opt.tolerances.placement_mismatch;
      if (ok) {
        trial.verdict = Verdict::kRigidlyFoldable;
        trial.strictness = strictness_at(pattern, trial.certificate_angles);
        trial.is_proof = true;  // the traced path is the certificate
        std::ostringstream why;
        why << "traced a folding path to max |rho| = " << trial.trace.max_fold << " rad (DOF "
            << trial.trace.dof_at_departure;
        if (method == TraceMethod::kFoldSize)
          why << ", stepping the fold's size ||rho||_2, from " << toward_flat << " rad near flat to "
              << trial.trace.path.back().norm();
        why << ", max residual " << trial.trace.max_residual << ", placement mismatch " << trial.certificate_mismatch
            << "); stopped by " << trial.trace.stop_text();
        trial.reason = why.str();
        out = std::move(trial);
        return finish();
      }
      if (!have_best || trial.trace.max_fold > best.trace.max_fold) {
        best = std::move(trial);
        have_best = true;
      }
    }
  }
  out = std::move(best);
  out.verdict = Verdict::kUndecided;
  std::ostringstream why;
  why << "folded points found near flat but no trace reached " << opt.certificate_fold
      << " rad (best " << out.trace.max_fold << ", stopped by " << out.trace.stop_text() << ")";
  out.reason = why.str();
  return finish();
}

}  // namespace rigidfold
