#pragma once
// The SORCE front door: a crease pattern in, its SORCE joints out - the path
// traced by the kernel's trace_motion (once where the model gives the exact path, else
// refined until the diagnostics settle: PathAccuracy) with the model `check` picks (the exact multiplier
// family for a pattern of flat-foldable degree-4 vertices, the general loop-closure solver
// otherwise, or always with sorce.trace.force_general), the joints of sorce_pattern.hpp, and,
// when asked, the panels' offset coefficients optimised for the figure of merit
// (sorce_optimize.hpp) with the joints rebuilt on the same traced path.
//
// Optimisation variables: the seed's three basis coefficients (eq 36/37,
// seed_offset_bases) of every face that borders a folding crease, in face order, in a box
// [-coefficient_bound, coefficient_bound]; the end offsets z_f(1) stay as derived (or given),
// so the stacking at t = 1 does not change. Start: the request's coefficients, else 0
// (linear offsets). The folds measured are the folding creases' joints.
//
// Units: as sorce_pattern.hpp (pattern units, radians, t dimensionless).
#include <optional>
#include <string>
#include <vector>

#include "design/sorce/sorce_optimize.hpp"
#include "design/sorce/sorce_pattern.hpp"

namespace rigidfold::sorce {

// How finely a splined path is traced. A path the model gives exactly (PathSpline::exact) is
// used as traced. Otherwise the steps are doubled from the request's trace.steps, at most
// max_doublings times, until two successive paths give the same diagnostics: the same folding
// creases, cusps, pivots, concave spans, ill-behaved and stationary t (each t within
// t_tolerance) and stacking, and s0, end points, arc lengths and protrusions within
// length_tolerance times the pattern's bounding-box diagonal. The finer of the two is used; the
// spline's values converge as N^-6, so its own error is about 1/64 of their difference. The
// doublings are few because a solver's path does not settle by refinement alone: its samples'
// own error (residual ~1e-10) grows in the spline's third derivative as N^3, and a flat-folded
// end it stops a few 1e-6 rad short of pi decides the stacking either way (vertex A on the
// general solver still changed at 1,280 steps, measured).
struct PathAccuracy {
  int max_doublings = 2;
  double t_tolerance = 1e-6;
  double length_tolerance = 1e-10;
};

// What the refinement did.
struct PathRefinement {
  bool exact = false;             // the model's exact path: traced once, nothing to refine
  std::vector<int> steps_tried;   // in order; the last is the path used
  bool settled = true;            // false: the diagnostics still changed at the last doubling
  std::string change;             // when not settled, what changed between the last two
};

struct SorceDesignRequest {
  PatternSorceRequest sorce;  // its `branch` is ignored: traced here from sorce.trace (force_general honoured)
  bool optimize = false;
  double epsilon = 0.0;                   // smallest convexity allowed (1/length)
  std::optional<double> max_protrusion;   // length
  std::optional<double> max_abs_s0;       // length
  double coefficient_bound = 2.0;         // > 0
  OffsetOptimizeOptions optimizer;
  int optimize_samples = 201;             // fold_report samples inside the search (>= 3)
  PathAccuracy accuracy;
};

struct SorceDesign {
  MotionBranch branch;                       // the traced path (branch 0 of the model's trace)
  PathRefinement refinement;                 // how many steps it took
  std::string model;                         // the model that traced it (trace_motion's model_name)
  PatternSorce sorce;                        // the joints (with the optimised coefficients, when asked)
  std::optional<OffsetDesign> optimization;  // the search's result, when asked
  std::vector<int> design_faces;             // faces whose coefficients were searched, 3 each in this order
};

// Throws InputError as pattern_sorce and optimize_offsets do, "coefficient_bound" (<= 0),
// "accuracy" (max_doublings outside 0..8, a tolerance not positive),
// "offset_coefficients[f]" for a start outside the box, and "branch" when nothing was traced.
SorceDesign sorce_design(const CreasePattern& pattern, const SorceDesignRequest& request);

// The design for people, a line each: the path (exact, or the steps it was splined through and
// whether its diagnostics settled), each folding crease's cusps, pivots, concave spans and
// ill-behaved t, the figure of merit (eq 38 with `epsilon`) and the stacking, the optimisation.
std::string brief(const SorceDesign& design, double epsilon);

}  // namespace rigidfold::sorce
