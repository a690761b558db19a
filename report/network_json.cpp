#include "report/network_json.hpp"

#include <cmath>
#include <numbers>

#include "kernel/math/angle_units.hpp"

namespace rigidfold::report {
namespace {

using Json = nlohmann::ordered_json;

Json configuration_json(const NetworkSpec& spec, const NetworkAnalysis& r) {
  const LinkageNetwork& net = spec.network;
  Json st;
  st["input_joint"] = net.joint_names[spec.input];
  st["input_start_deg"] = to_degrees(spec.input_start);
  if (!r.start.found) {
    st["closed_at_input_start"] = false;
    st["least_residual_rad"] = r.start.residual;
    st["starts"] = r.start.starts;
    return st;
  }
  st["closed_at_input_start"] = true;
  st["starts"] = r.start.starts;
  st["residual_rad"] = r.residual;
  Json q = Json::object();
  for (int k = 0; k < net.num_joints(); ++k) q[net.joint_names[k]] = joint_angle_degrees(r.start.q[k]);
  st["joints_deg"] = q;
  return st;
}

Json mobility_json(const NetworkAnalysis& r) {
  const RankResult& m = r.mobility_rank;
  return {{"dof", m.dof},           {"dof_input_held", r.mobility_rank_input_held.dof}, {"rank", m.rank},
          {"sigma_max", m.sigma_max}, {"sigma_kept", m.sigma_kept},                      {"sigma_dropped", m.sigma_dropped},
          {"method", m.method},     {"input_moves_1e-3_rad", r.input_moves}};
}

Json crease_pattern_json(const LinkageNetwork& net, const NetworkCreasePattern& cp, const std::string& file) {
  Json c;
  c["file"] = file;
  c["vertices"] = cp.pattern.num_vertices();
  c["creases"] = cp.num_creases();
  c["central_angle_sum_deg"] = to_degrees(cp.central_angle_sum);
  c["vertex_linkages"] = cp.vertex_linkage;
  Json o = Json::object();
  for (int k = 0; k < net.num_linkages(); ++k) o[net.linkages[k].name] = cp.orientation[k] > 0 ? "as given" : "reversed";
  c["layout"] = o;
  c["letters"] = cp.crease_letters();
  c["vertex_loop_residual_rad"] = cp.residual;
  return c;
}

Json trace_json(const NetworkSpec& spec, const NetworkTrace& trace, int steps) {
  Json tr;
  tr["steps"] = steps;
  tr["complete"] = trace.complete;
  if (!trace.complete) tr["stop_reason"] = trace.stop_reason;
  Json pts = Json::array();
  for (const NetworkTracePoint& p : trace.points) {
    Json outs = Json::object();
    for (int k : spec.outputs) outs[spec.network.joint_names[k]] = joint_angle_degrees(p.q[k]);
    pts.push_back({{"input_deg", to_degrees(p.input)}, {"outputs_deg", outs}, {"residual_rad", p.residual}, {"dof", p.dof}});
  }
  tr["points"] = pts;
  return tr;
}

}  // namespace

double joint_angle_degrees(double radians) {
  double d = to_degrees(std::remainder(radians, 2.0 * std::numbers::pi));
  if (d <= -180.0) d += 360.0;
  return d;
}

nlohmann::ordered_json network_json(const std::string& network_path, const NetworkSpec& spec, const NetworkAnalysis& analysis,
                                    const NetworkAnalysisOptions& options, const std::string& crease_pattern_path) {
  const NetworkAnalysis& r = analysis;
  Json j;
  j["network"] = network_path;
  if (!spec.description.empty()) j["description"] = spec.description;
  j["model"] = "general: one loop closure per linkage (3 rows), exact sparse Jacobian, minimum-norm Gauss-Newton, dense SVD rank";
  j["joints"] = spec.network.num_joints();
  j["linkages"] = spec.network.num_linkages();
  j["equations"] = r.equations;
  j["closure_tolerance_rad"] = options.closure_tolerance;
  j["rank_tolerance_relative"] = options.rank_tolerance;
  j["flat_vertices_2_33"] = r.flat_vertices;
  j["configuration"] = configuration_json(spec, r);
  if (r.start.found) j["mobility"] = mobility_json(r);
  j["verdict"] = r.verdict;
  j["verdict_class"] = to_string(r.verdict_class);
  if (r.crease_pattern) j["crease_pattern"] = crease_pattern_json(spec.network, *r.crease_pattern, crease_pattern_path);
  if (r.trace) j["trace"] = trace_json(spec, *r.trace, options.trace_steps);
  return j;
}

}  // namespace rigidfold::report
