#include "design/sorce/sorce_design.hpp"

#include <cmath>
#include <string>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::sorce {

SorceDesign sorce_design(const CreasePattern& pattern, const SorceDesignRequest& request) {
  if (!(request.coefficient_bound > 0.0) || !std::isfinite(request.coefficient_bound))
    throw InputError("coefficient_bound", "must be a positive number");
  SorceDesign out;
  {
    // Traced once, so that the optimised joints run on the very path the first ones did.
    const Topology topology = build_topology(pattern, "pattern");
    TraceRequest trace = request.sorce.trace;  // force_general as the caller set it
    MotionTrace traced = trace_motion(pattern, topology, trace);
    if (traced.branches.empty() || !traced.branches[0].traced)
      throw InputError("branch", "no motion was traced (" + traced.model_name + "): " + traced.note);
    out.branch = std::move(traced.branches[0]);
    out.model = traced.model_name;
  }
  PatternSorceRequest first = request.sorce;
  first.branch = out.branch;
  out.sorce = pattern_sorce(pattern, first);
  if (!request.optimize) return out;

  const int nf = pattern.num_faces();
  std::vector<bool> borders(nf, false);
  for (const CreaseJoint& j : out.sorce.creases)
    if (j.folds) borders[j.left_face] = borders[j.right_face] = true;
  std::vector<int> slot(nf, -1);
  for (int f = 0; f < nf; ++f)
    if (borders[f]) {
      slot[f] = static_cast<int>(out.design_faces.size());
      out.design_faces.push_back(f);
    }
  const std::vector<Polynomial> bases = seed_offset_bases();
  const int per_face = static_cast<int>(bases.size());
  const double c = request.coefficient_bound;
  std::vector<double> start(out.design_faces.size() * per_face, 0.0);
  for (int f : out.design_faces) {
    if (request.sorce.offset_coefficients.empty()) break;
    const std::vector<double>& given = request.sorce.offset_coefficients[f];
    for (std::size_t k = 0; k < given.size() && k < static_cast<std::size_t>(per_face); ++k) {
      if (!(std::abs(given[k]) < c))
        throw InputError("offset_coefficients[" + std::to_string(f) + "]", "the start must lie inside the box (-bound, bound)");
      start[slot[f] * per_face + k] = given[k];
    }
  }
  const PatternSorce& base = out.sorce;
  OffsetDesignProblem problem;
  problem.lower.assign(start.size(), -c);
  problem.upper.assign(start.size(), c);
  problem.epsilon = request.epsilon;
  problem.max_protrusion = request.max_protrusion;
  problem.max_abs_s0 = request.max_abs_s0;
  problem.report = ReportOptions{request.optimize_samples};
  problem.motions = [&base, &slot, &bases, per_face](const std::vector<double>& b) {
    auto offset = [&](int f) {
      const std::vector<double> coefficients(b.begin() + slot[f] * per_face, b.begin() + (slot[f] + 1) * per_face);
      return basis_offset(base.faces[f].end_value, coefficients, bases);
    };
    std::vector<FoldMotion> motions;
    for (const CreaseJoint& j : base.creases) {
      if (!j.folds) continue;
      FoldMotion m = j.motion;
      m.z_left = offset(j.left_face);
      m.z_right = offset(j.right_face);
      motions.push_back(std::move(m));
    }
    return motions;
  };
  out.optimization = optimize_offsets(problem, start, request.optimizer);

  // The joints rebuilt with the design found (the search's best, feasible or not: the report
  // says which), on the same path and end offsets.
  PatternSorceRequest second = first;
  second.end_offsets.clear();
  for (const FaceOffset& f : base.faces) second.end_offsets.push_back(f.end_value);
  second.offset_coefficients.assign(nf, {});
  for (int f : out.design_faces)
    second.offset_coefficients[f].assign(out.optimization->b.begin() + slot[f] * per_face,
                                         out.optimization->b.begin() + (slot[f] + 1) * per_face);
  out.sorce = pattern_sorce(pattern, second);
  return out;
}

}  // namespace rigidfold::sorce
