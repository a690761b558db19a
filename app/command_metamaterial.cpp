// rigidfold metamaterial --unit square-twist|element1|element2|element3 [unit parameters]
//                        [--samples N] [--json] [--plot DIR] [--cross-check [--cross-check-steps N]]
// rigidfold metamaterial --stacked 1|2|3|4 [--alpha-deg A] [--beta-deg B] [--l L] [--layers N]
//                        [--stacked-steps N] [--json]
// Seed 003's metamaterial units along their motion from flat to the fold limit
// (design/metamaterial/metamaterial_table.hpp): dimensions, Poisson's ratios, the height
// maximum and the ratios' sign changes; every sampled row checked before anything is printed.
// --plot DIR writes metamaterial.csv, dimensions.svg and poisson.svg through one OutputSet.
// --cross-check (square twist): the closed forms against the traced tessellation
// (design/metamaterial/square_twist_cross_check.hpp); its largest differences are reported,
// and a difference above 1e-9 is "no answer" (exit 3, nothing written or printed).
// --stacked M: metamaterial M of Fig 3-10 as geometry (design/metamaterial/stacked_metamaterial_check.hpp):
// both layers traced by the general solver, the stack placed by its bonding vertices; the
// measured W, L, H and Poisson's ratios against the closed forms (any difference > 1e-9 or a
// bond gap > 1e-10: exit 3 before anything is printed).
// The request is checked and run by design/metamaterial/metamaterial_request.hpp (shared with
// Python's rigidfold.metamaterial); its JSON is report/metamaterial_json.hpp's.
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "design/metamaterial/metamaterial_request.hpp"
#include "kernel/math/angle_units.hpp"
#include "report/metamaterial_json.hpp"

namespace rigidfold::cli {
namespace {

struct MetamaterialFlags {
  std::string unit;
  double alpha_deg = 0, beta_deg = 70, a = 1, b = 1, c = 1, l = 1;
  int samples = 181;
  bool json = false;
  std::string plot;
  bool cross_check = false;
  int cross_check_steps = 40;
  int stacked = 0, layers = 4, stacked_steps = 24;
};

// The request as typed: a flag not on the command line stays empty, so that the front door
// applies its default and can tell a flag that does not apply from one left alone.
metamaterial::MetamaterialRequest metamaterial_request_from_flags(const CLI::App& cmd, const MetamaterialFlags& f) {
  auto if_given = [&cmd]<class T>(const char* flag, const T& value) {
    return cmd.get_option(flag)->count() > 0 ? std::optional<T>(value) : std::nullopt;
  };
  metamaterial::MetamaterialRequest r;
  r.unit = f.unit;
  r.stacked = if_given("--stacked", f.stacked);
  r.alpha_deg = if_given("--alpha-deg", f.alpha_deg);
  r.beta_deg = if_given("--beta-deg", f.beta_deg);
  r.a = if_given("--a", f.a);
  r.b = if_given("--b", f.b);
  r.c = if_given("--c", f.c);
  r.l = if_given("--l", f.l);
  r.samples = if_given("--samples", f.samples);
  r.plot = if_given("--plot", f.plot);
  r.cross_check = if_given("--cross-check", f.cross_check);
  r.cross_check_steps = if_given("--cross-check-steps", f.cross_check_steps);
  r.layers = if_given("--layers", f.layers);
  r.stacked_steps = if_given("--stacked-steps", f.stacked_steps);
  r.naming = metamaterial::FieldNaming::kCommandLineFlags;
  return r;
}

void print_stacked_metamaterial_text(const metamaterial::StackedMetamaterialRun& run) {
  const metamaterial::StackedMetamaterialCheck& c = run.check;
  char line[320];
  std::snprintf(line, sizeof line, "stacked metamaterial %d, alpha %g deg, beta %g deg, l %g, %d layers, %d traced steps\n",
                c.params.metamaterial, run.alpha_deg, run.beta_deg, c.params.l, c.options.layers, c.options.steps);
  std::cout << line;
  std::snprintf(line, sizeof line,
                "  residual <= %.1e, bond gap <= %.1e, W L H vs closed forms <= %.1e, nu_in nu_out <= %.1e (rel)\n",
                c.max_residual, c.max_bond_gap, c.max_dimension_difference, c.max_ratio_difference);
  std::cout << line;
  if (c.has_maximum) {
    std::snprintf(line, sizeof line, "  height maximum %.12g at phi_II %.12g deg\n", c.height_max, to_degrees(c.phi_II));
    std::cout << line;
  } else {
    std::cout << "  no height maximum on the traced path\n";
  }
}

void print_metamaterial_cross_check_text(const metamaterial::SquareTwistCrossCheck& cc) {
  char line[320];
  std::snprintf(line, sizeof line,
                "  cross-check (3x3 T1 tessellation, general solver, %d steps, theta %.4g..%.4g deg): residual <= %.1e, "
                "geometry defect <= %.1e\n",
                cc.traced_steps, cc.theta_range_deg[0], cc.theta_range_deg[1], cc.max_residual, cc.max_geometry_defect);
  std::cout << line;
  std::snprintf(line, sizeof line,
                "    closed form vs traced: phi %.1e rad, L S H %.1e, d/dtheta %.1e (rel), nu_SL nu_HL %.1e (rel); tolerance %.0e\n",
                cc.max_phi_difference, cc.max_dimension_difference, cc.max_derivative_difference,
                cc.max_ratio_difference, metamaterial::kCrossCheckTolerance);
  std::cout << line;
  for (const auto& q : cc.stationary) {
    std::snprintf(line, sizeof line,
                  "    H %s at theta %.12g deg traced (closed %.12g), H %.12g (closed %.12g); nu_HL %.3g -> %.3g\n",
                  q.maximum ? "maximum" : "minimum", to_degrees(q.theta_traced), to_degrees(q.theta_closed),
                  q.height_traced, q.height_closed, q.nu_HL_before, q.nu_HL_after);
    std::cout << line;
  }
  std::snprintf(line, sizeof line, "    %.2f s\n", cc.seconds);
  std::cout << line;
}

// j: the run's JSON (report::metamaterial_unit_json), whose unit, parameters and fold_angle
// the first lines repeat.
void print_metamaterial_unit_text(const metamaterial::MetamaterialUnitRun& run, const nlohmann::ordered_json& j) {
  const metamaterial::MetamaterialTable& t = run.table;
  const auto dn = metamaterial::dimension_names(run.params.unit);
  const auto rn = metamaterial::ratio_names(run.params.unit);
  char line[320];
  std::cout << "metamaterial " << j["unit"].get<std::string>() << " " << j["parameters"].dump() << ", " << run.params.samples
            << " samples\n";
  std::cout << "  fold angle: " << j["fold_angle"].get<std::string>() << "\n";
  const auto& first = t.rows.front();
  const auto& last = t.rows.back();
  std::snprintf(line, sizeof line, "  %s, %s, %s: (%.9g, %.9g, %.9g) at %.6g deg -> (%.9g, %.9g, %.9g) at %.6g deg\n",
                dn[0].c_str(), dn[1].c_str(), dn[2].c_str(), first.x, first.y, first.H, to_degrees(first.fold), last.x,
                last.y, last.H, to_degrees(last.fold));
  std::cout << line;
  if (t.has_height_maximum) {
    std::snprintf(line, sizeof line, "  height maximum %.12g at fold %.12g deg (%d stationary point%s of H)\n",
                  t.height_maximum, to_degrees(t.height_maximum_fold), t.height_stationary_points,
                  t.height_stationary_points == 1 ? "" : "s");
    std::cout << line;
  } else {
    std::cout << "  no interior height maximum\n";
  }
  if (!t.nu_in_defined) std::cout << "  " << rn[0] << " undefined: a dimension it is built on stays 0\n";
  if (!t.nu_out_defined) std::cout << "  " << rn[1] << " undefined: a dimension it is built on stays 0\n";
  for (const auto& c : t.sign_changes) {
    std::snprintf(line, sizeof line, "  %s changes sign at fold %.12g deg (%s), %s after\n",
                  (c.ratio == "nu_in" ? rn[0] : rn[1]).c_str(), to_degrees(c.fold), c.kind.c_str(),
                  c.negative_after ? "negative" : "positive");
    std::cout << line;
  }
  std::snprintf(line, sizeof line, "  checks: constraint residual <= %.1e, derivative vs finite difference <= %.1e (relative)\n",
                t.max_constraint_residual, t.max_derivative_error);
  std::cout << line;
  if (run.cross_check) print_metamaterial_cross_check_text(*run.cross_check);
  if (!run.plot_files.empty())
    std::cout << "  wrote " << run.plot_files[0] << ", " << run.plot_files[1] << ", " << run.plot_files[2] << "\n";
}

}  // namespace

void add_metamaterial_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "metamaterial",
      "Metamaterial units of seed 003: dimensions and Poisson's ratios from flat to the fold limit, height maximum, sign changes");
  auto s = std::make_shared<MetamaterialFlags>();
  cmd->add_option("--unit", s->unit,
                  "square-twist (seed 003 3.3.2, T1 tessellation) or element1|element2|element3 (the double-corrugated "
                  "P/Q tessellations' basic elements, 3.2.3, Fig 3-11)");
  cmd->add_option("--alpha-deg", s->alpha_deg,
                  "sector alpha, degrees: square twist in (90, 180) (default 150, the seed's 5 pi/6); "
                  "elements in (0, 180) (default 60; the seed's Fig 3-12 values are lost)");
  cmd->add_option("--beta-deg", s->beta_deg, "elements: sector beta, degrees in (0, 180) (default 70; not from the seed)");
  cmd->add_option("--a", s->a, "square twist: side of the central square (> 0, default 1)");
  cmd->add_option("--b", s->b, "square twist: S offset, flat S = 2b + a (cos alpha + sin alpha) (default 1)");
  cmd->add_option("--c", s->c, "square twist: L offset, flat L = 2c + a (cos alpha + sin alpha) (default 1)");
  cmd->add_option("--l", s->l, "elements: crease length l (> 0, default 1)");
  cmd->add_option("--samples", s->samples, "fold angles k 180/(N+1) deg, k = 1..N, N in [3, 100000] (default 181)");
  cmd->add_flag("--json", s->json, "print one JSON object (numbers round-trip exactly)");
  cmd->add_option("--plot", s->plot, "directory to write metamaterial.csv, dimensions.svg and poisson.svg");
  cmd->add_flag("--cross-check", s->cross_check,
                "square twist: trace the 3x3 T1 tessellation with the general solver and compare its unit cell, "
                "Poisson's ratios (implicit differentiation along the path) and height maximum with the closed forms "
                "(<= 1e-9, else exit 3)");
  cmd->add_option("--cross-check-steps", s->cross_check_steps,
                  "traced steps of the cross-check, 10..2000 (default 40)");
  cmd->add_option("--stacked", s->stacked,
                  "stacked metamaterial 1..4 of Fig 3-10 (layers of double-corrugated sheets, our reconstruction): "
                  "trace its layers with the general solver and compare the stack with the closed forms (instead of --unit)");
  cmd->add_option("--layers", s->layers, "--stacked: layers in the stack, 2..16 (default 4)");
  cmd->add_option("--stacked-steps", s->stacked_steps, "--stacked: traced steps, 8..200 (default 24)");
  cmd->callback([cmd, s] {
    // Checked as a whole before any work (InputError naming the flag), then every sample, the
    // cross-check or the stack checked (NoAnswerError: exit 3, nothing written or printed).
    const metamaterial::MetamaterialRun run = metamaterial::run_metamaterial(metamaterial_request_from_flags(*cmd, *s));
    const nlohmann::ordered_json j = report::metamaterial_json(run);
    if (s->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    if (run.stacked)
      print_stacked_metamaterial_text(*run.stacked);
    else
      print_metamaterial_unit_text(*run.unit, j);
  });
}

}  // namespace rigidfold::cli
