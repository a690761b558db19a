// rigidfold energy PATTERN --rest REST.json|REST.fold [--k-m K] [--k-v K] [--k-u K]
//                  [--starts N] [--seed S] [--json]
// Each state also says whether it keeps the M/V letters and whether panels pass through each
// other there (the springs know neither).
// Stable states of any crease pattern with torsional springs at its creases
// (kernel/energy/stable_state_search.hpp): the rest state and N random starts that respect
// the letters, each minimised on the loop-closure manifold with no symmetry imposed; every
// state printed has passed its checks (closure <= 1e-12 rad, stationarity, reduced Hessian
// positive definite).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/number_flags.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/stable_state_search.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/fold_angles_input.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {
namespace {

constexpr int kMaxFreeCreases = 400;          // dense tangent-space steps (constrained_equilibrium.hpp)
constexpr double kRestClosureTolerance = 1e-6;  // radians: a rest state read from decimals closes to ~1e-12

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Rest angles per edge from a JSON of fold angles or from a FOLD file of the same pattern
// (its edges_foldAngle, else its 3D coordinates).
Eigen::VectorXd read_rest(const std::string& path, const CreasePattern& p, const Topology& t) {
  if (ends_with(path, ".json")) return read_fold_angles_json(path, p, t);
  if (!ends_with(path, ".fold")) throw InputError("--rest", "must be a .json of fold angles or a .fold of the same pattern: " + path);
  const CreasePattern r = read_pattern(path);
  if (r.num_vertices() != p.num_vertices() || r.num_edges() != p.num_edges())
    throw InputError(path, "has " + std::to_string(r.num_vertices()) + " vertices and " + std::to_string(r.num_edges()) +
                               " edges; the pattern has " + std::to_string(p.num_vertices()) + " and " +
                               std::to_string(p.num_edges()));
  for (int e = 0; e < p.num_edges(); ++e)
    if (r.edges[e] != p.edges[e]) throw InputError(path + ": edges_vertices[" + std::to_string(e) + "]", "differs from the pattern's");
  if (r.fold_angles_in_file) return stored_fold_angles(r);
  if (!r.coords_2d) return reference_fold_angles(r, build_topology(r, path));
  throw InputError(path, "has neither edges_foldAngle nor 3D coordinates: no rest state in it");
}

}  // namespace

void add_energy_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("energy", "Stable states of a pattern with crease springs (multistart, no symmetry imposed)");
  struct Args {
    std::string pattern, rest;
    double k_m = 1, k_v = 1, k_u = 1;
    int starts = 24;
    std::uint64_t seed = 1;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold, or .svg in Origami Simulator's colours)")->required();
  cmd->add_option("--rest", a->rest, "rest state: JSON of fold angles ({\"edge\": degrees} or an array) or a FOLD of the same pattern")
      ->required();
  cmd->add_option("--k-m", a->k_m, "stiffness of each mountain crease (>= 0, energy / rad^2; default 1)");
  cmd->add_option("--k-v", a->k_v, "stiffness of each valley crease (>= 0; default 1)");
  cmd->add_option("--k-u", a->k_u, "stiffness of each unassigned crease (>= 0; default 1)");
  cmd->add_option("--starts", a->starts, "random starts besides the rest state (0..1000, default 24)");
  cmd->add_option("--seed", a->seed, "seed of the random starts (default 1)");
  cmd->add_flag("--json", a->json, "print JSON (numbers round-trip exactly)");
  cmd->callback([a] {
    if (a->starts < 0 || a->starts > 1000) throw InputError("--starts", "must be between 0 and 1000");
    const CreasePattern p = read_pattern(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    const ClosureSystem sys(p, t);
    if (sys.num_unknowns() > kMaxFreeCreases)
      throw InputError(a->pattern, std::to_string(sys.num_unknowns()) + " free creases; the energy search takes at most " +
                                       std::to_string(kMaxFreeCreases));
    StiffnessByAssignment k;
    k.mountain = a->k_m;
    k.valley = a->k_v;
    k.unassigned = a->k_u;
    Eigen::VectorXd stiffness;
    try {
      stiffness = stiffness_by_assignment(p, k);
    } catch (const InputError& e) {
      const std::string flag = e.place() == "stiffness.mountain" ? "--k-m" : e.place() == "stiffness.valley" ? "--k-v" : "--k-u";
      throw InputError(flag, "must be a finite number >= 0");
    }
    const Eigen::VectorXd rest = read_rest(a->rest, p, t);
    const CreaseSprings springs = make_crease_springs(p, stiffness, rest);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys.evaluate(sys.unknowns_from_edges(rest), r, J);
    const double rest_residual = r.size() ? r.lpNorm<Eigen::Infinity>() : 0.0;
    if (!(rest_residual <= kRestClosureTolerance)) {
      Eigen::Index row = 0;
      r.cwiseAbs().maxCoeff(&row);
      throw InputError(a->rest, "the rest state does not close: loop-closure residual " + std::to_string(rest_residual) +
                                    " rad (row " + std::to_string(row) + ", allowed " + std::to_string(kRestClosureTolerance) + ")");
    }
    StableStateSearchOptions o;
    o.random_starts = a->starts;
    o.seed = a->seed;
    const StableStateSearch s = search_stable_states(p, t, sys, springs, rest, o);
    if (s.states.empty())
      throw NoAnswerError("no stable state reached from " + std::to_string(s.starts) + " starts (" +
                          std::to_string(s.starts_converged) + " minimisations converged)");

    nlohmann::ordered_json j;
    j["file"] = a->pattern;
    j["rest"] = a->rest;
    j["rest_closure_residual_rad"] = rest_residual;
    j["stiffness"] = {{"mountain", a->k_m}, {"valley", a->k_v}, {"unassigned", a->k_u}};
    j["starts"] = s.starts;
    j["starts_on_manifold"] = s.starts_on_manifold;
    j["starts_converged"] = s.starts_converged;
    nlohmann::ordered_json states = nlohmann::ordered_json::array();
    for (const auto& f : s.states) {
      nlohmann::ordered_json sj;
      sj["energy"] = f.state.energy;
      sj["reached_from_starts"] = f.reached_from;
      sj["from_rest"] = f.from_rest;
      sj["keeps_letters"] = f.creases_against_letters.empty();
      sj["creases_against_letters"] = f.creases_against_letters;
      sj["facet_interference"] = !f.interfering_faces.empty();
      nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
      for (const auto& [a, b] : f.interfering_faces) pairs.push_back({a, b});
      sj["interfering_face_pairs"] = pairs;
      sj["closure_residual_rad"] = f.state.closure_residual;
      sj["stationarity_residual"] = f.state.stationarity_residual;
      sj["tangent_dimension"] = f.state.tangent_dimension;
      sj["min_reduced_hessian_eigenvalue"] = std::isfinite(f.state.min_eigenvalue) ? nlohmann::ordered_json(f.state.min_eigenvalue)
                                                                                   : nlohmann::ordered_json(nullptr);
      nlohmann::ordered_json angles = nlohmann::ordered_json::array();
      for (int e = 0; e < p.num_edges(); ++e)
        angles.push_back(t.edge_is_hinge[e] ? nlohmann::ordered_json(to_degrees(f.state.edge_angles[e])) : nlohmann::ordered_json(nullptr));
      sj["fold_angles_deg"] = angles;
      states.push_back(sj);
    }
    j["stable_states"] = states;
    if (a->json) {
      std::cout << j.dump(2) << "\n";
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
  });
}

}  // namespace rigidfold::cli
