// rigidfold energy PATTERN --rest REST.json|REST.fold [--k-m K] [--k-v K] [--k-u K | --stiffness SPEC.json]
//                  [--starts N] [--seed S] [--barriers] [--json]
// --barriers: the barrier both ways between every pair of stable states (adjacent pairs in
// energy when there are more than 6 states): a string method with a climbing image on the
// closure manifold, refined by Newton to an index-1 saddle and checked
// (kernel/energy/minimum_energy_path.hpp); a pair whose saddle fails a check says "not found"
// and why. Off by default: one string search (two starts) per pair. Measured in Release on the
// bundled 8-crease waterbomb base with its rest60 state: --starts 2 (2 states, 1 pair) 0.08 s
// against 0.01 s without; the default 24 starts (5 states, 10 pairs, most of them "not found":
// their saddles lead to a third state) 1.7 s. Worst case per pair: 2 starts x (max_iterations
// = 3000 string iterations x 15 interior images) when the string neither converges nor stalls.
// --load SPEC.json: the vertex held at a height above the plane of its supports
// (kernel/energy/load_spec.hpp, vertex_height_control.hpp): the loaded equilibria reached from
// the rest state and from every stable state, each converged (KKT residual <= 1e-12) before
// it is printed, with its reaction force and stability; none converged: exit 3.
// --stiffness SPEC.json: one stiffness per crease (kernel/energy/stiffness_spec.hpp: default,
// by letter, by edge index, or from a flexure material), errors naming the JSON path.
// Each state also says whether it keeps the M/V letters and whether panels pass through each
// other there (the springs know neither).
// Stable states of any crease pattern with torsional springs at its creases
// (kernel/energy/crease_spring_states.hpp, JSON by report/energy_json.hpp): the rest state and N random starts that respect
// the letters, each minimised on the loop-closure manifold with no symmetry imposed; every
// state printed has passed its checks (closure <= 1e-12 rad, stationarity, reduced Hessian
// positive definite).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "report/energy_json.hpp"
#include "app/provenance.hpp"
#include "app/number_flags.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/crease_spring_states.hpp"
#include "kernel/energy/rest_angles.hpp"
#include "kernel/energy/stiffness_spec.hpp"
#include "kernel/energy/load_spec.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {

void add_energy_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("energy", "Stable states of a pattern with crease springs (multistart, no symmetry imposed)");
  struct Args {
    std::string pattern, rest, stiffness, load;
    double k_m = 1, k_v = 1, k_u = 1;
    int starts = 24;
    std::uint64_t seed = 1;
    bool json = false;
    bool barriers = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold, or .svg in Origami Simulator's colours)")->required();
  cmd->add_option("--rest", a->rest, "rest state: JSON of fold angles ({\"edge\": degrees} or an array) or a FOLD of the same pattern")
      ->required();
  auto* km = cmd->add_option("--k-m", a->k_m, "stiffness of each mountain crease (>= 0, energy / rad^2; default 1)");
  auto* kv = cmd->add_option("--k-v", a->k_v, "stiffness of each valley crease (>= 0; default 1)");
  auto* ku = cmd->add_option("--k-u", a->k_u, "stiffness of each unassigned crease (>= 0; default 1)");
  auto* spec = cmd->add_option("--stiffness", a->stiffness,
                               "per-crease stiffness: JSON {default, mountain, valley, unassigned, edges {\"index\": k}, "
                               "material {youngs_modulus, thickness, flexure_length, length_scale}}; replaces --k-m, --k-v, --k-u");
  cmd->add_option("--starts", a->starts, "random starts besides the rest state (0..1000, default 24)");
  cmd->add_option("--seed", a->seed, "seed of the random starts (default 1)");
  cmd->add_flag("--json", a->json, "print JSON (numbers round-trip exactly)");
  cmd->add_flag("--barriers", a->barriers,
                "the energy barrier both ways between the stable states (minimum-energy path on the closure manifold, "
                "saddle refined and checked); one path search per pair");
  auto* load_opt = cmd->add_option("--load", a->load,
                                   "vertex height control: JSON {vertex, height, supports (default: its valley creases)}; "
                                   "prints the loaded equilibria and their reaction forces");
  cmd->callback([a, km, kv, ku, spec, load_opt] {
    if (spec->count() > 0 && (km->count() > 0 || kv->count() > 0 || ku->count() > 0))
      throw InputError("--stiffness", "replaces --k-m, --k-v and --k-u: give one or the other");
    const CreasePattern p = read_pattern(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    CreaseSpringProblem problem;
    problem.stiffness.mountain = a->k_m;
    problem.stiffness.valley = a->k_v;
    problem.stiffness.unassigned = a->k_u;
    problem.search.random_starts = a->starts;
    problem.search.seed = a->seed;
    problem.rest_place = a->rest;
    problem.barriers = a->barriers;
    CreaseSpringStates found;
    if (spec->count() > 0) problem.edge_stiffness = read_stiffness_spec(a->stiffness, p);  // names the file and the JSON path
    if (load_opt->count() > 0) problem.load = read_load_spec(a->load, p, t);                // the same
    try {
      problem.rest = read_rest_state(a->rest, p, t);
      found = crease_spring_states(p, t, problem);
    } catch (const InputError& e) {
      // The kernel names its parameters; the user typed flags.
      if (e.place() == "starts") throw InputError("--starts", e.message());
      if (e.place().rfind("stiffness.", 0) == 0) {
        const std::string flag = e.place() == "stiffness.mountain" ? "--k-m" : e.place() == "stiffness.valley" ? "--k-v" : "--k-u";
        throw InputError(flag, "must be a finite number >= 0");
      }
      if (e.place() == "pattern") throw InputError(a->pattern, e.message());
      throw;
    }
    const StableStateSearch& s = found.search;
    // The loaded equilibria (found and checked by crease_spring_states).
    nlohmann::ordered_json loaded;
    if (problem.load) {
      const VertexHeightLoad& load = *problem.load;
      loaded["vertex"] = load.vertex;
      // Lengths and forces back in the file's units (the kernel's are normalised by
      // 2^length_exponent; a force is energy per length).
      loaded["height"] = to_file_units(p, load.height);
      loaded["supports"] = load.support_edges;
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const auto& eq : found.loaded) {
        nlohmann::ordered_json e;
        e["energy"] = eq.energy;
        e["force"] = std::ldexp(eq.force, -p.length_exponent);
        std::vector<double> reactions(eq.support_reactions.data(), eq.support_reactions.data() + eq.support_reactions.size());
        for (double& r : reactions) r = std::ldexp(r, -p.length_exponent);
        e["support_reactions"] = reactions;
        e["constraint_residual"] = eq.constraint_residual;
        e["stationarity_residual"] = eq.stationarity_residual;
        e["min_reduced_hessian_eigenvalue"] = std::isfinite(eq.min_eigenvalue) ? nlohmann::ordered_json(eq.min_eigenvalue)
                                                                                 : nlohmann::ordered_json(nullptr);
        e["stable"] = eq.stable;
        nlohmann::ordered_json angles = nlohmann::ordered_json::array();
        for (int ed = 0; ed < p.num_edges(); ++ed)
          angles.push_back(t.edge_is_hinge[ed] ? nlohmann::ordered_json(to_degrees(eq.edge_angles[ed])) : nlohmann::ordered_json(nullptr));
        e["fold_angles_deg"] = angles;
        list.push_back(e);
      }
      loaded["states"] = list;
    }

    nlohmann::ordered_json j;
    j["file"] = a->pattern;
    j["rest"] = a->rest;
    j.update(report::crease_spring_states_json(p, t, problem, found));
    if (!loaded.is_null()) j["loaded"] = loaded;
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    std::cout << a->pattern << ": " << s.states.size() << " stable state(s) from " << s.starts << " starts (the rest state and "
              << a->starts << " random ones; a search, not a proof that there are no others)\n";
    char line[256];
    for (std::size_t i = 0; i < s.states.size(); ++i) {
      const auto& f = s.states[i];
      std::snprintf(line, sizeof line, "  state %zu: energy %.12g, reached from %d start(s)%s; closure %.1e rad, min reduced Hessian eigenvalue %.6g\n",
                    i + 1, f.state.energy, f.reached_from, f.from_rest ? " incl. the rest state" : "", f.state.closure_residual,
                    f.state.min_eigenvalue);
      std::cout << line;
      std::cout << "    " << (f.creases_against_letters.empty() ? std::string("keeps every M/V letter")
                                                                 : std::to_string(f.creases_against_letters.size()) + " crease(s) against their letters")
                << ", " << (f.interfering_faces.empty() ? std::string("no facet interference")
                                                       : std::to_string(f.interfering_faces.size()) + " face pair(s) pass through each other")
                << "\n";
      std::cout << "    fold angles (deg):";
      int shown = 0;
      for (int e = 0; e < p.num_edges() && shown < 16; ++e)
        if (t.edge_is_hinge[e]) {
          std::snprintf(line, sizeof line, " %d:%.9g", e, to_degrees(f.state.edge_angles[e]));
          std::cout << line;
          ++shown;
        }
      std::cout << (shown == 16 ? " ... (use --json)" : "") << "\n";
    }
    for (const StateBarrier& b : found.barriers) {
      const MinimumEnergyPath& m = b.path;
      if (m.found) {
        if (m.top == PathTop::kSaddle)
          std::snprintf(line, sizeof line,
                        "  barrier state %d <-> state %d: %.12g from state %d, %.12g from state %d (index-1 saddle, energy %.12g, "
                        "reduced gradient %.1e, closure %.1e rad)\n",
                        b.first + 1, b.second + 1, m.barrier_from_a, b.first + 1, m.barrier_from_b, b.second + 1, m.saddle.energy,
                        m.saddle.stationarity_residual, m.saddle.closure_residual);
        else
          std::snprintf(line, sizeof line,
                        "  barrier state %d <-> state %d: %.12g from state %d, %.12g from state %d (top at the flat state, a "
                        "singular point where the energy has a cusp: energy %.12g)\n",
                        b.first + 1, b.second + 1, m.barrier_from_a, b.first + 1, m.barrier_from_b, b.second + 1, m.saddle.energy);
        std::cout << line;
        std::cout << "    top fold angles (deg):";
        int shown = 0;
        for (int e = 0; e < p.num_edges() && shown < 16; ++e)
          if (t.edge_is_hinge[e]) {
            std::snprintf(line, sizeof line, " %d:%.9g", e, to_degrees(m.saddle.edge_angles[e]));
            std::cout << line;
            ++shown;
          }
        std::cout << (shown == 16 ? " ... (use --json)" : "") << "\n";
      } else {
        std::cout << "  barrier state " << b.first + 1 << " <-> state " << b.second + 1 << ": not found (" << m.message << ")";
        if (b.saddle_joins[0] >= 0) {
          std::snprintf(line, sizeof line, "; its index-1 saddle (energy %.12g) joins state %d and state %d", m.saddle.energy,
                        b.saddle_joins[0] + 1, b.saddle_joins[1] + 1);
          std::cout << line;
        }
        std::cout << "\n";
      }
    }
    if (!loaded.is_null()) {
      std::snprintf(line, sizeof line, "  loaded: vertex %d held at height %.12g above its %zu supports\n", loaded["vertex"].get<int>(),
                    loaded["height"].get<double>(), loaded["supports"].size());
      std::cout << line;
      for (const auto& e : loaded["states"]) {
        std::snprintf(line, sizeof line, "    energy %.12g, force %.12g (push > 0)%s; constraint residual %.1e\n",
                      e["energy"].get<double>(), e["force"].get<double>(), e["stable"].get<bool>() ? ", stable" : ", unstable",
                      e["constraint_residual"].get<double>());
        std::cout << line;
      }
    }
  });
}

}  // namespace rigidfold::cli
