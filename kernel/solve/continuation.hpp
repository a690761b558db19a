#pragma once
// 1-DOF pseudo-arclength continuation along the constraint manifold r(x) = 0 of a
// ClosureSystem (docs/DESIGN.md, "Continuation").
//
// At a point x_k the tangent t_k is the unit null vector of J(x_k), oriented to continue the
// previous tangent (the first one along `direction`): from jacobian_rank (which also checks
// DOF = 1) for up to 2000 unknowns, above that by inverse iteration on the corrector's
// factorisation (the DOF is then not re-checked at every point). Predictor
// x_p = x_k + h t_k; corrector: Newton on the augmented system
// [r(x); t_k . (x - x_k) - h] = 0, each step the exact solution of the augmented linear
// system built from the minimum-norm step and the null vector of J (MinimumNormSolver:
// CHOLMOD on J^T J + lambda I, one symbolic analysis for the whole trace). The step h grows
// by 1.5 after a corrector that converges in <= 3 iterations (reuse: in <= 5 without a
// factorisation) and is halved after a failure
// (not converged, or the DOF at the new point is not 1, or the tangent turned by more than
// 0.5 rad). Opt-in for large systems: the Newton step by PCG with a stale factor instead
// (LinearSolver, ContinuationOptions::linear_solver).
//
// Factorisation reuse (ContinuationOptions::reuse): a chord (modified-Newton) corrector that
// keeps the last factorisation, its Jacobian J_fac and null vector w_fac across corrector
// iterations and continuation steps, and steps dx = J_fac^+ r + beta w_fac. Every step must
// contract the residual by `chord_contraction`. If a factor inherited from an earlier point
// fails that, the corrector restarts from the predictor with a fresh factor there (the stale
// steps leave soft-mode errors that spoil Newton from their iterates), and the next steps skip
// the stale attempt for 1, 2, 4, .. 16 steps; a factor made in this corrector that fails it is
// renewed at the current iterate. The tangent at a new point is the previous one (or w_fac)
// projected onto null(J(x)) with stale-factor solves, w <- w - J_fac^+ J w, until ||J w||_inf
// is at the round-off of the product (within 1000x of it if the projections stall; a fresh
// factorisation only if they stall above that).
// The tolerance is the same at every accepted point; only the work to reach it changes.
// Accuracy (why reuse is off by default): a residual at the tolerance can leave a point
// ~sigma_min^-1 * 1e-12 off the manifold along the soft (long-wavelength) modes of a large
// mesh. Newton's last, overshooting step ends near 1e-15 and removes that; the chord stops
// just under the tolerance, and extra chord steps do not help (a stale factor does not
// contract along the soft modes). Measured on the Miura against its closed form: Newton
// 3e-12 (160 x 160 cells) and 5.9e-12 (320); chord 1.4e-10 and 6.1e-10, for 1.6x less time.
//
// Units: x, h (arclength in unknown space) and residuals in radians.
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "kernel/closure/closure_system.hpp"

namespace rigidfold {

// kOff (default): Newton, a factorisation per iteration (quadratic convergence, the accuracy
// above). kOn: the chord corrector, faster on large meshes (Miura 320 x 320: 1.1 instead of
// 3.3 factorisations per step) at ~1e-10 rad of soft-mode error. kAuto: the chord above
// kRankRevealingLimit (2000) unknowns, Newton below.
enum class FactorizationReuse { kAuto, kOn, kOff };

// The linear solver of the Newton corrector (not of the chord corrector, which has its own
// stale-factor iteration). kDirect: a fresh CHOLMOD factorisation of J^T J + lambda I at every
// Newton iteration, the step and the tangent from it. kPcg: the same Newton step, by CGLS
// preconditioned with the factorisation in use even if it was made at an earlier iterate or
// point (stale_pcg.hpp), to a relative tolerance of ||r||_inf clamped to [1e-10, 1e-4]: the
// linear error is then O(||r||^2) and Newton stays quadratic, its last step ending far below
// the tolerance as the direct one does. A fresh factorisation at the current iterate (with
// the direct step) replaces the CG solve when CG does not converge in pcg_max_iterations or
// the rate of the last CG solve predicts it would not; it is the next preconditioner. The
// tangent at an accepted point: w = t - d with [J; t^T] d = [J t; 0] (J w = 0) by the same
// solve, to 1e-8 relative (it only feeds the predictor and the step's constraint row).
// kAuto: kDirect up to 2000 unknowns (kRankRevealingLimit); above, kPcg until more than a
// third of its first 6+ stale-factor solves end in a fresh factorisation anyway (large steps,
// e.g. the trace command's 0.2 rad), then kDirect for the rest of the trace
// (ContinuationResult::linear_solver says which; continuation.cpp has the figures).
enum class LinearSolver { kAuto, kDirect, kPcg };

struct ContinuationOptions {
  double initial_step = 0.05;   // h at the start (radians of arclength)
  double min_step = 1e-8;       // give up below this
  double max_step = 0.25;
  int max_points = 10000;
  double tolerance = 1e-12;     // corrector stop, ||r||_inf (radians)
  int max_corrector_iterations = 10;
  double lambda_relative = 1e-14;
  FactorizationReuse reuse = FactorizationReuse::kOff;
  double chord_contraction = 0.25;   // reuse: refactorise when ||r|| drops by less than this factor
  int max_chord_iterations = 20;     // reuse: corrector iterations cap (replaces max_corrector_iterations)
  // > 0: the step is measured by the largest change of any unknown instead (radians): h is
  // capped at max_angle_step / ||t||_inf (and starts at most there), so the number of points
  // does not grow with the number of unknowns (an arclength of 0.1 on a 100 x 100 Miura moves
  // each crease by ~1e-3 rad). When set, it replaces max_step.
  double max_angle_step = 0.0;
  // Landing: points placed exactly at given values of one unknown (e.g. a trace's output
  // steps), so that no separate projection is needed there. When the predictor would reach
  // the next value, the step is shortened to land on it and its corrector holds that unknown
  // at the value (a natural-parameter step; the same Newton step formula with e_k in place of
  // the tangent) - only where the unknown moves at >= 5% of the fastest one along t, else
  // the ordinary arclength step is taken and the value may be passed. Values must be
  // monotone; those behind the start are skipped. ContinuationPoint::landing says which.
  // Predictor: the tangent line plus the curvature of the parabola through the previous
  // point (about one Newton iteration less per point on a Miura trace). Off by default: it
  // changes where the points fall, and the branch explorer checks facet interference at its
  // points (the Type 1M onset moved from 23.45 to 22.49 deg with it); not with the chord
  // corrector (reuse), whose soft-mode error it pushed above 1e-10 on a 40 x 40 Miura.
  bool curved_predictor = false;
  int landing_unknown = -1;
  std::vector<double> landing_values;
  LinearSolver linear_solver = LinearSolver::kAuto;  // Newton corrector only (reuse off)
  int pcg_max_iterations = 8;                        // kPcg: CG iterations before a refactorisation
};

// Work done by one continue_one_dof call (all attempts, rejected steps and the start's
// projection included). Times are wall seconds.
struct ContinuationStats {
  int factorizations = 0;         // numeric factorisations of J^T J + lambda I (lambda retries count)
  int solves = 0;                 // minimum-norm solves (MinimumNormSolver::solve: 2 CHOLMOD solves each)
  int null_vectors = 0;           // inverse-iteration null vectors (MinimumNormSolver::null_vector: 4 CHOLMOD solves)
  int evaluations = 0;            // evaluations of r and J
  int rank_factorizations = 0;    // rank-revealing tangents (jacobian_rank), <= 2000 unknowns only
  int renewals = 0;               // reuse: factorisations forced by slow contraction, an uphill step,
                                  // a stale w_fac or a stalled tangent projection (all of these)
  int stale_restarts = 0;         // reuse: correctors restarted from xp because a stale factor failed
  int tangent_renewals = 0;       // reuse: tangent projections that stalled and refactorised
  int corrector_iterations = 0;
  int rejected_steps = 0;
  int pcg_solves = 0;             // kPcg: preconditioned CGLS solves (corrector steps and tangents)
  int pcg_iterations = 0;         // kPcg: their CG iterations (one pair of triangular solves each)
  int pcg_fallbacks = 0;          // kPcg: solves that did not converge in pcg_max_iterations (a
                                  // fresh factorisation followed)
  int pcg_predicted_renewals = 0; // kPcg: fresh factorisations instead of a PCG solve whose CG count,
                                  // predicted from the last solve's rate, would exceed the cap
  double seconds_pcg = 0.0;
  double seconds_factorize = 0.0, seconds_solve = 0.0, seconds_null_vector = 0.0, seconds_evaluate = 0.0,
         seconds_rank = 0.0, seconds_start = 0.0, seconds_total = 0.0;
};

struct ContinuationPoint {
  Eigen::VectorXd x;            // unknowns (radians), on the manifold
  double residual = 0.0;        // ||r(x)||_inf reached by the corrector
  double step = 0.0;            // arclength step that produced this point (0 for the start)
  int corrector_iterations = 0;
  int landing = -1;             // index into ContinuationOptions::landing_values if the point lies on it
};

struct ContinuationResult {
  std::vector<ContinuationPoint> points;  // the start (after projection) first
  bool stopped = false;                   // `stop` returned true at the last point
  std::string reason;                     // "stop", "max_points", "step too small", "start not on manifold", "not 1 DOF"
  bool reused_factorization = false;      // the chord corrector was used (options.reuse resolved)
  // The corrector's linear solver (options.reuse and linear_solver resolved): "direct
  // (CHOLMOD)", "PCG (stale CHOLMOD factor)", "chord (stale CHOLMOD factor)", or (kAuto)
  // "direct (CHOLMOD), after M of N stale-factor PCG solves ended in a fresh factorisation".
  std::string linear_solver;
  ContinuationStats stats;
};

// Traces from x0 (projected onto the manifold first) in the direction of `direction`
// (size num_unknowns(); only its sign against the tangent matters) until stop(x) is true
// at an accepted point. The system must have 1 DOF along the path.
ContinuationResult continue_one_dof(const ClosureSystem& system, const Eigen::VectorXd& x0,
                                    const Eigen::VectorXd& direction,
                                    const std::function<bool(const Eigen::VectorXd&)>& stop,
                                    const ContinuationOptions& options = {});

}  // namespace rigidfold
