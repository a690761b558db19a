// rigidfold sorce PATTERN --thickness T [--offsets linear|SPEC.json] [--circular EDGE,...] [--split EDGE:SPEC ...]
//                 [--optimize [--epsilon E]
//                 [--max-protrusion P] [--max-s0 S] [--max-evaluations N]] [--drive E] [--to DEG] [--steps N]
//                 [--at T] [--samples N] [--general] [--json] [--out DIR]
// SORCE rolling-contact joints (seed 002) for every folding crease of a pattern, on the path
// trace_motion traces (exact multiplier family for flat-foldable degree-4 patterns, else the
// general solver; --general forces it; design/sorce/sorce_design.hpp, the front door): per crease its
// profile pair's diagnostics, per face its offset, the pattern's verification figures, and
// with --optimize the offset coefficients searched for the figure of merit.
// --out DIR writes:
//   sorce.json      the JSON printed by --json
//   profiles.svg    every folding crease's profile pair side by side ("E<edge>")
//   profiles.dxf    the same as DXF polylines, true coordinates, layers E<edge>_LEFT/_RIGHT/_SLAB
//   panel_F.stl     panel F (face index) as slab + cams (design/sorce/sorce_solids.hpp) in its
//                   flat pose, its slab cut clear of each mate cam's sweep (clearance cuts,
//                   sorce_pattern_solids.hpp), one closed file per panel for printing (none, with the reason in
//                   the JSON, when a panel cannot be built: not convex, a cam section that
//                   crosses itself)
//   panels_at.stl   every panel placed at t = --at, for viewing (only with --at; mating cams
//                   touch along their contact lines there)
//   frames.fold     the panels' mid-planes, one frame per pose time (sorce_frames.hpp)
//   poses.csv       the pose table P_f(t)
// Nothing is printed or written unless the joints pass their checks (rolling and contact
// residuals, 3D consistency, vertex closure and contact; design/sorce/sorce_checks.hpp):
// otherwise exit 3. Lengths in the pattern file's units.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/number_flags.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "design/sorce/sorce_cam_interference.hpp"
#include "design/sorce/sorce_checks.hpp"
#include "design/sorce/sorce_design.hpp"
#include "design/sorce/sorce_dxf.hpp"
#include "design/sorce/sorce_frames.hpp"
#include "design/sorce/sorce_offsets_spec.hpp"
#include "design/sorce/sorce_pattern_solids.hpp"
#include "design/sorce/sorce_solids.hpp"
#include "design/sorce/sorce_split_spec.hpp"
#include "design/sorce/sorce_svg.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "report/sorce_json.hpp"

namespace rigidfold::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
using namespace rigidfold::sorce;
using report::cam_interference_json;
using report::checks_json;
using report::crease_json;
using report::finite_or_null;

std::vector<Polygon3> placed_panels(const std::vector<PanelSolid>& solids, const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Polygon3> all;
  for (std::size_t f = 0; f < solids.size(); ++f) {
    const std::vector<Polygon3> moved = transformed(solids[f].polygons, poses[f]);
    all.insert(all.end(), moved.begin(), moved.end());
  }
  return all;
}

}  // namespace

void add_sorce_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("sorce", "SORCE rolling-contact joints for thick panels (seed 002) on the traced folding path");
  struct Args {
    std::string pattern, offsets = "linear", out, parameter = "drive";
    double thickness = 0, epsilon = 0, max_protrusion = -1, max_s0 = -1, to = 0, at = -1;
    int drive = -1, steps = 40, samples = 201, max_evaluations = 400;
    std::vector<int> circular;
    std::vector<std::string> split;
    bool optimize = false, json = false, general = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold, .svg, .opx), flat")->required();
  cmd->add_option("--thickness", a->thickness, "every panel's thickness (> 0, the pattern's length units)")
      ->required()
      ->check(finite_number());
  cmd->add_option("--offsets", a->offsets,
                  "linear (z_f = z_f(1) t, z_f(1) by the stacking rule; default) or SPEC.json: {\"end_offsets\": [per face], "
                  "\"coefficients\": [[b1, b2, b3] per face]}");
  cmd->add_option("--circular", a->circular,
                  "creases (edge indices, comma-separated) made circular CORE joints: both faces z = -(T/2) tan(gamma/4), "
                  "profiles on arcs of radius T/2")
      ->delimiter(',');
  cmd->add_option("--split", a->split,
                  "EDGE:SPEC, repeatable: split crease EDGE, its right panel shifted by d(t) along the fold's half-angle "
                  "direction (seed eqs 58, 59); SPEC linear:D (d = D t) or quadratic:D (d = D t^2), D in length units; "
                  "split both collinear creases of a vertex with one SPEC for the seed's collinear split");
  cmd->add_flag("--optimize", a->optimize, "search the faces' offset coefficients for the figure of merit (NLopt COBYLA)");
  cmd->add_option("--epsilon", a->epsilon, "with --optimize: smallest convexity allowed (1/length, >= 0)")->check(finite_in(0, 1e300));
  cmd->add_option("--max-protrusion", a->max_protrusion, "with --optimize: bound on every cam's protrusion (length, >= 0)")
      ->check(finite_in(0, 1e300));
  cmd->add_option("--max-s0", a->max_s0, "with --optimize: bound on every |s0| (length, >= 0)")->check(finite_in(0, 1e300));
  auto* max_evaluations = cmd->add_option("--max-evaluations", a->max_evaluations, "with --optimize: the search's budget of designs evaluated (1..100000; default 400)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--drive", a->drive, "driving crease (edge index; default: the tracing model's choice)")->check(CLI::NonNegativeNumber);
  auto* to = cmd->add_option("--to", a->to,
                             "driving crease's final fold angle, t = 1 (degrees, signed; default 170 in its letter's direction; "
                             "+-180 for joints that reach the flat-folded state)")
                 ->check(finite_in(-180, 180, "degrees"));
  cmd->add_option("--steps", a->steps, "traced steps to start from (8..2000; a splined path is refined until its diagnostics settle)")->check(CLI::Range(8, 2000));
  cmd->add_option("--parameter", a->parameter,
                  "the path's parameter t: drive (t = drive / final drive; default), arc-length (t = arc length in "
                  "fold-angle space / total) or half-tangent (tan(pi t/2) ~ geometric mean of |tan(rho/2)|, the seed's "
                  "eq 35 on one vertex); sorce_path_spline.hpp");
  cmd->add_option("--at", a->at, "with --out: also write the panels placed at this t (0..1) as panels_at.stl")
      ->check(finite_in(0, 1));
  cmd->add_option("--samples", a->samples, "points per profile in the drawings and solids (8..20000)")->check(CLI::Range(8, 20000));
  cmd->add_flag("--general", a->general,
                "trace with the general loop-closure solver even where the exact multiplier model applies");
  cmd->add_flag("--json", a->json, "print JSON (numbers round-trip exactly)");
  cmd->add_option("--out", a->out, "directory for sorce.json, profiles.svg/.dxf, panels.stl, frames.fold, poses.csv");
  cmd->callback([a, to, max_evaluations] {
    OutputSet outputs;
    outputs.add_input("PATTERN", a->pattern);
    const bool spec_given = a->offsets != "linear";
    if (spec_given) outputs.add_input("--offsets", a->offsets);
    const fs::path dir(a->out);
    auto out_file = [&](const char* name) { return (dir / name).string(); };
    const std::vector<std::string> names{"sorce.json", "profiles.svg", "profiles.dxf", "frames.fold", "poses.csv"};
    if (!a->out.empty()) {
      outputs.add_output_directory("--out", a->out);
      for (const std::string& n : names) outputs.add_output("--out", out_file(n.c_str()));
      if (a->at >= 0) outputs.add_output("--out", out_file("panels_at.stl"));
    } else if (a->at >= 0) {
      throw InputError("--at", "needs --out DIR");
    }
    if (!a->optimize && (a->epsilon != 0 || a->max_protrusion >= 0 || a->max_s0 >= 0 || max_evaluations->count() > 0))
      throw InputError("--optimize", "--epsilon, --max-protrusion, --max-s0 and --max-evaluations bound the search: give --optimize");
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);

    const CreasePattern p = read_pattern(a->pattern);
    if (p.length_exponent != 0)
      throw InputError(a->pattern, "its size lies outside [2^-20, 2^20] length units: rescale the file for SORCE drawings");
    SorceDesignRequest rq;
    rq.sorce.thickness = a->thickness;
    if (!(a->thickness > 0)) throw InputError("--thickness", "must be > 0");
    if (spec_given) {
      const OffsetSpec spec = parse_offset_spec(read_input_file(a->offsets), a->offsets, p.num_faces());
      rq.sorce.end_offsets = spec.end_offsets;
      rq.sorce.offset_coefficients = spec.coefficients;
    }
    rq.sorce.circular_edges = a->circular;
    for (const std::string& text : a->split) {
      try {
        rq.sorce.splits.push_back(parse_split_spec(text));
      } catch (const InputError& e) {
        throw InputError("--split " + text, e.message());
      }
    }
    if (a->drive >= 0) rq.sorce.trace.drive = a->drive;
    if (to->count() > 0) {
      if (a->to == 0) throw InputError("--to", "must not be 0");
      rq.sorce.trace.to = to_radians(a->to);
    }
    rq.sorce.trace.steps = a->steps;
    rq.sorce.trace.force_general = a->general;
    if (a->parameter == "arc-length") rq.sorce.path_parameter = PathParameter::kArcLength;
    else if (a->parameter == "half-tangent") rq.sorce.path_parameter = PathParameter::kHalfTangent;
    else if (a->parameter != "drive")
      throw InputError("--parameter", "must be drive, arc-length or half-tangent, not '" + a->parameter + "'");
    rq.sorce.pose_times = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    if (a->at >= 0 && std::find(rq.sorce.pose_times.begin(), rq.sorce.pose_times.end(), a->at) == rq.sorce.pose_times.end()) {
      rq.sorce.pose_times.push_back(a->at);
      std::sort(rq.sorce.pose_times.begin(), rq.sorce.pose_times.end());
    }
    rq.optimize = a->optimize;
    rq.epsilon = a->epsilon;
    if (a->max_protrusion >= 0) rq.max_protrusion = a->max_protrusion;
    if (a->max_s0 >= 0) rq.max_abs_s0 = a->max_s0;
    rq.optimizer.max_evaluations = a->max_evaluations;

    SorceDesign d;
    try {
      d = sorce_design(p, rq);
    } catch (const InputError& e) {
      // The design layer's places, as the user gave them.
      const std::string& place = e.place();
      if (place == "thickness") throw InputError("--thickness", e.message());
      if (place == "drive") throw InputError("--drive", e.message());
      if (place == "to") throw InputError("--to", e.message());
      if (place.rfind("circular_edges", 0) == 0) throw InputError("--circular " + place.substr(14), e.message());
      if (place.rfind("splits[", 0) == 0) {  // the k-th --split as the user wrote it
        const std::size_t k = std::stoul(place.substr(7));
        if (k < a->split.size()) throw InputError("--split " + a->split[k], e.message());
      }
      if (place == "pattern" || place == "branch") throw InputError(a->pattern, e.message());
      if (place.rfind("end_offsets", 0) == 0 || place.rfind("offset_coefficients", 0) == 0)
        throw InputError((spec_given ? a->offsets : a->pattern) + ": " + place, e.message());
      throw;
    }
    const PatternSorce& s = d.sorce;
    // Nothing is reported before the joints pass their own checks.
    const SorceCheckVerdict verdict = check_sorce(p, s);
    if (!verdict.passed) throw NoAnswerError("the SORCE joints fail their check: " + verdict.failure, verdict.worst);

    Json j;
    j["file"] = a->pattern;
    j["thickness"] = a->thickness;
    Json path;
    path["model"] = d.model;
    path["driving_crease"] = s.path.drive;
    path["final_drive_deg"] = to_degrees(s.path.final_drive);
    path["parameter"] = to_string(s.path.parameter);
    path["arc_length_deg"] = to_degrees(s.path.arc_length);
    path["knots"] = s.path.knots.size();
    path["exact"] = d.refinement.exact;
    path["steps_tried"] = d.refinement.steps_tried;
    path["accuracy"] = {{"t_tolerance", rq.accuracy.t_tolerance},
                        {"length_tolerance_relative", rq.accuracy.length_tolerance},
                        {"max_doublings", rq.accuracy.max_doublings}};
    path["settled"] = d.refinement.settled;
    if (!d.refinement.settled) path["unsettled"] = d.refinement.change;
    path["parameter_definition"] = parameter_definition(s.path);
    j["path"] = path;
    Json faces = Json::array();
    for (std::size_t f = 0; f < s.faces.size(); ++f)
      faces.push_back({{"face", f}, {"end_offset", s.faces[f].end_value}, {"thickness", s.faces[f].thickness}});
    j["faces"] = faces;
    Json creases = Json::array();
    std::vector<FoldReport> reports;
    for (const CreaseJoint& c : s.creases) {
      creases.push_back(crease_json(c));
      if (c.folds) reports.push_back(c.report);
    }
    j["creases"] = creases;
    j["figure_of_merit"] = finite_or_null(figure_of_merit(reports, rq.epsilon));
    j["checks"] = checks_json(s.checks);
    // Cams against every other panel's slab and cams over 21 samples of t (FCL); the rolling
    // partners' cams are not a pair (their contact is the joint). First the solids as designed
    // (no clearance), then as printed: each slab cut clear of its mate cam's sweep, the STL files.
    std::vector<PanelSolid> solids;
    std::string solids_note;
    try {
      const PatternSolids plain = pattern_solids(p, s, a->samples);
      j["checks"]["cam_interference"] = cam_interference_json(cam_interference(p, s, plain, 21));
      ClearanceOptions cut;
      cut.cut = !a->out.empty();  // the cuts are for the STL files only (their sweeps cost seconds on a Miura)
      const PatternSolids built = cut.cut ? pattern_solids(p, s, a->samples, SolidOptions{}, cut) : plain;
      Json cuts = Json::array();
      for (const ClearanceCut& c : built.clearances)
        cuts.push_back({{"face", c.face}, {"edge", c.edge}, {"cut", c.cut}, {"margin", c.margin}, {"sweep_step", c.sweep_step},
                        {"region_area", c.region_area}});
      j["clearance_cuts"] = cuts;
      if (cut.cut) j["checks"]["cam_interference_printed"] = cam_interference_json(cam_interference(p, s, built, 21));
      solids = built.panels;
    } catch (const InputError& e) {
      solids.clear();
      solids_note = std::string("no STL: ") + e.what();
      j["checks"]["cam_interference"] = {{"checked", false}, {"reason", solids_note}};
      if (!a->out.empty()) j["checks"]["cam_interference_printed"] = j["checks"]["cam_interference"];
    }
    Json bounds = Json::object();
    for (const auto& [name, bound] : verdict.bounds) bounds[name] = bound;
    j["check_bounds"] = bounds;
    if (d.optimization) j["optimization"] = report::optimization_json(*d.optimization, d.design_faces);

    if (!a->out.empty()) {
      std::vector<NamedFold> folds;
      for (const CreaseJoint& c : s.creases)
        if (c.folds) folds.push_back({"E" + std::to_string(c.edge), c.motion});
      if (folds.empty()) throw InputError(a->pattern, "no crease folds on the traced path: no joint to draw");
      SvgOptions svg;
      svg.samples = a->samples;
      svg.width_px = 1600;
      svg.stroke = a->thickness / 40;
      outputs.stage(out_file("profiles.svg"), folds_profiles_svg(folds, svg));
      outputs.stage(out_file("profiles.dxf"), fold_profiles_dxf(folds, a->samples));
      PoseFrames frames;
      frames.times = s.pose_times;
      frames.poses = s.poses;
      for (double t : s.pose_times) {
        Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
        for (int e = 0; e < p.num_edges(); ++e) rho[e] = s.path.rho[e](t)[0];
        frames.fold_angles.push_back(rho);
      }
      outputs.stage(out_file("frames.fold"), write_fold_string(exploded_frames(p, frames)));
      outputs.stage(out_file("poses.csv"), pose_table_csv(p, frames));
      Json files = Json::object();
      if (solids.empty()) j["stl_note"] = solids_note;
      if (!solids.empty()) {
        Json panels = Json::array();
        for (int f = 0; f < p.num_faces(); ++f) {
          const std::string name = out_file(("panel_" + std::to_string(f) + ".stl").c_str());
          outputs.add_output("--out", name);
          outputs.stage(name, polygons_stl(solids[f].polygons, p.length_exponent, "rigidfold sorce panel (binary STL)"));
          panels.push_back(name);
        }
        files["panels"] = panels;
        if (a->at >= 0) {
          const auto k = std::find(s.pose_times.begin(), s.pose_times.end(), a->at) - s.pose_times.begin();
          outputs.stage(out_file("panels_at.stl"), polygons_stl(placed_panels(solids, s.poses[k]), p.length_exponent,
                                                                "rigidfold sorce panels placed at --at (binary STL)"));
          files["panels_at"] = out_file("panels_at.stl");
        }
      }
      for (const char* n : {"profiles.svg", "profiles.dxf", "frames.fold", "poses.csv"}) files[n] = out_file(n);
      j["out"] = files;
      outputs.stage(out_file("sorce.json"), document_text(j) + "\n");
    }
    outputs.commit();
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    std::cout << a->pattern << ": SORCE joints on " << reports.size() << " folding crease(s), thickness " << a->thickness << "\n";
    std::cout << brief(d, rq.epsilon);
    if (!a->out.empty()) std::cout << "  wrote " << a->out << "\n";
  });
}

}  // namespace rigidfold::cli
