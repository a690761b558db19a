#include "kernel/network/network_analysis.hpp"

#include <cmath>
#include <numbers>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold {
namespace {

// The seed's flat-vertex conditions (2-33) for one linkage: twists in (0, 180) deg summing
// to 360 deg (to 1e-12 rad).
bool flat_vertex(const NetworkLinkage& l) {
  double sum = 0.0;
  for (double a : l.twists) {
    if (!(a > 0.0 && a < std::numbers::pi)) return false;
    sum += a;
  }
  return std::fabs(sum - 2.0 * std::numbers::pi) <= 1e-12;
}

void decide(NetworkAnalysis& r) {
  const int dof = r.mobility_rank.dof;
  if (dof == 0) {
    r.mobility = NetworkMobility::kRigid;
    r.verdict_class = FoldabilityClass::kNotFoldableProof;
    r.verdict = "rigid (DOF 0 at a closed configuration)";
  } else if (r.input_moves > 0) {
    r.mobility = NetworkMobility::kMobile;
    r.verdict_class = FoldabilityClass::kFoldable;
    r.verdict = "mobile (DOF " + std::to_string(dof) + " at a closed configuration; the input moves)";
  } else if (r.mobility_rank_input_held.dof == 0) {
    r.mobility = NetworkMobility::kSingular;
    r.verdict_class = FoldabilityClass::kNotFoldableEvidence;
    r.verdict = "singular configuration (first-order DOF " + std::to_string(dof) +
                ") where the input does not move by 1e-3 rad: not mobile through it (evidence)";
  } else {
    r.mobility = NetworkMobility::kInputLocked;
    r.verdict_class = FoldabilityClass::kUndecided;
    r.verdict = "first-order DOF " + std::to_string(dof) + " with the input held: other joints move, the input does not";
  }
}

}  // namespace

bool NetworkAnalysisOptions::IsValid(std::string* error) const {
  auto fail = [&](const char* what) {
    if (error) *error = what;
    return false;
  };
  if (!(closure_tolerance > 0 && closure_tolerance < 1e-3)) return fail("closure_tolerance: must be in (0, 1e-3) rad");
  if (!(rank_tolerance > 0 && rank_tolerance < 1)) return fail("rank_tolerance: must be in (0, 1)");
  if (!(probe_step > 0 && probe_step < 0.1)) return fail("probe_step: must be in (0, 0.1) rad");
  if (trace_steps < 0 || trace_steps > kMaxTraceSteps) return fail("trace_steps: must be in 0..10000");
  return true;
}

const char* to_string(NetworkMobility m) {
  switch (m) {
    case NetworkMobility::kRigid: return "rigid";
    case NetworkMobility::kMobile: return "mobile";
    case NetworkMobility::kSingular: return "singular";
    case NetworkMobility::kInputLocked: return "input locked";
    case NetworkMobility::kNoConfiguration: return "no configuration";
  }
  return "?";
}

NetworkAnalysis analyse_network(const NetworkSpec& spec, const NetworkAnalysisOptions& options) {
  std::string invalid;
  if (!options.IsValid(&invalid)) throw InputError(invalid.substr(0, invalid.find(':')), invalid.substr(invalid.find(':') + 2));
  if (options.trace_steps > 0 && !spec.has_end) throw InputError(options.source + ": input.end_deg", "needed to trace the input");
  const NetworkClosure system(spec.network);
  const LinkageNetwork& net = system.network();
  if (options.crease_pattern) {
    // The layout's conditions, before anything is solved: at the flat state (q = 0) only the
    // loops' closure can miss (joint offsets), which is checked again at the real configuration.
    try {
      network_crease_pattern(net, Eigen::VectorXd::Zero(net.num_joints()), options.source);
    } catch (const NoAnswerError&) {
    }
  }
  NetworkAnalysis r;
  r.equations = system.num_rows();
  for (const NetworkLinkage& l : net.linkages)
    if (flat_vertex(l)) r.flat_vertices.push_back(l.name);
  // A closed configuration with the input at its start value. None found is evidence (not
  // proof) that the network does not move through that input; the free search is not tried
  // instead, since it lands on singular states (the flat state of developable vertices),
  // where a first-order DOF over-counts.
  r.start = find_network_configuration(system, spec.input, spec.input_start, spec.guess);
  if (!r.start.found) {
    if (options.trace_steps > 0)
      throw NoAnswerError("network: no closed configuration at input.start_deg to trace from", r.start.residual);
    if (options.crease_pattern)
      throw NoAnswerError("network --out: no closed configuration at input.start_deg to take the letters from", r.start.residual);
    r.mobility = NetworkMobility::kNoConfiguration;
    r.verdict_class = FoldabilityClass::kNotFoldableEvidence;
    r.verdict = "not mobile through the input's start value (evidence: no closed configuration found)";
    return r;
  }
  r.residual = system.residual(r.start.q).lpNorm<Eigen::Infinity>();
  if (!(r.residual <= options.closure_tolerance)) throw NoAnswerError("network: the configuration found is not closed", r.residual);
  r.mobility_rank = network_mobility(system, r.start.q, {}, options.rank_tolerance);
  r.mobility_rank_input_held = network_mobility(system, r.start.q, {spec.input}, options.rank_tolerance);
  // A first-order DOF over-counts at a singular point: "mobile" only when the input actually
  // moves by probe_step (both ways, or one way at a motion limit).
  r.input_moves = r.mobility_rank.dof > 0 ? probe_input_motion(system, r.start.q, spec.input, options.probe_step) : 0;
  decide(r);
  if (options.crease_pattern) {
    if (r.mobility != NetworkMobility::kMobile)
      throw InputError("crease_pattern", "the network is not mobile through input.start_deg (" + r.verdict +
                                             "): a crease pattern is written for a mobile assembly only");
    r.crease_pattern = network_crease_pattern(net, r.start.q, options.source, options.closure_tolerance);
  }
  if (options.trace_steps > 0) r.trace = trace_network(system, r.start.q, spec.input, spec.input_end, options.trace_steps);
  return r;
}

}  // namespace rigidfold
