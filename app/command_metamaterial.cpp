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
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <utility>
#include <nlohmann/json.hpp>
#include <string>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "design/metamaterial/metamaterial_table.hpp"
#include "design/metamaterial/square_twist_cross_check.hpp"
#include "design/metamaterial/stacked_metamaterial_check.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/output_set.hpp"

namespace rigidfold::cli {

void add_metamaterial_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "metamaterial",
      "Metamaterial units of seed 003: dimensions and Poisson's ratios from flat to the fold limit, height maximum, sign changes");
  struct Args {
    std::string unit;
    double alpha_deg = 0, beta_deg = 70, a = 1, b = 1, c = 1, l = 1;
    int samples = 181;
    bool json = false;
    std::string plot;
    bool cross_check = false;
    int cross_check_steps = 40;
    int stacked = 0, layers = 4, stacked_steps = 24;
  };
  auto s = std::make_shared<Args>();
  cmd->add_option("--unit", s->unit,
                  "square-twist (seed 003 3.3.2, T1 tessellation) or element1|element2|element3 (the double-corrugated "
                  "P/Q tessellations' basic elements, 3.2.3, Fig 3-11)")
      ;
  auto* alpha = cmd->add_option("--alpha-deg", s->alpha_deg,
                                "sector alpha, degrees: square twist in (90, 180) (default 150, the seed's 5 pi/6); "
                                "elements in (0, 180) (default 60; the seed's Fig 3-12 values are lost)");
  auto* beta = cmd->add_option("--beta-deg", s->beta_deg, "elements: sector beta, degrees in (0, 180) (default 70; not from the seed)");
  auto* oa = cmd->add_option("--a", s->a, "square twist: side of the central square (> 0, default 1)");
  auto* ob = cmd->add_option("--b", s->b, "square twist: S offset, flat S = 2b + a (cos alpha + sin alpha) (default 1)");
  auto* oc = cmd->add_option("--c", s->c, "square twist: L offset, flat L = 2c + a (cos alpha + sin alpha) (default 1)");
  auto* ol = cmd->add_option("--l", s->l, "elements: crease length l (> 0, default 1)");
  cmd->add_option("--samples", s->samples, "fold angles k 180/(N+1) deg, k = 1..N, N in [3, 100000] (default 181)");
  cmd->add_flag("--json", s->json, "print one JSON object (numbers round-trip exactly)");
  cmd->add_option("--plot", s->plot, "directory to write metamaterial.csv, dimensions.svg and poisson.svg");
  cmd->add_flag("--cross-check", s->cross_check,
                "square twist: trace the 3x3 T1 tessellation with the general solver and compare its unit cell, "
                "Poisson's ratios (implicit differentiation along the path) and height maximum with the closed forms "
                "(<= 1e-9, else exit 3)");
  auto* ccs = cmd->add_option("--cross-check-steps", s->cross_check_steps,
                              "traced steps of the cross-check, 10..2000 (default 40)");
  auto* ost = cmd->add_option("--stacked", s->stacked,
                               "stacked metamaterial 1..4 of Fig 3-10 (layers of double-corrugated sheets, our reconstruction): "
                               "trace its layers with the general solver and compare the stack with the closed forms (instead of --unit)");
  auto* olay = cmd->add_option("--layers", s->layers, "--stacked: layers in the stack, 2..16 (default 4)");
  auto* ostep = cmd->add_option("--stacked-steps", s->stacked_steps, "--stacked: traced steps, 8..200 (default 24)");
  auto* osam = cmd->get_option("--samples");
  auto* oplot = cmd->get_option("--plot");
  auto* occ = cmd->get_option("--cross-check");
  cmd->callback([s, alpha, beta, oa, ob, oc, ol, ccs, ost, olay, ostep, osam, oplot, occ] {
    if (ost->count() > 0) {
      if (!s->unit.empty()) throw InputError("--unit", "give either --unit or --stacked, not both");
      for (auto* o : {oa, ob, oc, osam, oplot, occ, ccs})
        if (o->count() > 0) throw InputError(o->get_name(), "does not apply to --stacked");
      if (s->stacked < 1 || s->stacked > 4) throw InputError("--stacked", "must be 1, 2, 3 or 4, got " + std::to_string(s->stacked));
      if (s->layers < 2 || s->layers > 16) throw InputError("--layers", "must be between 2 and 16, got " + std::to_string(s->layers));
      if (s->stacked_steps < 8 || s->stacked_steps > 200)
        throw InputError("--stacked-steps", "must be between 8 and 200, got " + std::to_string(s->stacked_steps));
      const double alpha_deg = alpha->count() > 0 ? s->alpha_deg : 60.0;
      for (const auto& [flag, v] : {std::pair<const char*, double>{"--alpha-deg", alpha_deg}, {"--beta-deg", s->beta_deg}})
        if (!(std::isfinite(v) && v > 0 && v < 180)) throw InputError(flag, "must lie strictly between 0 and 180 degrees");
      if (!(std::isfinite(s->l) && s->l > 0)) throw InputError("--l", "must be a finite number > 0");
      generators::StackedMetamaterialParams gp;
      gp.metamaterial = s->stacked;
      gp.alpha = to_radians(alpha_deg);
      gp.beta = to_radians(s->beta_deg);
      gp.l = s->l;
      if (s->stacked == 4 && std::fabs(std::cos((gp.alpha + gp.beta) / 2)) <= 1e-6)
        throw InputError("--beta-deg", "metamaterial 4 needs alpha + beta != 180 degrees (element 3 is locked there)");
      metamaterial::StackedMetamaterialOptions so;
      so.layers = s->layers;
      so.steps = s->stacked_steps;
      // Checked inside: NoAnswerError (exit 3) before anything is printed.
      const metamaterial::StackedMetamaterialCheck c = metamaterial::stacked_metamaterial_check(gp, so);
      nlohmann::ordered_json j;
      j["stacked_metamaterial"] = s->stacked;
      j["parameters"] = {{"alpha_deg", alpha_deg}, {"beta_deg", s->beta_deg}, {"l", s->l}, {"layers", s->layers}, {"steps", s->stacked_steps}};
      j["input"] = "phi_deg: dihedral of the seed's A2B2 (180 = flat); theta_deg: metamaterial 4's B4B5 (else = phi)";
      j["creases_per_layer"] = c.creases;
      j["bonding_vertices_per_bond"] = c.bonding_vertices;
      j["tolerances"] = {{"closed_form", metamaterial::kStackTolerance}, {"bond", metamaterial::kStackBond},
                         {"closure_residual", metamaterial::kStackResidual}};
      j["max_closure_residual"] = c.max_residual;
      j["max_bond_gap"] = c.max_bond_gap;
      j["max_dimension_difference"] = c.max_dimension_difference;
      j["max_ratio_difference"] = c.max_ratio_difference;
      if (s->stacked == 4) {
        j["phi_theta_relation"] = {{"inverse_3_26_max_difference_rad", c.max_relation_difference},
                                   {"printed_3_26_max_difference_rad", c.printed_relation_difference}};
      }
      if (c.has_maximum)
        j["height_maximum"] = {{"phi_II_deg", to_degrees(c.phi_II)}, {"theta_II_deg", to_degrees(c.theta_II)},
                               {"height", c.height_max}, {"negative_3d_before", c.negative_3d_before},
                               {"in_negative_out_positive_after", c.in_negative_out_positive_after}};
      else
        j["height_maximum"] = nullptr;
      nlohmann::ordered_json rows = nlohmann::ordered_json::array();
      for (const auto& r : c.states)
        rows.push_back({{"phi_deg", to_degrees(r.phi)}, {"theta_deg", to_degrees(r.theta)},
                        {"W", r.W}, {"L", r.L}, {"H", r.H},
                        {"W_closed", r.W_closed}, {"L_closed", r.L_closed}, {"H_closed", r.H_closed},
                        {"W_difference", r.W - r.W_closed}, {"L_difference", r.L - r.L_closed}, {"H_difference", r.H - r.H_closed},
                        {"nu_in", r.nu_in}, {"nu_out", r.nu_out}, {"nu_in_closed", r.nu_in_closed}, {"nu_out_closed", r.nu_out_closed},
                        {"bond_gap", r.bond_gap}});
      j["states"] = rows;
      j["seconds"] = c.seconds;
      if (s->json) {
        std::cout << document_text(j) << "\n";
        return;
      }
      char line[320];
      std::snprintf(line, sizeof line, "stacked metamaterial %d, alpha %g deg, beta %g deg, l %g, %d layers, %d traced steps\n",
                    s->stacked, alpha_deg, s->beta_deg, s->l, s->layers, s->stacked_steps);
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
      return;
    }
    if (s->unit.empty()) throw InputError("--unit", "is required (or --stacked 1..4)");
    for (auto* o : {olay, ostep})
      if (o->count() > 0) throw InputError(o->get_name(), "applies only with --stacked");
    using metamaterial::MetamaterialUnit;
    metamaterial::MetamaterialParams p;
    if (s->unit == "square-twist") p.unit = MetamaterialUnit::kSquareTwist;
    else if (s->unit == "element1") p.unit = MetamaterialUnit::kElement1;
    else if (s->unit == "element2") p.unit = MetamaterialUnit::kElement2;
    else if (s->unit == "element3") p.unit = MetamaterialUnit::kElement3;
    else if (s->unit == "P" || s->unit == "Q")
      throw InputError("--unit", s->unit + ": the seed gives dimension closed forms for the elements of the P/Q "
                                          "tessellations, not for a unit alone: use element1, element2 or element3");
    else throw InputError("--unit", "'" + s->unit + "' is not square-twist, element1, element2 or element3");
    const bool twist = p.unit == MetamaterialUnit::kSquareTwist;
    auto finite = [](const char* flag, double v) {
      if (!std::isfinite(v)) throw InputError(flag, "must be a finite number");
    };
    if (twist) {
      for (auto* o : {beta, ol})
        if (o->count() > 0) throw InputError(o->get_name(), "applies to the elements, not to --unit square-twist");
      const double alpha_deg = alpha->count() > 0 ? s->alpha_deg : 150.0;
      finite("--alpha-deg", alpha_deg);
      if (!(alpha_deg > 90 && alpha_deg < 180))
        throw InputError("--alpha-deg", std::to_string(alpha_deg) + " is outside (90, 180) degrees");
      finite("--a", s->a);
      finite("--b", s->b);
      finite("--c", s->c);
      if (!(s->a > 0)) throw InputError("--a", "must be > 0");
      p.square_twist.alpha = to_radians(alpha_deg);
      p.square_twist.a = s->a;
      p.square_twist.b = s->b;
      p.square_twist.c = s->c;
      // Lengths over the whole motion (theta, phi -> pi): 2c, 2b > a (sin alpha - cos alpha).
      const double need = s->a * (std::sin(p.square_twist.alpha) - std::cos(p.square_twist.alpha));
      if (!(2 * s->b > need)) throw InputError("--b", "must exceed a (sin alpha - cos alpha) / 2 = " + std::to_string(need / 2) + " so that S > 0 over the motion");
      if (!(2 * s->c > need)) throw InputError("--c", "must exceed a (sin alpha - cos alpha) / 2 = " + std::to_string(need / 2) + " so that L > 0 over the motion");
      if (ccs->count() > 0 && !s->cross_check) throw InputError("--cross-check-steps", "applies only with --cross-check");
      if (s->cross_check) {
        const double least = metamaterial::square_twist_cross_check_min_offset(p.square_twist.alpha, s->a);
        for (const auto& [flag, v] : {std::pair<const char*, double>{"--b", s->b}, {"--c", s->c}})
          if (!(v > least * (1 + 1e-9)))
            throw InputError(flag, std::string("--cross-check traces a tessellation whose pleat creases between twists "
                                               "need it > -a cos(alpha) = ") + std::to_string(least));
        if (s->cross_check_steps < 10 || s->cross_check_steps > 2000)
          throw InputError("--cross-check-steps", "must be between 10 and 2000, got " + std::to_string(s->cross_check_steps));
      }
    } else {
      if (s->cross_check) throw InputError("--cross-check", "applies to --unit square-twist (the elements have no traced tessellation here)");
      if (ccs->count() > 0) throw InputError("--cross-check-steps", "applies to --unit square-twist with --cross-check");
      for (auto* o : {oa, ob, oc})
        if (o->count() > 0) throw InputError(o->get_name(), "applies to --unit square-twist, not to the elements");
      const double alpha_deg = alpha->count() > 0 ? s->alpha_deg : 60.0;
      finite("--alpha-deg", alpha_deg);
      finite("--beta-deg", s->beta_deg);
      finite("--l", s->l);
      if (!(alpha_deg > 0 && alpha_deg < 180)) throw InputError("--alpha-deg", std::to_string(alpha_deg) + " is outside (0, 180) degrees");
      if (!(s->beta_deg > 0 && s->beta_deg < 180)) throw InputError("--beta-deg", std::to_string(s->beta_deg) + " is outside (0, 180) degrees");
      if (!(s->l > 0)) throw InputError("--l", "must be > 0");
      p.element.alpha = to_radians(alpha_deg);
      p.element.beta = to_radians(s->beta_deg);
      p.element.l = s->l;
      if (p.unit == MetamaterialUnit::kElement3 && std::fabs(std::cos((p.element.beta + p.element.alpha) / 2)) < 1e-12)
        throw InputError("--beta-deg", "element3 with alpha + beta = 180 degrees is locked ((3-26) pins theta at 0)");
    }
    if (s->samples < 3 || s->samples > 100000)
      throw InputError("--samples", "must be between 3 and 100000, got " + std::to_string(s->samples));
    p.samples = s->samples;

    OutputSet outputs;
    std::string csv_path, dims_path, ratios_path;
    if (!s->plot.empty()) {
      outputs.add_output_directory("--plot", s->plot);
      const std::string dir = s->plot.back() == '/' ? s->plot : s->plot + "/";
      csv_path = dir + "metamaterial.csv";
      dims_path = dir + "dimensions.svg";
      ratios_path = dir + "poisson.svg";
      for (const auto* path : {&csv_path, &dims_path, &ratios_path}) outputs.add_output("--plot", *path);
    }
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    // Every row below passed its checks in metamaterial_table (NoAnswerError -> exit 3).
    const metamaterial::MetamaterialTable t = metamaterial::metamaterial_table(p);
    // Checked inside (every difference <= 1e-9, else NoAnswerError -> exit 3, nothing written).
    std::optional<metamaterial::SquareTwistCrossCheck> cc;
    if (s->cross_check) {
      metamaterial::SquareTwistCrossCheckOptions o;
      o.steps = s->cross_check_steps;
      cc = metamaterial::square_twist_cross_check(p.square_twist, o);
    }
    if (!s->plot.empty()) {
      outputs.stage(csv_path, metamaterial::metamaterial_csv(t));
      outputs.stage(dims_path, metamaterial::metamaterial_dimensions_svg(t));
      outputs.stage(ratios_path, metamaterial::metamaterial_ratios_svg(t));
    }
    outputs.commit();

    const auto dn = metamaterial::dimension_names(p.unit);
    const auto rn = metamaterial::ratio_names(p.unit);
    nlohmann::ordered_json j;
    j["unit"] = metamaterial::unit_name(p.unit);
    if (twist) {
      j["parameters"] = {{"alpha_deg", to_degrees(p.square_twist.alpha)}, {"a", p.square_twist.a}, {"b", p.square_twist.b}, {"c", p.square_twist.c}};
      j["fold_angle"] = "theta_deg: fold magnitude of the S-direction pleats; second_angle_deg: phi of the L-direction pleats by (3-31)";
    } else {
      j["parameters"] = {{"alpha_deg", to_degrees(p.element.alpha)}, {"beta_deg", to_degrees(p.element.beta)}, {"l", p.element.l}};
      j["fold_angle"] = p.unit == MetamaterialUnit::kElement3
                            ? "rho_deg = 180 - phi of A2B2; second_angle_deg: dihedral theta of B4B5 by (3-26)"
                            : "rho_deg = 180 - phi of A2B2; second_angle_deg: the dihedral phi of A2B2";
    }
    j["samples"] = p.samples;
    j["dimensions"] = dn;
    j["ratios"] = rn;
    if (t.has_height_maximum)
      j["height_maximum"] = {{"fold_deg", to_degrees(t.height_maximum_fold)}, {"height", t.height_maximum}};
    else
      j["height_maximum"] = nullptr;
    j["height_stationary_points"] = t.height_stationary_points;
    nlohmann::ordered_json changes = nlohmann::ordered_json::array();
    for (const auto& c : t.sign_changes)
      changes.push_back({{"ratio", c.ratio == "nu_in" ? rn[0] : rn[1]},
                         {"kind", c.kind},
                         {"fold_deg", to_degrees(c.fold)},
                         {"negative_after", c.negative_after}});
    j["sign_changes"] = changes;
    j["ratios_defined"] = {{rn[0], t.nu_in_defined}, {rn[1], t.nu_out_defined}};
    j["checks"] = {{"max_constraint_residual", t.max_constraint_residual},
                   {"max_derivative_error", t.max_derivative_error},
                   {"constraint_tolerance", metamaterial::kConstraintTolerance},
                   {"derivative_tolerance", metamaterial::kDerivativeTolerance}};
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& r : t.rows) {
      nlohmann::ordered_json o;
      o["fold_deg"] = to_degrees(r.fold);
      o["second_angle_deg"] = to_degrees(r.second_angle);
      o[dn[0]] = r.x;
      o[dn[1]] = r.y;
      o[dn[2]] = r.H;
      o["d" + dn[0] + "_per_rad"] = r.dx;
      o["d" + dn[1] + "_per_rad"] = r.dy;
      o["d" + dn[2] + "_per_rad"] = r.dH;
      o[rn[0]] = r.nu_in;
      o[rn[1]] = r.nu_out;
      o["constraint_residual"] = r.constraint_residual;
      o["derivative_error"] = r.derivative_error;
      rows.push_back(o);
    }
    j["rows"] = rows;
    if (cc) {
      nlohmann::ordered_json st = nlohmann::ordered_json::array();
      for (const auto& q : cc->stationary)
        st.push_back({{"kind", q.maximum ? "maximum" : "minimum"},
                      {"theta_deg_traced", to_degrees(q.theta_traced)},
                      {"theta_deg_closed", to_degrees(q.theta_closed)},
                      {"height_traced", q.height_traced},
                      {"height_closed", q.height_closed},
                      {"nu_HL_traced", q.nu_HL_at},
                      {"nu_HL_before", q.nu_HL_before},
                      {"nu_HL_after", q.nu_HL_after}});
      j["cross_check"] = {
          {"sheet", "3x3 square-twist tessellation, layout type3-rows (T1), traced by the general loop-closure solver"},
          {"twists_per_side", cc->twists_per_side},
          {"creases", cc->creases},
          {"traced_steps", cc->traced_steps},
          {"compared_steps", cc->compared_steps},
          {"theta_deg_range", {cc->theta_range_deg[0], cc->theta_range_deg[1]}},
          {"tolerance", metamaterial::kCrossCheckTolerance},
          {"max_closure_residual", cc->max_residual},
          {"max_null_singular_value", cc->max_null_singular},
          {"min_next_singular_value", cc->min_next_singular},
          {"max_geometry_defect", cc->max_geometry_defect},
          {"max_phi_difference_rad", cc->max_phi_difference},
          {"max_dimension_difference", cc->max_dimension_difference},
          {"max_derivative_difference", cc->max_derivative_difference},
          {"max_ratio_difference", cc->max_ratio_difference},
          {"nu_SL_negative", cc->nu_SL_negative},
          {"stationary_points", st},
          {"max_stationary_theta_difference_rad", cc->max_stationary_theta_difference},
          {"max_stationary_height_difference", cc->max_stationary_height_difference},
          {"height_maximum", {{"theta_deg_traced", to_degrees(cc->height_maximum_theta_traced)},
                              {"theta_deg_closed", to_degrees(cc->height_maximum_theta_closed)},
                              {"height_traced", cc->height_maximum_traced},
                              {"height_closed", cc->height_maximum_closed}}},
          {"seconds", cc->seconds}};
    }
    if (s->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    char line[320];
    std::cout << "metamaterial " << j["unit"].get<std::string>() << " " << j["parameters"].dump() << ", " << p.samples
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
    if (cc) {
      std::snprintf(line, sizeof line,
                    "  cross-check (3x3 T1 tessellation, general solver, %d steps, theta %.4g..%.4g deg): residual <= %.1e, "
                    "geometry defect <= %.1e\n",
                    cc->traced_steps, cc->theta_range_deg[0], cc->theta_range_deg[1], cc->max_residual, cc->max_geometry_defect);
      std::cout << line;
      std::snprintf(line, sizeof line,
                    "    closed form vs traced: phi %.1e rad, L S H %.1e, d/dtheta %.1e (rel), nu_SL nu_HL %.1e (rel); tolerance %.0e\n",
                    cc->max_phi_difference, cc->max_dimension_difference, cc->max_derivative_difference,
                    cc->max_ratio_difference, metamaterial::kCrossCheckTolerance);
      std::cout << line;
      for (const auto& q : cc->stationary) {
        std::snprintf(line, sizeof line,
                      "    H %s at theta %.12g deg traced (closed %.12g), H %.12g (closed %.12g); nu_HL %.3g -> %.3g\n",
                      q.maximum ? "maximum" : "minimum", to_degrees(q.theta_traced), to_degrees(q.theta_closed),
                      q.height_traced, q.height_closed, q.nu_HL_before, q.nu_HL_after);
        std::cout << line;
      }
      std::snprintf(line, sizeof line, "    %.2f s\n", cc->seconds);
      std::cout << line;
    }
    if (!s->plot.empty()) std::cout << "  wrote " << csv_path << ", " << dims_path << ", " << ratios_path << "\n";
  });
}

}  // namespace rigidfold::cli
