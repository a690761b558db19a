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
#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/network/network_run.hpp"
#include "report/network_json.hpp"

namespace rigidfold::cli {
namespace {

void print_network_text(std::FILE* text, const std::string& path, const NetworkSpec& spec, const NetworkAnalysis& r,
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
    std::fprintf(text, "  %-8s %14.9f deg\n", net.joint_names[k].c_str(), report::joint_angle_degrees(r.start.q[k]));
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
      for (int k : spec.outputs) std::fprintf(text, " %12.6f", report::joint_angle_degrees(p.q[k]));
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
    const NetworkRun run = run_network(a->path, a->trace, a->out);
    // With --out - the FOLD text went to standard output: the summary goes to stderr.
    if (a->json) {
      (run.wrote_stdout ? std::cerr : std::cout) << document_text(report::network_json(a->path, run.spec, run.analysis,
                                                                                       run.options, a->out))
                                                 << "\n";
      return;
    }
    print_network_text(run.wrote_stdout ? stderr : stdout, a->path, run.spec, run.analysis, run.options, a->out);
  });
}

}  // namespace rigidfold::cli
