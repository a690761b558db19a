// rigidfold waterbomb --n N --theta0-deg T [--k-ratio R | --k-m K --k-v K] [--json]
//                    [--curve FILE.csv [--samples K]] [--target-switching-force F]
// Bistability of the symmetric waterbomb base (seed 004): every equilibrium of the spring
// energy along the 1-DOF symmetric path, each checked (loop closure, dV/dtheta = 0, and
// stationarity and stability on the unrestricted 2n-crease problem) before it is printed.
// --curve writes the energy and force-deflection curves (design/waterbomb/waterbomb_curve.hpp):
// every sample checked against the general model, or nothing is written (exit 3).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_curve.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/output_set.hpp"

namespace rigidfold::cli {
namespace {

// JSON number or null (NaN has no JSON form: the flat cusp has no reduced Hessian).
nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

void add_waterbomb_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("waterbomb", "Waterbomb base bistability (seed 004): stable states and the flat barrier");
  struct Args {
    int n = 0;
    double theta0_deg = 0, k_ratio = 1, k_m = 1, k_v = 1;
    bool json = false;
    std::string curve;
    int samples = 181;
    double target_switching_force = 0;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("--n", a->n, "mountain (= valley) creases, 3 <= n <= 180")->required();
  cmd->add_option("--theta0-deg", a->theta0_deg,
                  "rest state: angle between a valley crease and the axis, degrees in [0, 180 - 180/n]")
      ->required();
  auto* ratio = cmd->add_option("--k-ratio", a->k_ratio, "k_m / k_v with k_v = 1 (>= 0)");
  auto* km = cmd->add_option("--k-m", a->k_m, "stiffness of each mountain crease (>= 0, energy / rad^2)");
  auto* kv = cmd->add_option("--k-v", a->k_v, "stiffness of each valley crease (>= 0, energy / rad^2)");
  ratio->excludes(km)->excludes(kv);
  km->needs(kv);
  kv->needs(km);
  cmd->add_flag("--json", a->json, "print JSON (numbers round-trip exactly)");
  cmd->add_option("--curve", a->curve,
                  "write energy and force-deflection along the symmetric path (CSV; each sample checked on the general model)");
  auto* samples = cmd->add_option("--samples", a->samples, "samples of --curve over (0, theta_limit), 3..2001 (default 181)");
  auto* target = cmd->add_option("--target-switching-force", a->target_switching_force,
                                  "design: the mountain stiffness k_m (k_v as given, default 1) whose switching force is this (> 0; radius-1 base)");
  cmd->callback([a, ratio, samples, target] {
    if (a->n < 3 || a->n > 180) throw InputError("--n", "must be between 3 and 180, got " + std::to_string(a->n));
    const double limit_deg = 180.0 - 180.0 / a->n;
    if (!std::isfinite(a->theta0_deg) || a->theta0_deg < 0.0 || a->theta0_deg > limit_deg)
      throw InputError("--theta0-deg", "must be in [0, " + std::to_string(limit_deg) + "] degrees for n = " +
                                           std::to_string(a->n));
    double k_m = a->k_m, k_v = a->k_v;
    if (ratio->count() > 0) {
      if (!std::isfinite(a->k_ratio) || a->k_ratio < 0.0) throw InputError("--k-ratio", "must be a finite number >= 0");
      k_m = a->k_ratio;
      k_v = 1.0;
    }
    if (!std::isfinite(k_m) || k_m < 0.0) throw InputError("--k-m", "must be a finite number >= 0");
    if (!std::isfinite(k_v) || k_v < 0.0) throw InputError("--k-v", "must be a finite number >= 0");
    if (k_m == 0.0 && k_v == 0.0) throw InputError("--k-m", "at least one stiffness must be > 0");
    // Clamp against the last-bit rounding of the degree conversion at the upper limit.
    const double theta0 = std::min(to_radians(a->theta0_deg), kPi - kPi / a->n);
    if (samples->count() > 0 && a->curve.empty()) throw InputError("--samples", "needs --curve");
    if (a->samples < 3 || a->samples > 2001)
      throw InputError("--samples", "must be between 3 and 2001, got " + std::to_string(a->samples));
    OutputSet outputs;
    if (!a->curve.empty()) outputs.add_output("--curve", a->curve);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    // Every number below passed its check in waterbomb_bistability (NoAnswerError -> exit 3).
    const waterbomb::WaterbombBistability r = waterbomb::waterbomb_bistability(a->n, theta0, k_m, k_v);

    nlohmann::ordered_json j;
    j["n"] = a->n;
    j["theta0_deg"] = a->theta0_deg;
    j["k_m"] = k_m;
    j["k_v"] = k_v;
    j["rest"] = {{"gamma_m_deg", to_degrees(r.springs.rest.gamma_m)}, {"gamma_v_deg", to_degrees(r.springs.rest.gamma_v)}};
    j["theta_limit_deg"] = limit_deg;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& e : r.equilibria) {
      nlohmann::ordered_json s;
      s["kind"] = waterbomb::to_string(e.path.kind);
      s["theta_deg"] = to_degrees(e.path.theta);
      s["gamma_m_deg"] = to_degrees(e.path.angles.gamma_m);
      s["gamma_v_deg"] = to_degrees(e.path.angles.gamma_v);
      s["energy"] = e.path.energy;
      s["at_validity_limit"] = e.path.at_validity_limit;
      s["closure_residual_rad"] = e.closure_residual;
      s["slope_residual"] = e.path.slope_residual;
      if (e.path.kind == waterbomb::EquilibriumKind::kCuspMaximum || e.path.kind == waterbomb::EquilibriumKind::kCuspMinimum) {
        s["slope_below"] = e.path.slope_below;
        s["slope_above"] = e.path.slope_above;
      }
      s["stationarity_residual"] = e.stationarity_residual;
      s["min_reduced_hessian_eigenvalue"] = number_or_null(e.min_reduced_eigenvalue);
      s["stable"] = e.path.kind == waterbomb::EquilibriumKind::kMinimum && !e.path.at_validity_limit && e.stable_unrestricted;
      list.push_back(s);
    }
    j["equilibria"] = list;
    // Barriers along the symmetric path only: over the flat cusp from each stable state. An
    // unsymmetric path between the states may cross lower (not searched yet).
    nlohmann::ordered_json barriers = nlohmann::ordered_json::array();
    for (const auto& b : r.symmetric_path_barriers())
      barriers.push_back({{"from_theta_deg", to_degrees(b.from_theta)}, {"symmetric_path_barrier", b.height}});
    j["barriers"] = barriers;
    // Switching force under force control (rest before flat only), on the radius-1 base.
    const double valley_length = std::cos(kPi / a->n);
    if (theta0 < kPi / 2) {
      const auto sw = waterbomb::switching_force_checked(a->n, theta0, k_m, k_v);
      j["switching_force"] = {{"force", sw.force}, {"theta_deg", to_degrees(sw.theta)}, {"at_flat", sw.at_flat},
                              {"valley_crease_length", valley_length}, {"general_model_gap", sw.general_gap}};
    }
    if (target->count() > 0) {
      if (!std::isfinite(a->target_switching_force) || a->target_switching_force <= 0.0)
        throw InputError("--target-switching-force", "must be a finite number > 0");
      if (!(theta0 < kPi / 2)) throw InputError("--target-switching-force", "needs a rest state before flat (--theta0-deg < 90)");
      if (!(k_v > 0.0)) throw InputError("--k-v", "must be > 0 for --target-switching-force");
      const double k_m_design = waterbomb::mountain_stiffness_for_switching_force(a->n, theta0, k_v, a->target_switching_force, valley_length);
      (void)waterbomb::switching_force_checked(a->n, theta0, k_m_design, k_v);  // the design, confirmed on the general model
      j["design"] = {{"target_switching_force", a->target_switching_force}, {"k_m", k_m_design}, {"k_v", k_v}};
    }
    if (!a->curve.empty()) {
      const waterbomb::WaterbombCurve c = waterbomb::waterbomb_curve(a->n, theta0, k_m, k_v, a->samples);
      for (const auto& s : c.samples)
        if (!s.checked)
          throw NoAnswerError("--curve: the general model does not confirm the closed form at theta = " +
                              round_trip_text(to_degrees(s.theta)) + " deg (" + std::to_string(c.unchecked) +
                              " of " + std::to_string(c.samples.size()) + " samples unchecked)");
      std::string csv =
          "theta_deg,gamma_m_deg,gamma_v_deg,energy,height,deflection,force,force_closed_form,min_reduced_hessian_eigenvalue,stable\n";
      for (const auto& s : c.samples)
        csv += round_trip_text(to_degrees(s.theta)) + "," + round_trip_text(to_degrees(s.angles.gamma_m)) + "," +
               round_trip_text(to_degrees(s.angles.gamma_v)) + "," + round_trip_text(s.energy) + "," +
               round_trip_text(s.height) + "," + round_trip_text(s.deflection) + "," + round_trip_text(s.force) + "," +
               round_trip_text(s.force_closed_form) + "," + round_trip_text(s.min_eigenvalue) + "," +
               (s.stable ? "1" : "0") + "\n";
      outputs.stage(a->curve, csv);
    }
    outputs.commit();
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    char line[320];
    std::snprintf(line, sizeof line, "waterbomb base n = %d, rest theta0 = %.12g deg (gamma_m0 = %.12g, gamma_v0 = %.12g deg), k_m = %.12g, k_v = %.12g\n",
                  a->n, a->theta0_deg, to_degrees(r.springs.rest.gamma_m), to_degrees(r.springs.rest.gamma_v), k_m, k_v);
    std::cout << line;
    for (const auto& s : list) {
      std::snprintf(line, sizeof line, "  %-26s theta = %.12g deg  (gamma_m, gamma_v) = (%.12g, %.12g) deg  energy %.12g%s%s\n",
                    s["kind"].get<std::string>().c_str(), s["theta_deg"].get<double>(), s["gamma_m_deg"].get<double>(),
                    s["gamma_v_deg"].get<double>(), s["energy"].get<double>(), s["stable"].get<bool>() ? "  STABLE" : "",
                    s["at_validity_limit"].get<bool>() ? "  (on a contact limit)" : "");
      std::cout << line;
      if (!s["min_reduced_hessian_eigenvalue"].is_null()) {
        std::snprintf(line, sizeof line, "      closure %.1e rad, dV/dtheta %.1e, unrestricted stationarity %.1e, min reduced Hessian eigenvalue %.6g\n",
                      s["closure_residual_rad"].get<double>(), s["slope_residual"].get<double>(),
                      s["stationarity_residual"].get<double>(), s["min_reduced_hessian_eigenvalue"].get<double>());
        std::cout << line;
      }
    }
    if (j.contains("switching_force")) {
      std::snprintf(line, sizeof line, "  switching force %.12g at theta = %.12g deg%s (push from the rest state; radius-1 base)\n",
                    j["switching_force"]["force"].get<double>(), j["switching_force"]["theta_deg"].get<double>(),
                    j["switching_force"]["at_flat"].get<bool>() ? " (the flat corner)" : "");
      std::cout << line;
    }
    if (j.contains("design")) {
      std::snprintf(line, sizeof line, "  design: k_m = %.12g (with k_v = %.12g) switches at %.12g\n", j["design"]["k_m"].get<double>(),
                    k_v, a->target_switching_force);
      std::cout << line;
    }
    for (const auto& b : barriers) {
      std::snprintf(line, sizeof line, "  barrier over the flat state from theta = %.12g deg: %.12g (symmetric path)\n",
                    b["from_theta_deg"].get<double>(), b["symmetric_path_barrier"].get<double>());
      std::cout << line;
    }
  });
}

}  // namespace rigidfold::cli
