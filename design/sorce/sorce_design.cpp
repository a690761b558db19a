#include "design/sorce/sorce_design.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "kernel/math/angle_units.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::sorce {
namespace {

struct TracedPath {
  MotionBranch branch;
  std::string model;
};

// The model's traces by step count, each traced once: the design and its optimised rebuild
// settle on the same ladder of steps.
class PathLadder {
 public:
  PathLadder(const CreasePattern& pattern, const TraceRequest& trace)
      : pattern_(pattern), topology_(build_topology(pattern, "pattern")), trace_(trace) {}

  const TracedPath& at(int steps) {
    auto found = traced_.find(steps);
    if (found != traced_.end()) return found->second;
    TraceRequest rq = trace_;
    rq.steps = steps;
    MotionTrace traced = trace_motion(pattern_, topology_, rq);
    if (traced.branches.empty() || !traced.branches[0].traced)
      throw InputError("branch", "no motion was traced (" + traced.model_name + "): " + traced.note);
    return traced_.emplace(steps, TracedPath{std::move(traced.branches[0]), traced.model_name}).first->second;
  }

 private:
  const CreasePattern& pattern_;
  Topology topology_;
  TraceRequest trace_;
  std::map<int, TracedPath> traced_;
};

double bounding_diagonal(const CreasePattern& pattern) {
  Eigen::Vector3d lo = pattern.vertices.front(), hi = lo;
  for (const Eigen::Vector3d& v : pattern.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  return (hi - lo).norm();
}

bool same_values(const std::vector<double>& a, const std::vector<double>& b, double tolerance) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(std::abs(a[i] - b[i]) <= tolerance)) return false;
  return true;
}

bool same_spans(const std::vector<Span>& a, const std::vector<Span>& b, double tolerance) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(std::abs(a[i].begin - b[i].begin) <= tolerance && std::abs(a[i].end - b[i].end) <= tolerance)) return false;
  return true;
}

// Empty when the two designs give the same diagnostics (PathAccuracy); else what differs.
std::string diagnostics_change(const PatternSorce& a, const PatternSorce& b, const PathAccuracy& accuracy, double size) {
  if (a.creases.size() != b.creases.size()) return "the hinge creases";
  const double dt = accuracy.t_tolerance, length = accuracy.length_tolerance * size;
  for (std::size_t i = 0; i < a.creases.size(); ++i) {
    const CreaseJoint &x = a.creases[i], &y = b.creases[i];
    const std::string where = "crease " + std::to_string(x.edge) + ": ";
    if (x.folds != y.folds) return where + "whether it folds";
    if (!x.folds) continue;
    const FoldReport &p = x.report, &q = y.report;
    if (!same_values(p.cusps, q.cusps, dt)) return where + "cusps";
    if (p.pivot_at_start != q.pivot_at_start || p.pivot_at_end != q.pivot_at_end) return where + "pivots";
    if (!same_spans(p.concave_left, q.concave_left, dt) || !same_spans(p.concave_right, q.concave_right, dt))
      return where + "concave spans";
    if (!same_values(p.ill_behaved, q.ill_behaved, dt)) return where + "ill-behaved t";
    if (!same_values(p.stationary, q.stationary, dt)) return where + "stationary t";
    if (p.stacks != q.stacks) return where + "stacking";
    if (!same_values({p.s0, p.arc_length_left, p.arc_length_right, p.protrusion_left, p.protrusion_right},
                     {q.s0, q.arc_length_left, q.arc_length_right, q.protrusion_left, q.protrusion_right}, length))
      return where + "s0, arc lengths or protrusions";
    const double ends = std::max({(p.ends.left0 - q.ends.left0).norm(), (p.ends.right0 - q.ends.right0).norm(),
                                  (p.ends.left1 - q.ends.left1).norm(), (p.ends.right1 - q.ends.right1).norm()});
    if (!(ends <= length)) return where + "end points";
  }
  return "";
}

// eq 38's figure of merit for people: infinite where a convexity is unbounded or not positive.
std::string figure_of_merit_text(double fom) {
  return std::isfinite(fom) ? short_text(fom) : std::string("infinite (a convexity is unbounded or not positive)");
}

struct SettledJoints {
  TracedPath path;
  PatternSorce joints;
  PathRefinement refinement;
};

// The joints of `rq` on the ladder's path, from `steps` up, until their diagnostics settle.
SettledJoints settle(const CreasePattern& pattern, PatternSorceRequest rq, PathLadder& ladder, int steps,
                     const PathAccuracy& accuracy) {
  SettledJoints out;
  out.path = ladder.at(steps);
  out.refinement.steps_tried = {steps};
  out.refinement.exact = !out.path.branch.tan_half_ratio.empty() && rq.path_parameter == PathParameter::kDrive;
  rq.branch = out.path.branch;
  if (out.refinement.exact) {
    out.joints = pattern_sorce(pattern, rq);
    return out;
  }
  // The levels compare diagnostics only; the interference check runs once, on the path used.
  PatternSorceRequest probe = rq;
  probe.check_interference = false;
  out.joints = pattern_sorce(pattern, probe);
  const double size = bounding_diagonal(pattern);
  out.refinement.settled = false;
  out.refinement.change = "no finer path compared (max_doublings 0)";
  for (int doubling = 0; doubling < accuracy.max_doublings; ++doubling) {
    steps *= 2;
    TracedPath finer = ladder.at(steps);
    probe.branch = finer.branch;
    PatternSorce joints = pattern_sorce(pattern, probe);
    out.refinement.steps_tried.push_back(steps);
    out.refinement.change = diagnostics_change(out.joints, joints, accuracy, size);
    out.path = std::move(finer);
    out.joints = std::move(joints);
    if (out.refinement.change.empty()) {
      out.refinement.settled = true;
      break;
    }
  }
  if (rq.check_interference) {
    rq.branch = out.path.branch;
    out.joints = pattern_sorce(pattern, rq);
  }
  return out;
}

}  // namespace

SorceDesign sorce_design(const CreasePattern& pattern, const SorceDesignRequest& request) {
  if (!(request.coefficient_bound > 0.0) || !std::isfinite(request.coefficient_bound))
    throw InputError("coefficient_bound", "must be a positive number");
  const PathAccuracy& accuracy = request.accuracy;
  if (accuracy.max_doublings < 0 || accuracy.max_doublings > 8)
    throw InputError("accuracy", "max_doublings must be in 0..8");
  if (!(accuracy.t_tolerance > 0.0) || !(accuracy.length_tolerance > 0.0))
    throw InputError("accuracy", "the tolerances must be positive");
  SorceDesign out;
  PathLadder ladder(pattern, request.sorce.trace);
  SettledJoints settled = settle(pattern, request.sorce, ladder, request.sorce.trace.steps, accuracy);
  out.branch = std::move(settled.path.branch);
  out.model = std::move(settled.path.model);
  out.refinement = std::move(settled.refinement);
  out.sorce = std::move(settled.joints);
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
  // says which), with the same end offsets, on the path settled for them.
  PatternSorceRequest second = request.sorce;
  second.end_offsets.clear();
  for (const FaceOffset& f : base.faces) second.end_offsets.push_back(f.end_value);
  second.offset_coefficients.assign(nf, {});
  for (int f : out.design_faces)
    second.offset_coefficients[f].assign(out.optimization->b.begin() + slot[f] * per_face,
                                         out.optimization->b.begin() + (slot[f] + 1) * per_face);
  // The search ran on the path settled for the first design; the design found settles again
  // (its offsets can make the diagnostics ask for a finer path).
  settled = settle(pattern, second, ladder, request.sorce.trace.steps, accuracy);
  out.branch = std::move(settled.path.branch);
  out.refinement = std::move(settled.refinement);
  out.sorce = std::move(settled.joints);
  return out;
}

std::string brief(const SorceDesign& design, double epsilon) {
  const PatternSorce& s = design.sorce;
  const PathRefinement& path = design.refinement;
  std::ostringstream out;
  out << "  path: crease " << s.path.drive << " to " << short_text(to_degrees(s.path.final_drive)) << " deg, "
      << (path.exact ? "exact (multiplier model)"
                     : "splined through " + std::to_string(path.steps_tried.back()) + " steps" +
                           (path.settled ? ", where its diagnostics settle" : ""))
      << "\n";
  if (!path.settled)
    out << "  warning: the diagnostics below still changed between the last two step counts (" << path.change
        << "): they are the finer path's, not settled\n";
  std::vector<FoldReport> reports;
  for (const CreaseJoint& c : s.creases) {
    if (!c.folds) continue;
    const FoldReport& r = c.report;
    reports.push_back(r);
    out << "  crease " << c.edge << ": cusps " << r.cusps.size() << ", pivots" << (r.pivot_at_start ? " t=0" : "")
        << (r.pivot_at_end ? " t=1" : "") << (r.pivot_at_start || r.pivot_at_end ? "" : " none") << ", concave spans "
        << r.concave_left.size() << " left " << r.concave_right.size() << " right, ill-behaved t " << r.ill_behaved.size()
        << "\n";
  }
  out << "  figure of merit " << figure_of_merit_text(figure_of_merit(reports, epsilon)) << ", flat-folded end "
      << (s.checks.flat_folded_end ? "yes" : "no") << ", all stack " << (s.checks.all_stack ? "yes" : "no") << "\n";
  if (design.optimization)
    out << "  optimised: figure of merit " << figure_of_merit_text(design.optimization->fom) << ", feasible "
        << (design.optimization->feasible ? "yes" : "no") << "\n";
  return out.str();
}

}  // namespace rigidfold::sorce
