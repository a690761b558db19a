#pragma once
// The SORCE front door: a crease pattern in, its SORCE joints out - the path
// traced once by the kernel's trace_motion with the model `check` picks (the exact multiplier
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

struct SorceDesignRequest {
  PatternSorceRequest sorce;  // its `branch` is ignored: traced here from sorce.trace (force_general honoured)
  bool optimize = false;
  double epsilon = 0.0;                   // smallest convexity allowed (1/length)
  std::optional<double> max_protrusion;   // length
  std::optional<double> max_abs_s0;       // length
  double coefficient_bound = 2.0;         // > 0
  OffsetOptimizeOptions optimizer;
  int optimize_samples = 201;             // fold_report samples inside the search (>= 3)
};

struct SorceDesign {
  MotionBranch branch;                       // the traced path (branch 0 of the model's trace)
  std::string model;                         // the model that traced it (trace_motion's model_name)
  PatternSorce sorce;                        // the joints (with the optimised coefficients, when asked)
  std::optional<OffsetDesign> optimization;  // the search's result, when asked
  std::vector<int> design_faces;             // faces whose coefficients were searched, 3 each in this order
};

// Throws InputError as pattern_sorce and optimize_offsets do, "coefficient_bound" (<= 0),
// "offset_coefficients[f]" for a start outside the box, and "branch" when nothing was traced.
SorceDesign sorce_design(const CreasePattern& pattern, const SorceDesignRequest& request);

}  // namespace rigidfold::sorce
