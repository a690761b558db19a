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
#include <optional>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/network/network_closure.hpp"
#include "kernel/network/network_crease_pattern.hpp"
#include "kernel/network/network_json.hpp"
#include "kernel/network/network_trace.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/assignment.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/output_set.hpp"
#include "app/summary_stream.hpp"

namespace rigidfold::cli {
namespace {

constexpr double kClosureTolerance = 1e-12;  // rad, every printed configuration
constexpr double kRankTolerance = 1e-9;      // relative to sigma_max

// Degrees in (-180, 180].
double wrapped_degrees(double rad) {
  double d = to_degrees(std::remainder(rad, 2.0 * std::numbers::pi));
  if (d <= -180.0) d += 360.0;
  return d;
}

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
    if (a->trace < 0 || a->trace > kMaxTraceSteps) throw InputError("--trace", "must be in 0..10000");
    const NetworkSpec spec = read_network_json(a->path);
    if (a->trace > 0 && !spec.has_end) throw InputError(a->path + ": input.end_deg", "needed by --trace");
    const NetworkClosure system(spec.network);
    const LinkageNetwork& net = system.network();
    OutputSet outputs;
    outputs.add_input("NETWORK", a->path);
    if (!a->out.empty()) {
      outputs.add_output("--out", a->out);
      // The layout's conditions, before anything is solved: at the flat state (q = 0) only
      // the loops' closure can miss (joint offsets), which is checked again at the real
      // configuration below.
      try {
        network_crease_pattern(net, Eigen::VectorXd::Zero(net.num_joints()), a->path);
      } catch (const NoAnswerError&) {
      }
    }
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);

    // A closed configuration with the input at its start value. None found is evidence (not
    // proof) that the network does not move through that input; the free search is not tried
    // instead, since it lands on singular states (the flat state of developable vertices),
    // where a first-order DOF over-counts.
    const NetworkConfiguration start = find_network_configuration(system, spec.input, spec.input_start, spec.guess);
    nlohmann::ordered_json j;
    j["network"] = a->path;
    if (!spec.description.empty()) j["description"] = spec.description;
    j["model"] = "general: one loop closure per linkage (3 rows), exact sparse Jacobian, minimum-norm Gauss-Newton, dense SVD rank";
    j["joints"] = net.num_joints();
    j["linkages"] = net.num_linkages();
    j["equations"] = system.num_rows();
    j["closure_tolerance_rad"] = kClosureTolerance;
    j["rank_tolerance_relative"] = kRankTolerance;
    nlohmann::ordered_json flat = nlohmann::ordered_json::array();
    for (const NetworkLinkage& l : net.linkages)
      if (flat_vertex(l)) flat.push_back(l.name);
    j["flat_vertices_2_33"] = flat;
    if (!start.found) {
      if (a->trace > 0)
        throw NoAnswerError("network: no closed configuration at input.start_deg to trace from", start.residual);
      if (!a->out.empty())
        throw NoAnswerError("network --out: no closed configuration at input.start_deg to take the letters from", start.residual);
      j["configuration"] = {{"input_joint", net.joint_names[spec.input]},
                            {"input_start_deg", to_degrees(spec.input_start)},
                            {"closed_at_input_start", false},
                            {"least_residual_rad", start.residual},
                            {"starts", start.starts}};
      j["verdict"] = "not mobile through the input's start value (evidence: no closed configuration found)";
      if (a->json) {
        std::cout << document_text(j) << "\n";
        return;
      }
      std::printf("network %s: %d joints, %d linkages, %d equations\n", a->path.c_str(), net.num_joints(),
                  net.num_linkages(), system.num_rows());
      std::printf("no closed configuration with %s = %.12g deg: least residual %.3e rad after %d Newton starts\n",
                  net.joint_names[spec.input].c_str(), to_degrees(spec.input_start), start.residual, start.starts);
      std::printf("verdict: %s\n", j["verdict"].get<std::string>().c_str());
      return;
    }
    const double residual = system.residual(start.q).lpNorm<Eigen::Infinity>();
    if (!(residual <= kClosureTolerance)) throw NoAnswerError("network: the configuration found is not closed", residual);
    const RankResult mob = network_mobility(system, start.q, {}, kRankTolerance);
    const RankResult mob_held = network_mobility(system, start.q, {spec.input}, kRankTolerance);

    nlohmann::ordered_json st;
    st["input_joint"] = net.joint_names[spec.input];
    st["input_start_deg"] = to_degrees(spec.input_start);
    st["closed_at_input_start"] = true;
    st["starts"] = start.starts;
    st["residual_rad"] = residual;
    nlohmann::ordered_json q = nlohmann::ordered_json::object();
    for (int k = 0; k < net.num_joints(); ++k) q[net.joint_names[k]] = wrapped_degrees(start.q[k]);
    st["joints_deg"] = q;
    j["configuration"] = st;
    nlohmann::ordered_json m;
    m["dof"] = mob.dof;
    m["dof_input_held"] = mob_held.dof;
    m["rank"] = mob.rank;
    m["sigma_max"] = mob.sigma_max;
    m["sigma_kept"] = mob.sigma_kept;
    m["sigma_dropped"] = mob.sigma_dropped;
    m["method"] = mob.method;
    // A first-order DOF over-counts at a singular point: "mobile" only when the input
    // actually moves by 1e-3 rad (both ways, or one way at a motion limit).
    const int moves = mob.dof > 0 ? probe_input_motion(system, start.q, spec.input) : 0;
    m["input_moves_1e-3_rad"] = moves;
    j["mobility"] = m;
    std::string verdict;
    if (mob.dof == 0) {
      verdict = "rigid (DOF 0 at a closed configuration)";
    } else if (moves > 0) {
      verdict = "mobile (DOF ";
      verdict += std::to_string(mob.dof);
      verdict += " at a closed configuration; the input moves)";
    } else if (mob_held.dof == 0) {
      verdict = "singular configuration (first-order DOF ";
      verdict += std::to_string(mob.dof);
      verdict += ") where the input does not move by 1e-3 rad: not mobile through it (evidence)";
    } else {
      verdict = "first-order DOF ";
      verdict += std::to_string(mob.dof);
      verdict += " with the input held: other joints move, the input does not";
    }
    j["verdict"] = verdict;
    std::optional<NetworkCreasePattern> cp;
    if (!a->out.empty()) {
      if (!(mob.dof > 0 && moves > 0))
        throw InputError("--out", "the network is not mobile through input.start_deg (" + verdict +
                                      "): a crease pattern is written for a mobile assembly only");
      cp = network_crease_pattern(net, start.q, a->path, kClosureTolerance);
      outputs.stage(a->out, write_fold_string(cp->pattern));
      nlohmann::ordered_json c;
      c["file"] = a->out;
      c["vertices"] = cp->pattern.num_vertices();
      c["creases"] = cp->pattern.num_edges() - 8;
      c["central_angle_sum_deg"] = to_degrees(cp->central_angle_sum);
      c["vertex_linkages"] = cp->vertex_linkage;
      nlohmann::ordered_json o = nlohmann::ordered_json::object();
      for (int k = 0; k < net.num_linkages(); ++k) o[net.linkages[k].name] = cp->orientation[k] > 0 ? "as given" : "reversed";
      c["layout"] = o;
      std::string letters;
      for (int e = 0; e < cp->pattern.num_edges(); ++e)
        if (cp->edge_joint[e] >= 0) letters += assignment_letter(cp->pattern.assignments[e]);
      c["letters"] = letters;
      c["vertex_loop_residual_rad"] = cp->residual;
      j["crease_pattern"] = c;
    }

    NetworkTrace trace;
    if (a->trace > 0) {
      trace = trace_network(system, start.q, spec.input, spec.input_end, a->trace);
      nlohmann::ordered_json tr;
      tr["steps"] = a->trace;
      tr["complete"] = trace.complete;
      if (!trace.complete) tr["stop_reason"] = trace.stop_reason;
      nlohmann::ordered_json pts = nlohmann::ordered_json::array();
      for (const NetworkTracePoint& p : trace.points) {
        nlohmann::ordered_json o;
        o["input_deg"] = to_degrees(p.input);
        nlohmann::ordered_json outs = nlohmann::ordered_json::object();
        for (int k : spec.outputs) outs[net.joint_names[k]] = wrapped_degrees(p.q[k]);
        o["outputs_deg"] = outs;
        o["residual_rad"] = p.residual;
        o["dof"] = p.dof;
        pts.push_back(o);
      }
      tr["points"] = pts;
      j["trace"] = tr;
    }
    outputs.commit();
    // With --out - the FOLD text went to standard output: the summary goes to stderr.
    std::FILE* text = outputs.writes_stdout() ? stderr : stdout;
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    std::fprintf(text, "network %s: %d joints, %d linkages, %d equations\n", a->path.c_str(), net.num_joints(), net.num_linkages(),
                system.num_rows());
    if (!spec.description.empty()) std::fprintf(text, "  %s\n", spec.description.c_str());
    std::fprintf(text, "closed configuration at %s = %.12g deg, residual %.2e rad (<= %.0e)\n", net.joint_names[spec.input].c_str(),
                to_degrees(spec.input_start), residual, kClosureTolerance);
    for (int k = 0; k < net.num_joints(); ++k) std::fprintf(text, "  %-8s %14.9f deg\n", net.joint_names[k].c_str(), wrapped_degrees(start.q[k]));
    std::fprintf(text, "mobility: DOF %d (input held: %d), rank %d, singular values kept >= %.3e, dropped <= %.3e (tolerance %.0e x %.3e)\n",
                mob.dof, mob_held.dof, mob.rank, mob.sigma_kept, mob.sigma_dropped, kRankTolerance, mob.sigma_max);
    std::fprintf(text, "verdict: %s\n", j["verdict"].get<std::string>().c_str());
    if (a->trace > 0) {
      std::fprintf(text, "trace of %s (deg):", net.joint_names[spec.input].c_str());
      for (int k : spec.outputs) std::fprintf(text, " %s", net.joint_names[k].c_str());
      std::fprintf(text, "  residual_rad dof\n");
      for (const NetworkTracePoint& p : trace.points) {
        std::fprintf(text, "  %12.6f", to_degrees(p.input));
        for (int k : spec.outputs) std::fprintf(text, " %12.6f", wrapped_degrees(p.q[k]));
        std::fprintf(text, "  %.1e %d\n", p.residual, p.dof);
      }
      if (!trace.complete) std::fprintf(text, "trace stopped: %s\n", trace.stop_reason.c_str());
    }
    if (cp)
      std::fprintf(text, "crease pattern: %d vertices, %d creases (letters %s), vertex loops close to %.1e rad; wrote %s\n",
                  cp->pattern.num_vertices(), cp->pattern.num_edges() - 8,
                  j["crease_pattern"]["letters"].get<std::string>().c_str(), cp->residual, a->out.c_str());
  });
}

}  // namespace rigidfold::cli
