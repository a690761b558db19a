// rigidfold network NETWORK.json [--json] [--trace N] [--out P.fold]
// A network of spherical linkages given by twists (kernel/network/network_json.hpp): a closed
// configuration at the input's start value, the mobility there (DOF with the stated rank
// tolerance), and with --trace N the input-output relation over N equal input steps.
// Joint angles are the seed-003 DH angles theta (linkage_network.hpp); a crease's fold angle
// is rho = -theta. Every configuration printed has its closure residual checked first.
// --out P.fold: a mobile assembly of four 4R linkages whose vertices are flat paper (2-33)
// around a flat central panel (2-32) as a crease pattern (network_crease_pattern.hpp), its
// letters and fold angles those of the configuration at the input's start; the conditions
// are checked before anything is solved (exit 2 naming the place and the reason), and the
// file is written only after the pattern's own vertex loops close there.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/network/network_analysis.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/output_set.hpp"

namespace rigidfold::cli {
namespace {

using Json = nlohmann::ordered_json;

// Degrees in (-180, 180].
double wrapped_degrees(double rad) {
  double d = to_degrees(std::remainder(rad, 2.0 * std::numbers::pi));
  if (d <= -180.0) d += 360.0;
  return d;
}

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
  for (int k = 0; k < net.num_joints(); ++k) q[net.joint_names[k]] = wrapped_degrees(r.start.q[k]);
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
    for (int k : spec.outputs) outs[spec.network.joint_names[k]] = wrapped_degrees(p.q[k]);
    pts.push_back({{"input_deg", to_degrees(p.input)}, {"outputs_deg", outs}, {"residual_rad", p.residual}, {"dof", p.dof}});
  }
  tr["points"] = pts;
  return tr;
}

Json network_json(const std::string& path, const NetworkSpec& spec, const NetworkAnalysis& r, const NetworkAnalysisOptions& o,
                  const std::string& out) {
  const LinkageNetwork& net = spec.network;
  Json j;
  j["network"] = path;
  if (!spec.description.empty()) j["description"] = spec.description;
  j["model"] = "general: one loop closure per linkage (3 rows), exact sparse Jacobian, minimum-norm Gauss-Newton, dense SVD rank";
  j["joints"] = net.num_joints();
  j["linkages"] = net.num_linkages();
  j["equations"] = r.equations;
  j["closure_tolerance_rad"] = o.closure_tolerance;
  j["rank_tolerance_relative"] = o.rank_tolerance;
  j["flat_vertices_2_33"] = r.flat_vertices;
  j["configuration"] = configuration_json(spec, r);
  if (r.start.found) j["mobility"] = mobility_json(r);
  j["verdict"] = r.verdict;
  j["verdict_class"] = to_string(r.verdict_class);
  if (r.crease_pattern) j["crease_pattern"] = crease_pattern_json(net, *r.crease_pattern, out);
  if (r.trace) j["trace"] = trace_json(spec, *r.trace, o.trace_steps);
  return j;
}

void print_text(std::FILE* text, const std::string& path, const NetworkSpec& spec, const NetworkAnalysis& r,
                const NetworkAnalysisOptions& o, const std::string& out) {
  const LinkageNetwork& net = spec.network;
  std::fprintf(text, "network %s: %d joints, %d linkages, %d equations\n", path.c_str(), net.num_joints(), net.num_linkages(),
               r.equations);
  if (!r.start.found) {
    std::fprintf(text, "no closed configuration with %s = %.12g deg: least residual %.3e rad after %d Newton starts\n",
                 net.joint_names[spec.input].c_str(), to_degrees(spec.input_start), r.start.residual, r.start.starts);
    std::fprintf(text, "verdict: %s\n", r.verdict.c_str());
    return;
  }
  if (!spec.description.empty()) std::fprintf(text, "  %s\n", spec.description.c_str());
  std::fprintf(text, "closed configuration at %s = %.12g deg, residual %.2e rad (<= %.0e)\n", net.joint_names[spec.input].c_str(),
               to_degrees(spec.input_start), r.residual, o.closure_tolerance);
  for (int k = 0; k < net.num_joints(); ++k)
    std::fprintf(text, "  %-8s %14.9f deg\n", net.joint_names[k].c_str(), wrapped_degrees(r.start.q[k]));
  const RankResult& m = r.mobility_rank;
  std::fprintf(text, "mobility: DOF %d (input held: %d), rank %d, singular values kept >= %.3e, dropped <= %.3e (tolerance %.0e x %.3e)\n",
               m.dof, r.mobility_rank_input_held.dof, m.rank, m.sigma_kept, m.sigma_dropped, o.rank_tolerance, m.sigma_max);
  std::fprintf(text, "verdict: %s\n", r.verdict.c_str());
  if (r.trace) {
    std::fprintf(text, "trace of %s (deg):", net.joint_names[spec.input].c_str());
    for (int k : spec.outputs) std::fprintf(text, " %s", net.joint_names[k].c_str());
    std::fprintf(text, "  residual_rad dof\n");
    for (const NetworkTracePoint& p : r.trace->points) {
      std::fprintf(text, "  %12.6f", to_degrees(p.input));
      for (int k : spec.outputs) std::fprintf(text, " %12.6f", wrapped_degrees(p.q[k]));
      std::fprintf(text, "  %.1e %d\n", p.residual, p.dof);
    }
    if (!r.trace->complete) std::fprintf(text, "trace stopped: %s\n", r.trace->stop_reason.c_str());
  }
  if (r.crease_pattern) {
    std::fprintf(text, "crease pattern: %d vertices, %d creases (letters %s), vertex loops close to %.1e rad; wrote %s\n",
                 r.crease_pattern->pattern.num_vertices(), r.crease_pattern->num_creases(),
                 r.crease_pattern->crease_letters().c_str(),
                 r.crease_pattern->residual, out.c_str());
  }
}

}  // namespace

void add_network_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("network", "Network of spherical linkages given by twists: mobility and input-output relations");
  struct Args {
    std::string path;
    bool json = false;
    int trace = 0;
    std::string out;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("NETWORK", a->path, "network JSON (linkages, twists_deg, shared joints)")->required();
  cmd->add_flag("--json", a->json, "print JSON");
  cmd->add_option("--trace", a->trace, "trace the input from input.start_deg to input.end_deg in N steps");
  cmd->add_option("--out", a->out,
                  "write the assembly of four 4R linkages as a FOLD crease pattern (needs flat vertices (2-33), a flat "
                  "central panel (2-32) and a mobile network; letters from the configuration at input.start_deg)");
  cmd->callback([a] {
    NetworkAnalysisOptions o;
    o.trace_steps = a->trace;
    o.crease_pattern = !a->out.empty();
    o.source = a->path;
    if (std::string why; !o.IsValid(&why)) throw InputError("--trace", "must be in 0..10000");
    const NetworkSpec spec = read_network_json(a->path);
    OutputSet outputs;
    outputs.add_input("NETWORK", a->path);
    if (!a->out.empty()) outputs.add_output("--out", a->out);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    NetworkAnalysis r;
    try {
      r = analyse_network(spec, o);
    } catch (const InputError& e) {
      if (e.place() == "crease_pattern") throw InputError("--out", e.message());
      throw;
    }
    if (r.crease_pattern) outputs.stage(a->out, write_fold_string(r.crease_pattern->pattern));
    outputs.commit();
    if (a->json) {
      std::cout << document_text(network_json(a->path, spec, r, o, a->out)) << "\n";
      return;
    }
    // With --out - the FOLD text went to standard output: the summary goes to stderr.
    print_text(outputs.writes_stdout() ? stderr : stdout, a->path, spec, r, o, a->out);
  });
}

}  // namespace rigidfold::cli
