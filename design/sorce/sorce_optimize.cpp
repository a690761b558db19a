#include "design/sorce/sorce_optimize.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <nlopt.hpp>

#include "design/nlopt/nlopt_result_name.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kHalfPi = 1.5707963267948966;

// The search minimises log FOM. Where the design is concave somewhere (or epsilon = 0 and a
// convexity is 0) eq 38's denominator is floored at kFloorRatio times the largest convexity:
// the linear models COBYLA builds need finite values on the infeasible side too. A design
// whose largest convexity is not finite and positive (a pivot or cusp diverging upwards, a
// builder that throws InputError) gets kObjectiveCap, above every floored value
// (log(1e6) = 13.8).
constexpr double kFloorRatio = 1e-6;
constexpr double kObjectiveCap = 30.0;

void check_input(const OffsetDesignProblem& p, const std::vector<double>& b, const std::string& b_place) {
  if (!p.motions) throw InputError("motions", "no motion builder");
  if (p.lower.empty() || p.lower.size() != p.upper.size())
    throw InputError("bounds", "lower and upper need the same, non-zero length (" + std::to_string(p.lower.size()) +
                                   ", " + std::to_string(p.upper.size()) + ")");
  for (std::size_t k = 0; k < p.lower.size(); ++k)
    if (!std::isfinite(p.lower[k]) || !std::isfinite(p.upper[k]) || !(p.lower[k] < p.upper[k]))
      throw InputError("bounds", "need finite lower < upper at coefficient " + std::to_string(k));
  if (b.size() != p.lower.size())
    throw InputError(b_place,
                     "has " + std::to_string(b.size()) + " coefficients, the bounds " + std::to_string(p.lower.size()));
  for (std::size_t k = 0; k < b.size(); ++k)
    if (!(b[k] >= p.lower[k] && b[k] <= p.upper[k]))
      throw InputError(b_place, "coefficient " + std::to_string(k) + " outside the bounds");
  if (!(p.epsilon >= 0.0) || !std::isfinite(p.epsilon)) throw InputError("epsilon", "must be finite and >= 0");
  if (p.max_protrusion && !(*p.max_protrusion >= 0.0)) throw InputError("max_protrusion", "must be >= 0");
  if (p.max_abs_s0 && !(*p.max_abs_s0 >= 0.0)) throw InputError("max_abs_s0", "must be >= 0");
  if (p.report.samples < 3) throw InputError("samples", "need at least 3");
}

bool near(double value, double bound, double tolerance, double scale) {
  return std::abs(value - bound) <= tolerance * scale;
}

// One evaluation: reports, summary, exact feasibility and binding constraints. `built` is false
// when the builder or fold_report threw InputError or gave no folds (then the design is
// infeasible with FOM +infinity).
struct Evaluation {
  OffsetDesign design;
  bool built = false;
};

Evaluation measure(const OffsetDesignProblem& p, const std::vector<double>& b, double tolerance) {
  Evaluation e;
  OffsetDesign& d = e.design;
  d.b = b;
  d.min_convexity = kInf;
  d.max_convexity = -kInf;
  try {
    const std::vector<FoldMotion> motions = p.motions(b);
    for (const FoldMotion& m : motions) d.folds.push_back(fold_report(m, p.report));
    e.built = !d.folds.empty();
  } catch (const InputError&) {
    d.folds.clear();
  }
  d.evaluations = 1;
  if (!e.built) {
    d.fom = kInf;
    return e;
  }
  for (const FoldReport& f : d.folds) {
    d.min_convexity = std::min({d.min_convexity, f.min_convexity_left, f.min_convexity_right});
    d.max_convexity = std::max({d.max_convexity, f.max_convexity_left, f.max_convexity_right});
    d.max_protrusion = std::max({d.max_protrusion, f.protrusion_left, f.protrusion_right});
    d.max_abs_s0 = std::max(d.max_abs_s0, std::abs(f.s0));
    d.cusps += f.cusps.size();
    d.ill_behaved += f.ill_behaved.size() + f.stationary.size();
  }
  d.fom = figure_of_merit(d.folds, p.epsilon);
  bool in_box = true;
  for (std::size_t k = 0; k < b.size(); ++k) in_box = in_box && b[k] >= p.lower[k] && b[k] <= p.upper[k];
  d.feasible = in_box && std::isfinite(d.max_convexity) && d.min_convexity >= p.epsilon && d.min_convexity > 0.0 &&
               d.cusps == 0 && d.ill_behaved == 0 && (!p.max_protrusion || d.max_protrusion <= *p.max_protrusion) &&
               (!p.max_abs_s0 || d.max_abs_s0 <= *p.max_abs_s0) && std::isfinite(d.fom);

  const double eps_scale = p.epsilon > 0.0 ? p.epsilon : 1e-12;
  for (std::size_t j = 0; j < d.folds.size(); ++j) {
    const FoldReport& f = d.folds[j];
    const int i = static_cast<int>(j);
    if (near(f.min_convexity_left, p.epsilon, tolerance, eps_scale))
      d.binding.push_back({"convexity_left", i, f.min_convexity_left, p.epsilon});
    if (near(f.min_convexity_right, p.epsilon, tolerance, eps_scale))
      d.binding.push_back({"convexity_right", i, f.min_convexity_right, p.epsilon});
    if (p.max_protrusion) {
      const double bound = *p.max_protrusion, scale = bound > 0.0 ? bound : 1e-12;
      if (near(f.protrusion_left, bound, tolerance, scale))
        d.binding.push_back({"protrusion_left", i, f.protrusion_left, bound});
      if (near(f.protrusion_right, bound, tolerance, scale))
        d.binding.push_back({"protrusion_right", i, f.protrusion_right, bound});
    }
    if (p.max_abs_s0) {
      const double bound = *p.max_abs_s0, scale = bound > 0.0 ? bound : 1e-12;
      if (near(std::abs(f.s0), bound, tolerance, scale)) d.binding.push_back({"s0", i, std::abs(f.s0), bound});
    }
  }
  for (std::size_t k = 0; k < b.size(); ++k) {
    const double width = p.upper[k] - p.lower[k];
    const int i = static_cast<int>(k);
    if (near(b[k], p.lower[k], tolerance, width)) d.binding.push_back({"lower", i, b[k], p.lower[k]});
    if (near(b[k], p.upper[k], tolerance, width)) d.binding.push_back({"upper", i, b[k], p.upper[k]});
  }
  return e;
}

// The search's view of an evaluation: objective and inequality constraints g <= 0, all finite.
//   convexity of fold j: atan((epsilon - lo_j) / hi), lo_j the fold's smallest convexity, hi
//     the largest over all folds: scale free (hi sets the design's own curvature unit), equal
//     to (epsilon - lo_j) / hi near the bound, and saturating at pi/2 where lo_j -> -infinity
//     (a pivot's or cusp's diverging curvature). A fold with a cusp, an ill-behaved t or an
//     infinite convexity gets pi/2: it violates "finite convexities, no cusps".
//   protrusion, |s0| of fold j: (value - bound) / L, L the largest slab thickness of the
//     motions (1 if every thickness is 0): lengths in the design's own unit.
// Exact feasibility (the result's `feasible`) is judged by measure(), not by these values.
struct SearchValues {
  double objective = kObjectiveCap;
  std::vector<double> g;
  double violation = kInf;  // sum of positive g (for the fallback when nothing is feasible)
};

SearchValues search_values(const OffsetDesignProblem& p, const Evaluation& e, std::size_t folds, double length) {
  SearchValues v;
  const std::size_t per_fold = 1 + (p.max_protrusion ? 1 : 0) + (p.max_abs_s0 ? 1 : 0);
  v.g.assign(folds * per_fold, kHalfPi);
  const OffsetDesign& d = e.design;
  if (!e.built || d.folds.size() != folds) return v;
  const double hi = d.max_convexity;
  const bool defined = std::isfinite(hi) && hi > 0.0;
  if (defined) {
    const double lo = std::max({d.min_convexity, p.epsilon, kFloorRatio * hi});
    v.objective = std::log(hi / lo);
  }
  for (std::size_t j = 0; j < folds; ++j) {
    const FoldReport& f = d.folds[j];
    std::size_t k = j * per_fold;
    const double lo = std::min(f.min_convexity_left, f.min_convexity_right);
    const double fold_hi = std::max(f.max_convexity_left, f.max_convexity_right);
    const bool fold_ok =
        defined && std::isfinite(fold_hi) && f.cusps.empty() && f.ill_behaved.empty() && f.stationary.empty();
    v.g[k++] = fold_ok ? std::atan((p.epsilon - lo) / hi) : kHalfPi;
    if (p.max_protrusion) v.g[k++] = (std::max(f.protrusion_left, f.protrusion_right) - *p.max_protrusion) / length;
    if (p.max_abs_s0) v.g[k++] = (std::abs(f.s0) - *p.max_abs_s0) / length;
  }
  v.violation = 0.0;
  for (double g : v.g) v.violation += std::max(0.0, g);
  return v;
}

// State shared by NLopt's callbacks. NLopt's COBYLA evaluates the objective and then the
// constraints at the same x; the last evaluation is cached so each x costs one set of fold
// reports, and every evaluation is offered to the best-design bookkeeping.
struct Search {
  const OffsetDesignProblem* problem = nullptr;
  double tolerance = 0.0;
  std::size_t folds = 0;
  double length = 1.0;
  int evaluations = 0;
  std::vector<double> last_x;
  SearchValues last;
  bool have_best_feasible = false;
  OffsetDesign best_feasible;
  double least_violation = kInf;
  OffsetDesign least_violating;
  std::exception_ptr error;

  const SearchValues& at(const double* x, unsigned n) {
    if (!last_x.empty() && std::equal(last_x.begin(), last_x.end(), x, x + n)) return last;
    last_x.assign(x, x + n);
    ++evaluations;
    Evaluation e = measure(*problem, last_x, tolerance);
    last = search_values(*problem, e, folds, length);
    if (e.design.feasible) {
      if (!have_best_feasible || e.design.fom < best_feasible.fom) {
        best_feasible = std::move(e.design);
        have_best_feasible = true;
      }
    } else if (!have_best_feasible && last.violation < least_violation) {
      least_violation = last.violation;
      least_violating = std::move(e.design);
    }
    return last;
  }
};

// NLopt's C++ wrapper turns an exception from a callback into a generic failure and loses it;
// the callbacks keep an unexpected one (anything but the builder's InputError, which makes an
// infeasible design) and stop the search, and optimize_offsets rethrows it.
double objective(unsigned n, const double* x, double* grad, void* data) {
  (void)grad;  // derivative-free
  auto* s = static_cast<Search*>(data);
  try {
    return s->at(x, n).objective;
  } catch (...) {
    s->error = std::current_exception();
    throw nlopt::forced_stop();
  }
}

void constraints(unsigned m, double* result, unsigned n, const double* x, double* grad, void* data) {
  (void)grad;
  auto* s = static_cast<Search*>(data);
  try {
    const SearchValues& v = s->at(x, n);
    std::copy(v.g.begin(), v.g.begin() + m, result);
  } catch (...) {
    s->error = std::current_exception();
    throw nlopt::forced_stop();
  }
}

}  // namespace

OffsetDesign evaluate_offsets(const OffsetDesignProblem& problem, const std::vector<double>& b,
                              double binding_tolerance) {
  check_input(problem, b, "b");
  if (!(binding_tolerance >= 0.0)) throw InputError("binding_tolerance", "must be >= 0");
  return measure(problem, b, binding_tolerance).design;
}

OffsetDesign optimize_offsets(const OffsetDesignProblem& problem, const std::vector<double>& start,
                              const OffsetOptimizeOptions& options) {
  check_input(problem, start, "start");
  if (options.max_evaluations < 1) throw InputError("options", "max_evaluations must be >= 1");
  if (!(options.initial_step > 0.0 && options.initial_step <= 1.0))
    throw InputError("options", "initial_step must be in (0, 1]");
  if (!(options.xtol_rel >= 0.0) || !(options.ftol_rel >= 0.0) || !(options.binding_tolerance >= 0.0))
    throw InputError("options", "tolerances must be >= 0");

  // The start fixes the number of folds (constraints) and the length scale; a start that
  // cannot be built is an input error, not something to search from.
  const std::vector<FoldMotion> start_motions = problem.motions(start);
  if (start_motions.empty()) throw InputError("start", "the builder gives no folds");
  Search s;
  s.problem = &problem;
  s.tolerance = options.binding_tolerance;
  s.folds = start_motions.size();
  s.length = 0.0;
  for (const FoldMotion& m : start_motions) s.length = std::max({s.length, m.thickness_left, m.thickness_right});
  if (!(s.length > 0.0)) s.length = 1.0;

  // COBYLA rather than SBPLX on a penalised objective: the constraints are inequalities whose
  // binding values the caller wants reported (a penalty leaves the optimum inside or outside
  // its bound by an amount set by the penalty weight), and COBYLA needs no derivatives, which
  // the FOM's max/min over folds and t does not have where the extreme changes fold or t
  // (its linear models cope with such kinks; a gradient method would zig-zag).
  const unsigned n = static_cast<unsigned>(start.size());
  const std::size_t per_fold = 1 + (problem.max_protrusion ? 1 : 0) + (problem.max_abs_s0 ? 1 : 0);
  std::vector<double> step(n);
  for (unsigned k = 0; k < n; ++k) step[k] = options.initial_step * (problem.upper[k] - problem.lower[k]);
  std::vector<double> x = start;
  std::string stop;
  nlopt::opt opt(nlopt::LN_COBYLA, n);
  opt.set_lower_bounds(problem.lower);
  opt.set_upper_bounds(problem.upper);
  opt.set_min_objective(objective, &s);
  // Constraint tolerance 0: feasibility is judged exactly by measure() anyway.
  opt.add_inequality_mconstraint(constraints, &s, std::vector<double>(s.folds * per_fold, 0.0));
  opt.set_maxeval(options.max_evaluations);
  opt.set_xtol_rel(options.xtol_rel);
  opt.set_ftol_rel(options.ftol_rel);
  opt.set_initial_step(step);
  double f = 0.0;
  try {
    stop = nlopt_result_name(opt.optimize(x, f));
  } catch (const nlopt::roundoff_limited&) {
    stop = "ROUNDOFF_LIMITED";
  } catch (const nlopt::forced_stop&) {
    stop = "FORCED_STOP";
  } catch (const std::runtime_error& e) {
    stop = std::string("FAILURE: ") + e.what();
  }
  if (s.error) std::rethrow_exception(s.error);

  OffsetDesign result = s.have_best_feasible ? s.best_feasible : s.least_violating;
  if (s.evaluations == 0) result = measure(problem, start, options.binding_tolerance).design;
  result.evaluations = s.evaluations;
  result.algorithm = "LN_COBYLA";
  result.stop_reason = stop;
  result.improved = result.b != start;
  return result;
}

}  // namespace rigidfold::sorce
