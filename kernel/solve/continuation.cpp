#include "kernel/solve/continuation.hpp"

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/solve/stale_pcg.hpp"

namespace rigidfold {

namespace {

// Above this many unknowns the tangent comes from the corrector's own factorisation
// (inverse iteration) instead of a rank-revealing factorisation of J at every point: SPQR
// on a 10^5-10^6-crease Jacobian costs far more than the whole corrector.
constexpr int kRankRevealingLimit = 2000;

// LinearSolver::kAuto: the PCG corrector above kRankRevealingLimit unknowns (where the tangent
// no longer comes from a rank-revealing factorisation), the direct one below; and back to the
// direct one for the rest of the trace once the stale factors stop paying: after
// kAutoPcgWindow attempts (solves tried plus solves skipped because the last CG rate predicted
// a miss), when more than a third of them ended in a fresh factorisation anyway.
// Measured (Miura, one run each, 2-core machine, nothing else running; BM_Trace: 104 points of
// equal arclength from 5 to 170 deg; BM_PeerTrace: trace_motion's settings, steps of up to
// 0.2 rad in any crease, landing, curved predictor):
//   BM_Trace 100 x 100: direct 3.37 s (250 factorisations), PCG 2.42 s (104), errors against
//   the closed form 1.7e-12 / 5.4e-12; BM_PeerTrace 100 x 100: direct 1.68 s (87 factorisations),
//   PCG 1.34 s (45), error 2.1e-11 both; 50 x 50 PCG 0.24 s.
// (PCG looked 3.4x slower on BM_PeerTrace before: a landing step 1.5e-13 long broke the curved
// predictor, which then failed 21 steps; PCG's different points had only met it.)
constexpr int kPcgUnknowns = kRankRevealingLimit + 1;
constexpr int kAutoPcgWindow = 6;

// CHOLMOD's supernodal switch for the trace's factor (MinimumNormSolver's argument): a trace
// solves with each factor 15-20 times (PCG iterations, null vectors, tangents), against a few
// times in one corrector, so the supernodal factor's slower triangular solves weigh more here
// than in kSupernodalFlopsPerEntry's measurements. Measured on BM_Trace/n/3 (104 points, the
// default linear solver; one run each, 2-core machine, nothing else running), seconds in total
// (factorise / PCG):
//   cells   flops/nnz(L)   simplicial            supernodal
//   320         128         88.6 (31.8 / 37.2)    96.9 (20.1 / 51.8)
//   500         187        305   (123 / 127)     268   (51.2 / 152)
// The crossover, interpolated between the two: ~150. Below 120 both switches pick simplicial.
constexpr double kTraceSupernodalFlopsPerEntry = 150.0;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// A fixed, generic start vector for inverse iteration (no special direction of the mesh).
Eigen::VectorXd generic_vector(int n) {
  Eigen::VectorXd g(n);
  for (int k = 0; k < n; ++k) g[k] = 1.0 + 0.5 * std::sin(1.7 * k + 0.3);
  return g;
}

// The linear algebra of one trace with its counters: the factorisation in use (of J_fac,
// with w_fac its unit null vector), kept until refactor() replaces it.
class Linear {
 public:
  Linear(const ClosureSystem& system, const Eigen::SparseMatrix<double>& pattern, double lambda_relative,
         ContinuationStats& stats)
      : system_(system),
        solver_(pattern, {}, FactorOrdering::kDefault, kTraceSupernodalFlopsPerEntry),
        lambda_relative_(lambda_relative),
        stats_(stats) {}

  void evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::SparseMatrix<double>& J) {
    const auto t0 = Clock::now();
    system_.evaluate(x, r, J);
    ++stats_.evaluations;
    stats_.seconds_evaluate += seconds_since(t0);
  }
  // Factorises at J and computes w_fac (sign of `guess`). False (and no factor) on failure.
  bool refactor(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& guess) {
    auto t0 = Clock::now();
    const int before = solver_.factorizations();
    valid_ = solver_.factorize(J, lambda_relative_);
    pcg_rate_ = 0.0;
    stats_.factorizations += solver_.factorizations() - before;
    stats_.seconds_factorize += seconds_since(t0);
    if (!valid_) return false;
    J_fac_ = J;
    t0 = Clock::now();
    w_fac_ = solver_.null_vector(J_fac_, guess);
    ++stats_.null_vectors;
    stats_.seconds_null_vector += seconds_since(t0);
    return true;
  }
  // J_fac^+ y (minimum norm, orthogonal to w_fac up to the refinement's accuracy).
  Eigen::VectorXd solve(const Eigen::VectorXd& y) {
    const auto t0 = Clock::now();
    Eigen::VectorXd d = solver_.solve(J_fac_, y);
    ++stats_.solves;
    stats_.seconds_solve += seconds_since(t0);
    return d;
  }
  // The least-squares solution of [J; a^T] dx = [y; c] by CGLS preconditioned with the factor
  // in use (stale_pcg.hpp). Needs valid().
  StalePcgResult pcg(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& y, const Eigen::VectorXd& a, double c,
                     double relative_tolerance, int max_iterations) {
    const auto t0 = Clock::now();
    StalePcgOptions o;
    o.relative_tolerance = relative_tolerance;
    o.max_iterations = max_iterations;
    StalePcgResult res = stale_pcg_step(solver_, w_fac_, J, y, a, c, o);
    ++stats_.pcg_solves;
    stats_.pcg_iterations += res.iterations;
    if (!res.converged) ++stats_.pcg_fallbacks;
    if (res.iterations > 0)
      pcg_rate_ = res.converged ? std::pow(std::max(res.relative_residual, 1e-300), 1.0 / res.iterations) : 1.0;
    stats_.seconds_pcg += seconds_since(t0);
    return res;
  }
  // Whether a PCG solve to `relative_tolerance` is expected to converge within max_iterations
  // with the factor in use: CG's contraction per iteration in the last solve with it predicts
  // the count (untried since the factorisation: yes). A no counts a predicted renewal.
  bool pcg_expected(double relative_tolerance, int max_iterations) {
    if (!valid_) return false;
    if (pcg_rate_ <= 0.0) return true;
    const bool ok = pcg_rate_ < 1.0 && std::log(relative_tolerance) / std::log(pcg_rate_) <= max_iterations;
    if (!ok) ++stats_.pcg_predicted_renewals;
    return ok;
  }
  void count_renewal() { ++stats_.renewals; }
  ContinuationStats& stats() { return stats_; }
  bool valid() const { return valid_; }
  const Eigen::VectorXd& w() const { return w_fac_; }

 private:
  const ClosureSystem& system_;
  MinimumNormSolver solver_;
  double lambda_relative_;
  ContinuationStats& stats_;
  bool valid_ = false;
  double pcg_rate_ = 0.0;  // CG contraction per iteration in the last PCG solve with this factor (0: none yet)
  Eigen::SparseMatrix<double> J_fac_;
  Eigen::VectorXd w_fac_;
};

struct Corrected {
  Eigen::VectorXd x;
  Eigen::SparseMatrix<double> J;  // J(x), from the last evaluation
  double residual = 0.0;
  int iterations = 0;
  int factorizations = 0;         // refactor() calls in this corrector
  bool converged = false;
  bool stale_tried = false;       // reuse, PCG: stepped with a factorisation from an earlier point
  bool stale_failed = false;      // ... and it contracted too slowly (reuse: restarted from xp, fresh;
                                  // PCG: CG did not converge, refactorised)
};

// Newton on [r(x); t.(x - xk) - h] = 0 from xp. With w the unit null vector of J(x), the
// exact step of the augmented linear system [J; t^T] dx = [r; c] is
//     dx = J^+ r + beta w,   beta = (c - t.J^+ r) / (t.w)
// (J^+ r is the minimum-norm solution, orthogonal to w; the augmented matrix has full
// column rank at a regular 1-DOF point), so the corrector keeps Newton's quadratic
// convergence while factorising only J^T J + lambda I, whose pattern (and symbolic
// analysis, in `solver`) is shared by every step of the trace.
// Without reuse every iteration refactorises (Newton). With reuse the same step is taken
// with [J_fac; t^T] (chord method). Its rate is not only ~ |x - x_fac| * curvature: the soft
// (long-wavelength) modes of a large tessellation amplify the stale part of J_fac by
// 1/sigma_min, so a factor from the previous point can leave errors along them that the
// residual hardly shows and that spoil the next Newton step. Hence:
//   - a factor inherited from an earlier point (stale, tried only if try_stale) must
//     contract ||r|| by chord_contraction at every step, else the corrector restarts from xp
//     with a fresh factor there (a Newton step from the predictor converges fast);
//   - a factor made in this corrector is kept while it contracts by chord_contraction,
//     else refactorised at the current iterate (Newton again).
// The constraint row: a.(x - origin) = offset (arclength: a = t, origin = xk, offset = h;
// landing: a = e_k, origin = xk, offset = value - xk[k]). Measured from xk, not as a.x =
// target: a.x is of the size of x (hundreds of radians on a large mesh), and its rounding
// would sit near the corrector's 1e-12 tolerance.
struct Constraint {
  const Eigen::VectorXd& a;
  const Eigen::VectorXd& origin;
  double offset;
};

// With pcg (Newton only, not with reuse) each iteration first tries the augmented step by
// CGLS preconditioned with the factor in use, to a relative tolerance of ||r||_inf clamped to
// [1e-10, 1e-4] (quadratic convergence kept: the linear error is O(||r||^2)); if it fails to
// converge within pcg_max_iterations, or the last CG rate predicts that, J is refactorised
// and the direct step taken. A factor from an earlier point that failed so sets
// stale_failed (the caller then skips such attempts for a while, as with reuse).
Corrected correct(Linear& lin, const Constraint& con, const Eigen::VectorXd& t, const Eigen::VectorXd& xp,
                  const ContinuationOptions& options, bool reuse, bool try_stale, bool pcg) {
  Corrected c;
  c.x = xp;
  Eigen::VectorXd r;
  double prev = std::numeric_limits<double>::infinity();
  bool own = false;    // the factor in use was made in this corrector
  bool force = reuse && !try_stale;
  const int cap = reuse ? options.max_chord_iterations : options.max_corrector_iterations;
  for (;;) {
    lin.evaluate(c.x, r, c.J);
    const double arc = con.a.dot(c.x - con.origin) - con.offset;
    c.residual = std::max(r.size() > 0 ? r.lpNorm<Eigen::Infinity>() : 0.0, std::abs(arc));
    if (c.residual <= options.tolerance) {
      c.converged = true;
      return c;
    }
    if (c.iterations >= cap) return c;
    const bool slow = !(c.residual <= options.chord_contraction * prev);  // NaN counts as slow
    if (reuse && c.iterations > 0 && !own && slow) {
      c.stale_failed = true;  // restart from the predictor with a fresh factor there
      ++lin.stats().stale_restarts;
      c.x = xp;
      prev = std::numeric_limits<double>::infinity();
      force = true;
      continue;
    }
    if (!std::isfinite(c.residual)) return c;
    const double rel = std::clamp(c.residual, 1e-10, 1e-4);
    // A factor from an earlier point is tried unless one failed lately (try_stale: the same
    // back-off as the chord's).
    if (pcg && (own || try_stale) && lin.pcg_expected(rel, options.pcg_max_iterations)) {
      const StalePcgResult step = lin.pcg(c.J, r, con.a, arc, rel, options.pcg_max_iterations);
      if (!own) c.stale_tried = true;
      if (step.converged) {
        c.x -= step.dx;
        ++c.iterations;
        continue;
      }
      if (!own) c.stale_failed = true;
    }
    const bool refactor = !reuse || !lin.valid() || force || (c.iterations > 0 && slow);
    force = false;
    if (refactor) {
      if (reuse && lin.valid()) lin.count_renewal();
      ++c.factorizations;
      own = true;
      if (!lin.refactor(c.J, t)) return c;
    } else if (!own) {
      c.stale_tried = true;
    }
    const Eigen::VectorXd d = lin.solve(r);
    const double tw = con.a.dot(lin.w());
    if (std::abs(tw) < 1e-8 * con.a.lpNorm<Eigen::Infinity>()) {
      if (refactor) return c;  // the tangent plane turned away: not a regular 1-DOF point
      force = true;            // perhaps only the stale w_fac did
      continue;
    }
    prev = c.residual;
    c.x -= d + ((arc - con.a.dot(d)) / tw) * lin.w();
    ++c.iterations;
  }
}

// Tangent at a corrected point x (J = J(x)) from the previous tangent t (or w_fac) with
// stale-factor solves: w <- w - J_fac^+ J w contracts the component off null(J) at the chord rate.
// Stops when ||J w||_inf is within 64 eps of the round-off bound max_i (|J| |w|)_i of the
// product itself (1000x that if the projections stall); refactorises at x otherwise.
Eigen::VectorXd project_tangent(Linear& lin, const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& t) {
  // A renewal costs a factorisation and a null vector, 8-25 solves on large meshes: keep
  // projecting while it still contracts.
  constexpr int kMaxProjections = 12;
  const Eigen::SparseMatrix<double> absJ = J.cwiseAbs();
  // Start from t or from w_fac, whichever J annihilates better: w_fac wins when the factor
  // was made during this step's corrector, near x.
  Eigen::VectorXd w = t;
  if (lin.valid()) {
    const Eigen::VectorXd wf = lin.w().dot(t) < 0 ? Eigen::VectorXd(-lin.w()) : lin.w();
    if ((J * wf).lpNorm<Eigen::Infinity>() < (J * t).lpNorm<Eigen::Infinity>()) w = wf;
  }
  double last = std::numeric_limits<double>::infinity();
  for (int k = 0;; ++k) {
    const Eigen::VectorXd y = J * w;
    const double err = y.lpNorm<Eigen::Infinity>();
    const double bound = 64 * std::numeric_limits<double>::epsilon() * (absJ * w.cwiseAbs()).maxCoeff();
    if (err <= bound) return w;
    if (k >= kMaxProjections || !(err < 0.7 * last)) {
      // Stalled. Within 1000x the bound (~1e-11 relative) it is the floor of the stale
      // solves, and a fresh null vector would be no more exact: keep w. Else the factor is
      // too stale.
      if (err <= 1e3 * bound) return w;
      break;
    }
    last = err;
    w -= lin.solve(y);
    w /= w.norm();
  }
  lin.count_renewal();
  ++lin.stats().tangent_renewals;
  if (!lin.refactor(J, t)) return {};
  return lin.w();
}

}  // namespace

ContinuationResult continue_one_dof(const ClosureSystem& system, const Eigen::VectorXd& x0,
                                    const Eigen::VectorXd& direction,
                                    const std::function<bool(const Eigen::VectorXd&)>& stop,
                                    const ContinuationOptions& options) {
  if (x0.size() != system.num_unknowns() || direction.size() != system.num_unknowns())
    throw std::invalid_argument("continue_one_dof: x0 and direction need num_unknowns() entries");
  const auto t_begin = Clock::now();
  ContinuationResult out;
  ContinuationStats& st = out.stats;
  struct Finish {  // total time on every return path (every one returns `out` itself)
    ContinuationStats& st;
    Clock::time_point t0;
    ~Finish() { st.seconds_total = seconds_since(t0); }
  } finish{st, t_begin};
  NewtonOptions nopt;
  nopt.tolerance = options.tolerance;
  const NewtonResult start = newton_project(system, x0, nopt);
  st.factorizations += start.factorizations;
  st.seconds_start = seconds_since(t_begin);
  if (!start.converged) {
    out.reason = "start not on manifold";
    return out;
  }
  out.points.push_back({start.x, start.residual_history.back(), 0.0, start.iterations});
  Eigen::VectorXd r0;
  Eigen::SparseMatrix<double> J0;
  system.evaluate(start.x, r0, J0);
  Linear lin(system, J0, options.lambda_relative, st);
  const bool rank_revealing = system.num_unknowns() <= kRankRevealingLimit;
  const bool reuse = options.reuse == FactorizationReuse::kOn ||
                     (options.reuse == FactorizationReuse::kAuto && !rank_revealing);
  out.reused_factorization = reuse;
  bool pcg = !reuse && (options.linear_solver == LinearSolver::kPcg ||
                        (options.linear_solver == LinearSolver::kAuto && system.num_unknowns() >= kPcgUnknowns));
  const bool pcg_may_drop = pcg && options.linear_solver == LinearSolver::kAuto;
  out.linear_solver = reuse ? "chord (stale CHOLMOD factor)" : pcg ? "PCG (stale CHOLMOD factor)" : "direct (CHOLMOD)";
  // kAuto: PCG until the stale factors stop paying (kAutoPcgWindow above), then direct.
  auto maybe_drop_pcg = [&] {
    if (!pcg_may_drop || !pcg) return;
    const int attempts = st.pcg_solves + st.pcg_predicted_renewals;
    const int missed = st.pcg_fallbacks + st.pcg_predicted_renewals;
    if (attempts < kAutoPcgWindow || 3 * missed <= attempts) return;
    pcg = false;
    out.linear_solver = "direct (CHOLMOD), after " + std::to_string(missed) + " of " + std::to_string(attempts) +
                        " stale-factor PCG solves ended in a fresh factorisation";
  };
  // Small systems: unit null vector from a rank-revealing factorisation, which also checks
  // DOF = 1 (empty if not).
  auto rank_tangent = [&](const Eigen::VectorXd& x) -> Eigen::VectorXd {
    const auto t0 = Clock::now();
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    system.evaluate(x, r, J);
    const RankResult rk = jacobian_rank(J);
    ++st.rank_factorizations;
    st.seconds_rank += seconds_since(t0);
    if (rk.dof != 1 || rk.null_space.cols() != 1) return {};
    return rk.null_space.col(0);
  };
  // Large systems: the null vector of a fresh factorisation at x (inverse iteration); the DOF
  // is not re-checked there.
  auto fresh_tangent = [&](const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& guess) -> Eigen::VectorXd {
    if (!lin.refactor(J, guess)) return {};
    return lin.w();
  };
  // PCG: the null vector of J at a corrected point from the previous tangent t, w = t - d with
  // [J; t^T] d = [J t; 0] (so J w = 0, t . w = 1), solved with the factor in use; a fresh
  // factorisation if that fails.
  auto pcg_tangent = [&](const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& prev) -> Eigen::VectorXd {
    constexpr double kTangentTolerance = 1e-8;
    if (!lin.pcg_expected(kTangentTolerance, options.pcg_max_iterations)) return fresh_tangent(J, prev);
    const Eigen::VectorXd Jt = J * prev;
    const StalePcgResult d = lin.pcg(J, Jt, prev, 0.0, kTangentTolerance, options.pcg_max_iterations);
    if (!d.converged) return fresh_tangent(J, prev);
    Eigen::VectorXd w = prev - d.dx;
    const double norm = w.norm();
    if (!(norm > 0) || !std::isfinite(norm)) return fresh_tangent(J, prev);
    // CG's own stopping test is on its normal equations, so J w itself is checked as well: a
    // wrong tangent would fail every later step.
    const double miss = (J * w).lpNorm<Eigen::Infinity>();
    const double scale = (J.cwiseAbs() * w.cwiseAbs()).maxCoeff();
    if (!(miss <= kTangentTolerance * scale)) return fresh_tangent(J, prev);
    return w / norm;
  };
  Eigen::VectorXd t = rank_revealing ? rank_tangent(start.x) : fresh_tangent(J0, generic_vector(system.num_unknowns()));
  if (t.size() == 0) {
    out.reason = "not 1 DOF";
    return out;
  }
  if (t.dot(direction) < 0) t = -t;
  // Step cap: in arclength, or by the largest change of an unknown (max_angle_step).
  auto step_cap = [&](const Eigen::VectorXd& tangent) {
    if (options.max_angle_step <= 0) return options.max_step;
    return options.max_angle_step / std::max(tangent.lpNorm<Eigen::Infinity>(), 1e-300);
  };
  double h = std::min(options.initial_step, step_cap(t));
  // Landing values ahead of the start, in order; `sense` is the way the landing unknown's
  // values run.
  const int land_k = options.landing_unknown;
  const std::vector<double>& land = options.landing_values;
  if (land_k >= system.num_unknowns()) throw std::invalid_argument("continue_one_dof: landing_unknown out of range");
  std::size_t next_land = 0;
  double sense = 0.0;
  Eigen::VectorXd e_land;
  if (land_k >= 0 && !land.empty()) {
    sense = land.size() > 1 ? (land.back() > land.front() ? 1.0 : -1.0) : (land[0] >= start.x[land_k] ? 1.0 : -1.0);
    e_land = Eigen::VectorXd::Zero(system.num_unknowns());
    e_land[land_k] = 1.0;
  }
  auto skip_passed_landings = [&](const Eigen::VectorXd& x) {
    while (next_land < land.size() && sense * (land[next_land] - x[land_k]) <= 0) ++next_land;
  };
  if (sense != 0) skip_passed_landings(start.x);
  // Reuse: after a stale factor failed, skip the stale attempt for 1, 2, 4, .. 16 steps
  // (each failed attempt costs solves and an evaluation); a success resets.
  int stale_skip = 0, stale_wait = 0;
  while (static_cast<int>(out.points.size()) < options.max_points) {
    if (stop(out.points.back().x)) {
      out.stopped = true;
      out.reason = "stop";
      return out;
    }
    maybe_drop_pcg();
    const Eigen::VectorXd& xk = out.points.back().x;
    // Land on the next value if this step reaches it and the unknown is a usable parameter.
    int landing = -1;
    double hs = h;
    if (sense != 0 && next_land < land.size()) {
      const double tk = t[land_k];
      const double gap = land[next_land] - xk[land_k];
      if (sense * tk >= 0.05 * t.lpNorm<Eigen::Infinity>() && std::fabs(h * tk) >= std::fabs(gap)) {
        hs = gap / tk;
        landing = static_cast<int>(next_land);
      }
    }
    // Predictor: the tangent line, plus the curvature term of the parabola through the
    // previous point (x(s) = xk + s t + s^2 c, c from x(-h_prev) = x_prev): its error is
    // O(h^3) instead of O(h^2), which saves about one Newton iteration per point.
    Eigen::VectorXd xp = xk + hs * t;
    if (out.points.size() >= 2 && options.curved_predictor && !reuse) {
      const ContinuationPoint& last = out.points.back();
      const double hp = last.step;
      // Not when the step is over 100x the last: the term divides by hp^2, so it scales the
      // rounding of the points' difference by (hs / hp)^2 (1e4 x 1e-16 |x| at 100x). A landing
      // step can be ~1e-13 long (a landing value a rounding error ahead of the last point);
      // after one, the term threw the predictor 1e13 away (21 rejected steps in a row on the
      // trace command's 100 x 100 Miura).
      if (hp > 0 && hs <= 100 * hp) xp += (hs * hs / (hp * hp)) * (out.points[out.points.size() - 2].x - xk + hp * t);
    }
    const Corrected c = landing >= 0
                            ? correct(lin, Constraint{e_land, xk, land[next_land] - xk[land_k]}, t, xp, options, reuse,
                                      stale_wait == 0, pcg)
                            : correct(lin, Constraint{t, xk, h}, t, xp, options, reuse, stale_wait == 0, pcg);
    st.corrector_iterations += c.iterations;
    if (c.stale_failed) {
      stale_skip = std::min(std::max(1, 2 * stale_skip), 16);
      stale_wait = stale_skip;
    } else if (c.stale_tried) {
      stale_skip = 0;
    } else if (stale_wait > 0) {
      --stale_wait;
    }
    Eigen::VectorXd t_new;
    if (c.converged) {
      if (rank_revealing)
        t_new = rank_tangent(c.x);
      else if (reuse)
        t_new = project_tangent(lin, c.J, t);
      else if (pcg)
        t_new = pcg_tangent(c.J, t);
      else  // Newton: the null vector of the last corrector step (at an iterate within about
            // the previous residual of c.x), accurate enough for a predictor and the turn test
        t_new = c.factorizations > 0 ? lin.w() : fresh_tangent(c.J, t);
      if (t_new.size() != 0 && t_new.dot(t) < 0) t_new = -t_new;
    }
    if (!c.converged || t_new.size() == 0 || std::acos(std::clamp(t_new.dot(t), -1.0, 1.0)) > 0.5) {
      ++st.rejected_steps;
      h = 0.5 * hs;
      if (h < options.min_step) {
        out.reason = "step too small";
        return out;
      }
      continue;
    }
    out.points.push_back({c.x, c.residual, hs, c.iterations, landing});
    if (sense != 0) skip_passed_landings(c.x);
    t = t_new;
    // Growth: Newton after a quick corrector; chord only while the factor needed no renewal
    // (a larger step would make the stale factor contract worse). A landing step keeps h
    // (its own length was set by the landing value).
    const bool easy = reuse ? c.factorizations == 0 && c.iterations <= 5 : c.iterations <= 3;
    if (easy && landing < 0) h = std::min(h * 1.5, step_cap(t));
    h = std::min(h, step_cap(t));
  }
  out.reason = "max_points";
  return out;
}

}  // namespace rigidfold
