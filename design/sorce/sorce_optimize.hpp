#pragma once
// Inverse design of SORCE offsets (seed 002 section 7, digest section 4 "Inverse design"):
// choose the coefficients b of the offset functions (eq 36: z = end (t + sum b_j B_j), and
// optionally the coefficients of a split offset d(t)) that minimise the figure of merit
// (eq 38: largest convexity over smallest, over every fold and t), subject to
//   every convexity c_l, c_r >= epsilon on every fold for all t (finite: no pivots),
//   no cusps and no t where gamma' = 0 (fold_report's cusps, ill_behaved, stationary empty),
//   optional: largest protrusion beyond the slab faces <= a bound, |s0| <= a bound,
//   b inside a box.
// The problem is generic: a caller-supplied function maps b to the fold motions (one vertex,
// or later a pattern's folds sharing panel offsets), and every measure comes from
// fold_report (sorce_fold_report.hpp) on those motions.
//
// Method: NLopt's COBYLA (derivative-free, inequality constraints), see sorce_optimize.cpp.
// Deterministic: no random numbers, a fixed evaluation budget and fixed tolerances, so the
// same inputs give the same result bit for bit on one build.
//
// Units: b dimensionless (multiplies the bases, whose values are dimensionless in t);
// convexities 1/length; protrusion and s0 in the motions' length unit.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "design/sorce/sorce_fold_report.hpp"

namespace rigidfold::sorce {

// b (all coefficients, concatenated in the caller's order) -> the folds' motions. May throw
// InputError for a b it cannot build; the optimiser treats such a b as infeasible.
using OffsetMotionBuilder = std::function<std::vector<FoldMotion>(const std::vector<double>& b)>;

struct OffsetDesignProblem {
  OffsetMotionBuilder motions;
  // Box on b: both of the coefficient count's length, lower[k] < upper[k] (finite).
  std::vector<double> lower, upper;
  double epsilon = 0.0;                  // smallest allowed convexity (1/length), >= 0
  std::optional<double> max_protrusion;  // bound on every fold's protrusion (length), >= 0
  std::optional<double> max_abs_s0;      // bound on every fold's |s0| (length), >= 0
  ReportOptions report{201};             // fold_report settings for every evaluation
};

struct OffsetOptimizeOptions {
  int max_evaluations = 400;  // NLopt maxeval (>= 1)
  // COBYLA's initial step in every coordinate, as a fraction of the box width (0, 1].
  double initial_step = 0.05;
  double xtol_rel = 1e-6;  // NLopt stop on relative change of b
  double ftol_rel = 1e-8;  // NLopt stop on relative change of the objective (log FOM)
  // A constraint is reported binding when |value - bound| <= binding_tolerance * scale,
  // scale = |bound| (convexity, protrusion, s0; 1e-12 if the bound is 0) or the box width
  // (coefficient bounds).
  double binding_tolerance = 1e-3;
};

// One active constraint at the returned design.
struct BindingConstraint {
  // "convexity_left", "convexity_right" (value = that profile's min convexity, bound =
  // epsilon), "protrusion_left", "protrusion_right", "s0" (value |s0|), "lower", "upper"
  // (coefficient box; value = b[index]).
  std::string name;
  int index = 0;  // fold index for the fold constraints, coefficient index for the box
  double value = 0.0, bound = 0.0;
};

// A design b with its measures (also what evaluate_offsets returns).
struct OffsetDesign {
  std::vector<double> b;
  std::vector<FoldReport> folds;                    // fold_report of every motion, problem.report settings
  double fom = 0.0;                                 // figure_of_merit(folds, epsilon): eq 38 (+inf if undefined)
  double min_convexity = 0.0, max_convexity = 0.0;  // over folds, both profiles
  double max_protrusion = 0.0, max_abs_s0 = 0.0;
  std::size_t cusps = 0;                   // fold_report cusps, over the folds
  std::size_t ill_behaved = 0;             // t with gamma' = 0 (ill_behaved and stationary): profile undefined
  bool feasible = false;                   // every constraint above met exactly (no tolerance)
  std::vector<BindingConstraint> binding;  // constraints within binding_tolerance of their bound
  // Optimiser bookkeeping (evaluate_offsets: 1 evaluation, algorithm/stop_reason empty).
  int evaluations = 0;      // designs measured (one fold_report per fold each)
  std::string algorithm;    // "LN_COBYLA"
  std::string stop_reason;  // NLopt's result, e.g. "XTOL_REACHED", "MAXEVAL_REACHED"
  bool improved = false;    // the returned b is not the start
};

// Measures b without optimising (evaluations = 1). Throws InputError as optimize_offsets, with
// the place "b" for b, and "binding_tolerance" (< 0).
OffsetDesign evaluate_offsets(const OffsetDesignProblem& problem, const std::vector<double>& b,
                              double binding_tolerance = 1e-3);

// Minimises the FOM from `start` (one COBYLA run). Returns the best feasible design evaluated
// (the start itself if it is feasible and nothing better was found); if no evaluated design is
// feasible, the one with the smallest constraint violation, with feasible = false.
// Throws InputError: "motions" (no builder), "bounds" (lengths differ or 0, lower >= upper, not
// finite), "start" (length differs from the bounds', outside them, or the builder gives no
// folds), "epsilon" (< 0 or not finite), "max_protrusion", "max_abs_s0" (< 0), "samples"
// (report samples < 3), "options" (max_evaluations < 1, initial_step outside (0, 1],
// tolerances < 0); the builder's own errors at the start; and rethrows any exception other
// than InputError that the builder or fold_report throws during the search.
OffsetDesign optimize_offsets(const OffsetDesignProblem& problem, const std::vector<double>& start,
                              const OffsetOptimizeOptions& options = {});

}  // namespace rigidfold::sorce
