// rigidfold waterbomb --sweep-n A..B [--sweep-split-deg B1,B2] [--sweep-k-ratio R1,R2] --theta0-deg T [--json] [--plot DIR]
//   a design sweep (design/waterbomb/waterbomb_sweep.hpp): the CSV table on stdout (or JSON),
//   with --plot DIR also DIR/sweep.csv (python/plot_waterbomb.py --sweep draws it).
// rigidfold waterbomb --n N [--split-deg B] --theta0-deg T [--k-ratio R | --k-m K --k-v K] [--json]
//                    [--curve FILE.csv] [--plot DIR] [--samples K] [--target-switching-force F]
// Bistability of the symmetric waterbomb base (seed 004): every equilibrium of the spring
// energy along the 1-DOF symmetric path, each checked (loop closure, dV/dtheta = 0, and
// stationarity and stability on the unrestricted 2n-crease problem) before it is printed.
// --curve writes the energy and force-deflection curves (design/waterbomb/waterbomb_curve.hpp):
// every sample checked against the general model, or nothing is written (exit 3). Past the
// flat state the general model continues along the one branch of the flat state's tangent
// cone that keeps the M/V letters (waterbomb_flat_crossing.hpp): the JSON's "flat_crossing"
// (cone lines, every branch's direction, height rate and letter check, the one taken) and a
// text line report it; no such branch: exit 3 with that reason. The split fold's curve crosses
// flat the same way (its symmetric motion: all half-valleys equal, all half-mountains equal).
// --split-deg B: the split-fold base (sector b = B deg, design/waterbomb/split_fold_bistability.hpp),
// every equilibrium and curve sample confirmed on the general 4n-crease model; theta0 must lie
// in the split fold's valid range. The split fold's switching force is the general model's
// (split_fold_switching_force); --target-switching-force designs k_m for it too
// (split_fold_mountain_stiffness_for_switching_force); no rest-angle design for split folds yet.
// --target-switching-force F --design theta0 (plain base, replaces --theta0-deg): the rest angle
// whose switching force is F (waterbomb_rest_design.hpp), confirmed on the general model.
// --target-second-state-deg T2 (plain base, replaces --theta0-deg): the rest angle theta0 whose
// second stable state lies at T2 (design/waterbomb/waterbomb_rest_design.hpp), then the whole
// analysis at that theta0; the design is printed only when a checked stable state lies within
// 1e-9 rad of T2 (exit 3 otherwise).
// --plot DIR: DIR/waterbomb.csv (the --curve table) and DIR/waterbomb.json (the --json
// document), the data of the energy and force figure; both staged with the other outputs, so a
// failed command writes neither. The binary starts no process: the figure is drawn from them by
// `python3 python/plot_waterbomb.py DIR/waterbomb.csv DIR/waterbomb.json --out F.png`, as the
// main job does.

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "design/waterbomb/split_fold_bistability.hpp"
#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_curve.hpp"
#include "design/waterbomb/waterbomb_rest_design.hpp"
#include "design/waterbomb/waterbomb_switching.hpp"
#include "design/waterbomb/waterbomb_sweep.hpp"
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

std::string curve_csv(const std::vector<waterbomb::CurveSample>& samples) {
  std::string csv =
      "theta_deg,gamma_m_deg,gamma_v_deg,energy,height,deflection,force,force_closed_form,min_reduced_hessian_eigenvalue,stable\n";
  for (const auto& s : samples)
    csv += round_trip_text(to_degrees(s.theta)) + "," + round_trip_text(to_degrees(s.angles.gamma_m)) + "," +
           round_trip_text(to_degrees(s.angles.gamma_v)) + "," + round_trip_text(s.energy) + "," +
           round_trip_text(s.height) + "," + round_trip_text(s.deflection) + "," + round_trip_text(s.force) + "," +
           round_trip_text(s.force_closed_form) + "," + round_trip_text(s.min_eigenvalue) + "," +
           (s.stable ? "1" : "0") + "\n";
  return csv;
}

// A list flag: "A..B" (integers, step 1) when `range` is allowed, else numbers separated by commas.
std::vector<double> number_list(const std::string& text, const char* flag, bool range) {
  std::vector<double> out;
  auto number = [&](const std::string& t) {
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(t, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (t.empty() || used != t.size() || !std::isfinite(x))
      throw InputError(flag, "'" + t + "' is not a finite number (lists: a,b,c" + (range ? std::string(" or A..B") : std::string()) + ")");
    return x;
  };
  if (const auto dots = text.find(".."); range && dots != std::string::npos) {
    const double lo = number(text.substr(0, dots)), hi = number(text.substr(dots + 2));
    if (lo != std::floor(lo) || hi != std::floor(hi) || hi < lo || hi - lo > 1000)
      throw InputError(flag, "a range A..B needs integers A <= B, got " + text);
    for (double x = lo; x <= hi; ++x) out.push_back(x);
    return out;
  }
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    out.push_back(number(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (out.size() > 1000) throw InputError(flag, "more than 1000 values");
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

template <class Args>
void run_sweep(const Args& a, bool have_theta0) {
  if (!have_theta0) throw InputError("--theta0-deg", "is required for a sweep");
  waterbomb::SweepSpec spec;
  for (double x : number_list(a.sweep_n, "--sweep-n", true)) {
    if (x != std::floor(x) || x < 3 || x > waterbomb::kMaxSweepDegree)
      throw InputError("--sweep-n", "each degree must be an integer in [3, " + std::to_string(waterbomb::kMaxSweepDegree) +
                                        "], got " + round_trip_text(x));
    spec.n.push_back(static_cast<int>(x));
  }
  spec.split_deg = number_list(a.sweep_split, "--sweep-split-deg", false);
  spec.k_ratio = number_list(a.sweep_k, "--sweep-k-ratio", false);
  spec.theta0_deg = a.theta0_deg;
  OutputSet outputs;
  std::string table_path;
  if (!a.plot.empty()) {
    outputs.add_output_directory("--plot", a.plot);
    const std::string dir = a.plot.back() == '/' ? a.plot : a.plot + "/";
    table_path = dir + "sweep.csv";
    outputs.add_output("--plot", table_path);
  }
  std::vector<waterbomb::SweepRow> rows;
  try {
    rows = waterbomb::waterbomb_sweep(spec);
  } catch (const InputError& e) {
    const std::string& p = e.place();
    throw InputError(p == "n" || p == "rows" ? "--sweep-n" : p == "split_deg" ? "--sweep-split-deg" : p == "k_ratio" ? "--sweep-k-ratio" : "--theta0-deg",
                     e.message());
  }
  const std::string csv = waterbomb::sweep_csv(rows);
  if (!a.plot.empty()) outputs.stage(table_path, csv);
  outputs.commit();
  if (a.json) {
    nlohmann::ordered_json j;
    j["theta0_deg"] = spec.theta0_deg;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& r : rows) {
      nlohmann::ordered_json row = {{"n", r.n}, {"split_deg", r.split_deg}, {"k_ratio", r.k_ratio}, {"status", r.status}};
      if (r.status == "ok") {
        row["stable_states"] = r.stable_states;
        row["state2_theta_deg"] = number_or_null(r.state2_theta_deg);
        row["state2_gamma_m_deg"] = number_or_null(r.state2_gamma_m_deg);
        row["state2_gamma_v_deg"] = number_or_null(r.state2_gamma_v_deg);
        row["state2_energy"] = number_or_null(r.state2_energy);
        row["barrier_from_rest"] = number_or_null(r.barrier_from_rest);
        row["barrier_from_state2"] = number_or_null(r.barrier_from_state2);
        row["switching_force"] = number_or_null(r.switching_force);
      }
      list.push_back(row);
    }
    j["rows"] = list;
    std::cout << document_text(j) << "\n";
    return;
  }
  std::cout << csv;
  if (!a.plot.empty()) std::cerr << "wrote " << table_path << "\n";
}

}  // namespace

void add_waterbomb_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("waterbomb", "Waterbomb base bistability (seed 004): stable states and the flat barrier");
  struct Args {
    int n = 0;
    double theta0_deg = 0, k_ratio = 1, k_m = 1, k_v = 1;
    bool json = false;
    std::string curve, plot;
    double split_deg = 0;
    int samples = 181;
    double target_switching_force = 0;
    double target_second_state_deg = 0;
    std::string sweep_n, sweep_split = "0", sweep_k = "1";
    std::string design = "k_m";
  };
  auto a = std::make_shared<Args>();
  auto* n_opt = cmd->add_option("--n", a->n, "mountain (= valley) creases, 3 <= n <= 180 (required unless --sweep-n)");
  auto* theta0_opt = cmd->add_option("--theta0-deg", a->theta0_deg,
                                     "rest state: angle between a valley crease and the axis, degrees in [0, 180 - 180/n] "
                                     "(required unless --target-second-state-deg designs it)");
  auto* ratio = cmd->add_option("--k-ratio", a->k_ratio, "k_m / k_v with k_v = 1 (>= 0)");
  auto* km = cmd->add_option("--k-m", a->k_m, "stiffness of each mountain crease (>= 0, energy / rad^2)");
  auto* kv = cmd->add_option("--k-v", a->k_v, "stiffness of each valley crease (>= 0, energy / rad^2)");
  ratio->excludes(km)->excludes(kv);
  km->needs(kv);
  kv->needs(km);
  cmd->add_flag("--json", a->json, "print JSON (numbers round-trip exactly)");
  cmd->add_option("--curve", a->curve,
                  "write energy and force-deflection along the symmetric path (CSV; each sample checked on the general model)");
  auto* split = cmd->add_option("--split-deg", a->split_deg,
                                 "split-fold base: sector b of each split-fold facet, degrees in (0, 180/n)");
  auto* plot_opt = cmd->add_option("--plot", a->plot,
                  "directory to write waterbomb.csv and waterbomb.json (the data of python/plot_waterbomb.py's energy and force figure)");
  auto* samples = cmd->add_option("--samples", a->samples, "samples of --curve / --plot over the valid range, 3..2001 (default 181)");
  auto* target = cmd->add_option("--target-switching-force", a->target_switching_force,
                                  "design: the mountain stiffness k_m (k_v as given, default 1) whose switching force is this (> 0; radius-1 base)");
  auto* second = cmd->add_option("--target-second-state-deg", a->target_second_state_deg,
                                  "design: the rest angle theta0 (replaces --theta0-deg) whose second stable state lies at this theta, "
                                  "degrees in (90, 180 - 180/n); plain base only");
  auto* design_opt = cmd->add_option("--design", a->design,
                                     "what --target-switching-force designs: k_m (default; at --theta0-deg) or theta0 (the rest "
                                     "angle, replacing --theta0-deg; k as given)");
  auto* sweep_n = cmd->add_option("--sweep-n", a->sweep_n,
                                   "design sweep: degrees n as A..B or a comma list (3..36); prints the CSV table "
                                   "(one checked analysis per n, split width and ratio at --theta0-deg)");
  auto* sweep_split = cmd->add_option("--sweep-split-deg", a->sweep_split, "sweep: split widths b in degrees, comma list (0 = plain base; default 0)");
  auto* sweep_k = cmd->add_option("--sweep-k-ratio", a->sweep_k, "sweep: stiffness ratios k_m / k_v, comma list (default 1)");
  cmd->callback([a, ratio, samples, target, split, theta0_opt, second, n_opt, sweep_n, sweep_split, sweep_k, km, design_opt, plot_opt] {
    if (plot_opt->count() > 0 && a->plot.empty()) throw InputError("--plot", "needs a directory name");
    if (sweep_n->count() > 0) {
      if (n_opt->count() > 0 || split->count() > 0 || ratio->count() > 0 || km->count() > 0 || !a->curve.empty() ||
          target->count() > 0 || second->count() > 0 || samples->count() > 0)
        throw InputError("--sweep-n", "a sweep takes --theta0-deg, --sweep-split-deg, --sweep-k-ratio, --json and --plot only");
      if (design_opt->count() > 0) throw InputError("--design", "needs --target-switching-force (not a sweep)");
      run_sweep(*a, theta0_opt->count() > 0);
      return;
    }
    if (sweep_split->count() > 0 || sweep_k->count() > 0)
      throw InputError(sweep_split->count() > 0 ? "--sweep-split-deg" : "--sweep-k-ratio", "needs --sweep-n");
    if (n_opt->count() == 0) throw InputError("--n", "is required (or --sweep-n for a design sweep)");
    if (a->n < 3 || a->n > 180) throw InputError("--n", "must be between 3 and 180, got " + std::to_string(a->n));
    const bool split_fold = split->count() > 0;
    if (design_opt->count() > 0 && a->design != "k_m" && a->design != "theta0")
      throw InputError("--design", "must be k_m or theta0, got '" + a->design + "'");
    if (design_opt->count() > 0 && target->count() == 0) throw InputError("--design", "needs --target-switching-force");
    const bool rest_by_force = target->count() > 0 && a->design == "theta0";
    if (rest_by_force && theta0_opt->count() > 0)
      throw InputError("--design", "theta0 designs the rest angle: give it without --theta0-deg");
    if (rest_by_force && split_fold) throw InputError("--split-deg", "--design theta0 is not available for split folds yet (--design k_m is)");
    const bool design_rest = second->count() > 0;
    if (design_rest && theta0_opt->count() > 0)
      throw InputError("--target-second-state-deg", "designs the rest angle: give it without --theta0-deg");
    if (!design_rest && !rest_by_force && theta0_opt->count() == 0)
      throw InputError("--theta0-deg", "is required (or --target-second-state-deg, or --target-switching-force with --design theta0, to design it)");
    if (rest_by_force) {
      if (!std::isfinite(a->target_switching_force) || a->target_switching_force <= 0.0)
        throw InputError("--target-switching-force", "must be a finite number > 0");
      a->theta0_deg = 45.0;  // a placeholder inside the range, replaced by the design below
    }
    if (design_rest && split_fold)
      throw InputError("--target-second-state-deg", "is for the plain base only (not with --split-deg)");
    if (design_rest && target->count() > 0)
      throw InputError("--target-second-state-deg", "cannot be combined with --target-switching-force");
    if (design_rest) {
      const double hi = 180.0 - 180.0 / a->n;
      if (!std::isfinite(a->target_second_state_deg) || !(a->target_second_state_deg > 90.0) ||
          !(a->target_second_state_deg < hi) || !(to_radians(a->target_second_state_deg) < kPi - kPi / a->n))
        throw InputError("--target-second-state-deg", "must lie in (90, " + round_trip_text(hi) + ") degrees for n = " +
                                                          std::to_string(a->n) + ", got " +
                                                          round_trip_text(a->target_second_state_deg));
      a->theta0_deg = 45.0;  // a placeholder inside the range, replaced by the design below
    }
    double limit_deg = 180.0 - 180.0 / a->n, lower_deg = 0.0;
    double b = 0.0;
    waterbomb::SplitFoldRange split_range;
    if (split_fold) {
      const double b_max_deg = 180.0 / a->n;
      if (!std::isfinite(a->split_deg) || !(a->split_deg > 0.0) || !(a->split_deg < b_max_deg))
        throw InputError("--split-deg", "must lie in (0, " + round_trip_text(b_max_deg) + ") degrees (180/n) for n = " +
                                            std::to_string(a->n) + ", got " + round_trip_text(a->split_deg));
      b = to_radians(a->split_deg);
      if (!(b < kPi / a->n)) throw InputError("--split-deg", "rounds to 180/n degrees or more");
      split_range = waterbomb::split_fold_range(a->n, b);
      lower_deg = to_degrees(split_range.theta_min);
      limit_deg = to_degrees(split_range.theta_max);
    }
    if (!std::isfinite(a->theta0_deg) || a->theta0_deg < lower_deg || a->theta0_deg > limit_deg)
      throw InputError("--theta0-deg", "must be in [" + round_trip_text(lower_deg) + ", " + round_trip_text(limit_deg) +
                                           "] degrees for n = " + std::to_string(a->n) +
                                           (split_fold ? " and --split-deg " + round_trip_text(a->split_deg) +
                                                             " (the split fold's valid range)"
                                                       : std::string()));
    double k_m = a->k_m, k_v = a->k_v;
    if (ratio->count() > 0) {
      if (!std::isfinite(a->k_ratio) || a->k_ratio < 0.0) throw InputError("--k-ratio", "must be a finite number >= 0");
      k_m = a->k_ratio;
      k_v = 1.0;
    }
    if (!std::isfinite(k_m) || k_m < 0.0) throw InputError("--k-m", "must be a finite number >= 0");
    if (!std::isfinite(k_v) || k_v < 0.0) throw InputError("--k-v", "must be a finite number >= 0");
    if (k_m == 0.0 && k_v == 0.0) throw InputError("--k-m", "at least one stiffness must be > 0");
    waterbomb::RestAngleDesign rest_design;
    if (design_rest) {
      rest_design = waterbomb::rest_angle_for_state2(a->n, to_radians(a->target_second_state_deg), k_m, k_v);
      a->theta0_deg = to_degrees(rest_design.theta0);
    }
    if (rest_by_force) {
      rest_design.theta0 = waterbomb::rest_angle_for_switching_force(a->n, a->target_switching_force, k_m, k_v, std::cos(kPi / a->n));
      a->theta0_deg = to_degrees(rest_design.theta0);
    }
    // Clamp against the last-bit rounding of the degree conversion at the upper limit.
    const double theta0 = design_rest || rest_by_force ? rest_design.theta0 : split_fold ? std::min(std::max(to_radians(a->theta0_deg), split_range.theta_min), split_range.theta_max)
                                     : std::min(to_radians(a->theta0_deg), kPi - kPi / a->n);
    if (samples->count() > 0 && a->curve.empty() && a->plot.empty()) throw InputError("--samples", "needs --curve or --plot");
    if (split_fold && target->count() > 0 && !(theta0 < kPi / 2 - 2e-4))
      throw InputError("--target-switching-force", "needs a rest state before flat (--theta0-deg < 90)");
    if (a->samples < 3 || a->samples > 2001)
      throw InputError("--samples", "must be between 3 and 2001, got " + std::to_string(a->samples));
    OutputSet outputs;
    std::string plot_csv, plot_json;
    if (!a->plot.empty()) {
      outputs.add_output_directory("--plot", a->plot);
      const std::string dir = a->plot.back() == '/' ? a->plot : a->plot + "/";
      plot_csv = dir + "waterbomb.csv";
      plot_json = dir + "waterbomb.json";
      for (const auto* path : {&plot_csv, &plot_json}) outputs.add_output("--plot", *path);
    }
    if (!a->curve.empty()) outputs.add_output("--curve", a->curve);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    // Every number below passed its check in waterbomb_bistability or split_fold_bistability
    // (NoAnswerError -> exit 3).
    std::vector<waterbomb::CheckedEquilibrium> equilibria;
    std::vector<waterbomb::WaterbombBistability::Barrier> path_barriers;
    waterbomb::FoldPair rest;
    nlohmann::ordered_json unconfirmed = nlohmann::ordered_json::array();
    double support_distance = std::cos(kPi / a->n);
    if (split_fold) {
      const waterbomb::SplitFoldBistability r = waterbomb::split_fold_bistability(a->n, b, theta0, k_m, k_v);
      equilibria = r.equilibria;
      path_barriers = r.symmetric_path_barriers();
      rest = r.springs.rest;
      support_distance = r.support_distance;
      for (const auto& u : r.unconfirmed_near_contact)
        unconfirmed.push_back({{"kind", waterbomb::to_string(u.kind)}, {"theta_from_deg", to_degrees(u.theta_lo)},
                               {"theta_to_deg", to_degrees(u.theta_hi)}, {"why", u.why}});
    } else {
      const waterbomb::WaterbombBistability r = waterbomb::waterbomb_bistability(a->n, theta0, k_m, k_v);
      equilibria = r.equilibria;
      path_barriers = r.symmetric_path_barriers();
      rest = r.springs.rest;
      if (design_rest) {
        // The design, confirmed forward: a stable state (checked on the unsymmetric model) at the target.
        const double target2 = to_radians(a->target_second_state_deg);
        double gap = INFINITY;
        for (const auto& st : r.stable_states()) gap = std::min(gap, std::fabs(st.path.theta - target2));
        if (!(gap <= 1e-9))
          throw NoAnswerError("--target-second-state-deg: the forward analysis at the designed theta0 = " +
                                  round_trip_text(a->theta0_deg) + " deg finds no stable state at the target (gap, rad)",
                              gap);
      }
    }

    nlohmann::ordered_json j;
    j["n"] = a->n;
    j["theta0_deg"] = a->theta0_deg;
    j["k_m"] = k_m;
    j["k_v"] = k_v;
    if (split_fold) j["split_deg"] = a->split_deg;
    j["rest"] = {{"gamma_m_deg", to_degrees(rest.gamma_m)}, {"gamma_v_deg", to_degrees(rest.gamma_v)}};
    if (split_fold) {
      j["theta_min_deg"] = lower_deg;
      j["support_distance"] = support_distance;
      // false: the printed forms (seed eqs 3.13-3.30) break down there before facets touch.
      j["theta_min_is_contact"] = split_range.lower_is_contact;
      j["theta_limit_is_contact"] = split_range.upper_is_contact;  // vertex to the supports along a valley split-facet centreline (unit creases)
    }
    j["theta_limit_deg"] = limit_deg;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const auto& e : equilibria) {
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
    if (split_fold) j["unconfirmed_near_contact_limit"] = unconfirmed;
    // Barriers along the symmetric path only: over the flat cusp from each stable state. An
    // unsymmetric path between the states may cross lower (not searched yet).
    nlohmann::ordered_json barriers = nlohmann::ordered_json::array();
    for (const auto& bar : path_barriers)
      barriers.push_back({{"from_theta_deg", to_degrees(bar.from_theta)}, {"symmetric_path_barrier", bar.height}});
    j["barriers"] = barriers;
    // Switching force under force control (rest before flat only), on the radius-1 base.
    const double valley_length = std::cos(kPi / a->n);
    if (split_fold && theta0 < kPi / 2 - 2e-4) {
      const auto sw = waterbomb::split_fold_switching_force(a->n, b, theta0, k_m, k_v);
      j["switching_force"] = {{"force", sw.force}, {"theta_deg", to_degrees(sw.theta)}, {"at_flat", sw.at_flat},
                              {"support_distance", support_distance}, {"closed_form_gap", sw.closed_form_gap}};
    }
    if (!split_fold && theta0 < kPi / 2) {
      const auto sw = waterbomb::switching_force_checked(a->n, theta0, k_m, k_v);
      j["switching_force"] = {{"force", sw.force}, {"theta_deg", to_degrees(sw.theta)}, {"at_flat", sw.at_flat},
                              {"valley_crease_length", valley_length}, {"general_model_gap", sw.general_gap}};
    }
    if (design_rest) {
      double gap = INFINITY;
      for (const auto& e : list)
        if (e["stable"].get<bool>()) gap = std::min(gap, std::fabs(to_radians(e["theta_deg"].get<double>()) - to_radians(a->target_second_state_deg)));
      j["design"] = {{"target_second_state_deg", a->target_second_state_deg}, {"theta0_deg", a->theta0_deg},
                     {"slope_residual", rest_design.slope_residual}, {"curvature", rest_design.curvature},
                     {"second_state_gap_rad", gap}};
    }
    if (rest_by_force) {
      // The design, confirmed on the general model: the switching force at the designed theta0.
      const auto sw = waterbomb::switching_force_checked(a->n, theta0, k_m, k_v);
      const double miss = std::fabs(sw.force - a->target_switching_force);
      if (!(miss <= 1e-9 * a->target_switching_force))
        throw NoAnswerError("--target-switching-force: the designed theta0 switches " + round_trip_text(miss) + " away from the target", miss);
      j["design"] = {{"target_switching_force", a->target_switching_force}, {"theta0_deg", a->theta0_deg}, {"k_m", k_m}, {"k_v", k_v},
                     {"switching_force", sw.force}};
    } else if (target->count() > 0 && split_fold) {
      if (!std::isfinite(a->target_switching_force) || a->target_switching_force <= 0.0)
        throw InputError("--target-switching-force", "must be a finite number > 0");
      if (!(k_v > 0.0)) throw InputError("--k-v", "must be > 0 for --target-switching-force");
      const double k_m_design =
          waterbomb::split_fold_mountain_stiffness_for_switching_force(a->n, b, theta0, k_v, a->target_switching_force);
      j["design"] = {{"target_switching_force", a->target_switching_force}, {"k_m", k_m_design}, {"k_v", k_v}};
    } else if (target->count() > 0) {
      if (!std::isfinite(a->target_switching_force) || a->target_switching_force <= 0.0)
        throw InputError("--target-switching-force", "must be a finite number > 0");
      if (!(theta0 < kPi / 2)) throw InputError("--target-switching-force", "needs a rest state before flat (--theta0-deg < 90)");
      if (!(k_v > 0.0)) throw InputError("--k-v", "must be > 0 for --target-switching-force");
      const double k_m_design = waterbomb::mountain_stiffness_for_switching_force(a->n, theta0, k_v, a->target_switching_force, valley_length);
      (void)waterbomb::switching_force_checked(a->n, theta0, k_m_design, k_v);  // the design, confirmed on the general model
      j["design"] = {{"target_switching_force", a->target_switching_force}, {"k_m", k_m_design}, {"k_v", k_v}};
    }
    if (!a->curve.empty() || !a->plot.empty()) {
      std::vector<waterbomb::CurveSample> curve;
      int unchecked = 0;
      // Which branch of the flat state's tangent cone the general model continued along.
      auto write_flat_crossing = [&](const waterbomb::FlatCrossing& fc, int creases, const char* system) {
        nlohmann::ordered_json branches = nlohmann::ordered_json::array();
        for (const auto& br : fc.branches) {
          std::vector<double> dir;
          for (int e = 0; e < creases; ++e) dir.push_back(br.direction[e]);
          branches.push_back({{"direction", dir},
                              {"height_rate", br.height_rate},
                              {"below_supports", br.far_side},
                              {"keeps_letters", br.keeps_letters},
                              {"first_wrong_crease", br.first_wrong_crease < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(br.first_wrong_crease)}});
        }
        j["flat_crossing"] = {{"system", system},
                              {"kernel_dimension", fc.kernel_dimension},
                              {"cone_lines", fc.cone_lines},
                              {"branches_below_supports", fc.far_side_branches},
                              {"letter_keeping_below_supports", fc.letter_keeping},
                              {"taken", fc.taken < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(fc.taken)},
                              {"branches", branches}};
      };
      if (split_fold) {
        const waterbomb::SplitFoldCurve c = waterbomb::split_fold_curve(a->n, b, theta0, k_m, k_v, a->samples);
        curve = c.samples;
        unchecked = c.unchecked;
        if (c.crosses_flat)
          write_flat_crossing(c.flat_crossing, 4 * a->n,
                              "closure rows + symmetry equalities (all half-valleys equal, all half-mountains equal), "
                              "tangent cone at the flat state; supports: the half-valley ends (split facets' outer-edge midpoints)");
        if (c.stopped_at_flat || !c.stop_message.empty())
          throw NoAnswerError(std::string(a->curve.empty() ? "--plot" : "--curve") + ": " + c.stop_message);
      } else {
        const waterbomb::WaterbombCurve c = waterbomb::waterbomb_curve(a->n, theta0, k_m, k_v, a->samples);
        curve = c.samples;
        unchecked = c.unchecked;
        write_flat_crossing(c.flat_crossing, 2 * a->n, "closure rows + rotational symmetry equalities, tangent cone at the flat state");
        if (c.stopped_at_flat || !c.stop_message.empty())
          throw NoAnswerError(std::string(a->curve.empty() ? "--plot" : "--curve") + ": " + c.stop_message);
      }
      const char* flag = a->curve.empty() ? "--plot" : "--curve";
      for (const auto& s : curve)
        if (!s.checked)
          throw NoAnswerError(std::string(flag) + ": the general model does not confirm the closed form at theta = " +
                              round_trip_text(to_degrees(s.theta)) + " deg (" + std::to_string(unchecked) + " of " +
                              std::to_string(curve.size()) + " samples unchecked)");
      const std::string csv = curve_csv(curve);
      if (!a->curve.empty()) outputs.stage(a->curve, csv);
      if (!a->plot.empty()) {
        outputs.stage(plot_csv, csv);
        outputs.stage(plot_json, document_text(j) + "\n");
      }
    }
    outputs.commit();
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    char line[320];
    if (split_fold) {
      std::snprintf(line, sizeof line, "split-fold waterbomb base n = %d, b = %.12g deg (valid range [%.12g, %.12g] deg)\n", a->n,
                    a->split_deg, lower_deg, limit_deg);
      std::cout << line;
    }
    std::snprintf(line, sizeof line, "waterbomb base n = %d, rest theta0 = %.12g deg (gamma_m0 = %.12g, gamma_v0 = %.12g deg), k_m = %.12g, k_v = %.12g\n",
                  a->n, a->theta0_deg, to_degrees(rest.gamma_m), to_degrees(rest.gamma_v), k_m, k_v);
    std::cout << line;
    if (j.contains("flat_crossing")) {
      const auto& fc = j["flat_crossing"];
      const int taken = fc["taken"].get<int>();
      std::snprintf(line, sizeof line,
                    "  flat crossing: tangent cone of the symmetric closure system has %d lines (%zu branches, %d below the supports, "
                    "%d keeping the M/V letters); the curve continues along branch %d\n",
                    fc["cone_lines"].get<int>(), fc["branches"].size(), fc["branches_below_supports"].get<int>(),
                    fc["letter_keeping_below_supports"].get<int>(), taken);
      std::cout << line;
    }
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
      std::snprintf(line, sizeof line, split_fold ? "  switching force %.12g at theta = %.12g deg%s (push from the rest state; unit creases)\n"
                                                  : "  switching force %.12g at theta = %.12g deg%s (push from the rest state; radius-1 base)\n",
                    j["switching_force"]["force"].get<double>(), j["switching_force"]["theta_deg"].get<double>(),
                    j["switching_force"]["at_flat"].get<bool>() ? " (the flat corner)" : "");
      std::cout << line;
    }
    if (design_rest) {
      std::snprintf(line, sizeof line, "  design: rest theta0 = %.17g deg puts the second stable state at %.12g deg (gap %.1e rad)\n",
                    a->theta0_deg, a->target_second_state_deg, j["design"]["second_state_gap_rad"].get<double>());
      std::cout << line;
    } else if (rest_by_force) {
      std::snprintf(line, sizeof line, "  design: rest theta0 = %.17g deg (k_m = %.12g, k_v = %.12g) switches at %.12g\n", a->theta0_deg,
                    k_m, k_v, a->target_switching_force);
      std::cout << line;
    } else if (j.contains("design")) {
      std::snprintf(line, sizeof line, "  design: k_m = %.12g (with k_v = %.12g) switches at %.12g\n", j["design"]["k_m"].get<double>(),
                    k_v, a->target_switching_force);
      std::cout << line;
    }
    for (const auto& bar : barriers) {
      std::snprintf(line, sizeof line, "  barrier over the flat state from theta = %.12g deg: %.12g (symmetric path)\n",
                    bar["from_theta_deg"].get<double>(), bar["symmetric_path_barrier"].get<double>());
      std::cout << line;
    }
    for (const auto& u : unconfirmed) {
      std::snprintf(line, sizeof line, "  unconfirmed %s next to a contact limit, theta in [%.6g, %.6g] deg (not an equilibrium of this result)\n",
                    u["kind"].get<std::string>().c_str(), u["theta_from_deg"].get<double>(), u["theta_to_deg"].get<double>());
      std::cout << line;
    }
    if (!a->plot.empty()) std::cout << "  wrote " << plot_csv << ", " << plot_json << "\n";
  });
}

}  // namespace rigidfold::cli
