// rigidfold thick PATTERN.fold|.svg --thickness T [--hinges top|bottom|mid|valley|bennett] [--reverse] [--json]
//                 [--out THICK.fold] [--stl FOLDED.stl --at DEG]
// The thick-panel kernel's front door (kernel/thick/thick_report.hpp): the pattern's panels
// as slabs of thickness T (file units), hinges placed as asked, mobility at the flat state
// (DOF, locked vertices, vertices off the zero-thickness motion) and, when it moves, a
// short trace from flat compared with the zero-thickness motion (first branch of
// trace_motion, up to 90 deg of its driving crease; --reverse: traced the other way from
// flat). Every state printed closes to 1e-10. Past the trace, the zero-thickness states up to
// the end of its path (180 deg where it folds flat) that close on the thick sheet as they are
// (trace.extension); slab interference (FCL) at flat, every trace step and every extension
// state (slab_interference: passed, margin, first colliding pair with its state, driving
// angle and shared crease); the stacking order at the end of that path (stacking: per crease
// which side each panel lies on and whether that is its letter's; folded flat: the panels
// bottom to top with their layers and the least gap between overlapping ones). Every check
// lives in the kernel (kernel/thick/thick_run.hpp): this file parses, calls run_thick, prints.
//
// --out writes the thick sheet (thick_sheet_from_hinge_heights: vertices truncated into
// holes, hinge edges 0..E-1 at their heights, 3D) as FOLD with two extension keys:
//   "rigidfold:thickness":      one number per face of the sheet, its panel's slab thickness
//                               (top - bottom, file units; kernel/thick/thick_slabs.hpp);
//   "rigidfold:hinge_heights":  one entry per edge of the sheet: the height (z at the flat
//                               state, file units) of the hinge of edges 0..E-1 (the input's
//                               edges, same order), null for the cut edges after them.
// --stl writes the panels as closed slabs at the state where the driving crease is at --at
// degrees on the traced thick motion (binary STL, kernel/geometry/folded_output.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/number_flags.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_report.hpp"
#include "kernel/thick/thick_run.hpp"
#include "kernel/thick/thick_slabs.hpp"

namespace rigidfold::cli {

namespace {

ThickHinges parse_hinges(const std::string& text) {
  if (text == "top") return ThickHinges::kTop;
  if (text == "bottom") return ThickHinges::kBottom;
  if (text == "mid") return ThickHinges::kMid;
  if (text == "valley") return ThickHinges::kValley;
  if (text == "bennett") return ThickHinges::kBennett;
  throw InputError("--hinges", "'" + text + "' is not one of top, bottom, mid, valley, bennett");
}

nlohmann::ordered_json fold_angles_deg(const Eigen::VectorXd& rho) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (Eigen::Index e = 0; e < rho.size(); ++e) a.push_back(to_degrees(rho[e]));
  return a;
}

const char* side_name(int side) { return side > 0 ? "top" : (side < 0 ? "bottom" : "level"); }

// Slab interference along flat + trace + extension (kernel/thick/slab_interference.hpp).
nlohmann::ordered_json interference_json(const CreasePattern& p, const ThickReport& r) {
  const SlabInterference& in = r.interference;
  nlohmann::ordered_json j;
  j["passed"] = in.passed();
  j["margin"] = to_file_units(p, in.margin);
  j["states_checked"] = in.states.size();
  int colliding = 0;
  for (const SlabInterferenceState& s : in.states) colliding += s.collisions.empty() ? 0 : 1;
  j["colliding_states"] = colliding;
  j["collisions"] = in.collision_count;
  if (in.first_state >= 0) {
    const SlabInterferenceState& s = in.states[in.first_state];
    const SlabCollision& c = s.collisions.front();
    nlohmann::ordered_json first;
    first["state"] = in.first_state;
    first["drive_deg"] = to_degrees(s.drive);
    first["faces"] = {c.face_a, c.face_b};
    first["shared_crease"] = c.shared_edge >= 0 ? nlohmann::ordered_json(c.shared_edge) : nlohmann::ordered_json();
    // The state's fold angles: flat (0), then the trace, then the extension.
    const int k = in.first_state;
    const int nt = static_cast<int>(r.trace.size());
    const Eigen::VectorXd* rho = k == 0 ? nullptr : (k - 1 < nt ? &r.trace[k - 1].rho : &r.extension[k - 1 - nt].rho);
    first["shared_crease_fold_deg"] =
        c.shared_edge >= 0 ? nlohmann::ordered_json(rho ? to_degrees((*rho)[c.shared_edge]) : 0.0) : nlohmann::ordered_json();
    j["first"] = first;
  }
  nlohmann::ordered_json per = nlohmann::ordered_json::array();
  for (const SlabInterferenceState& s : in.states) {
    nlohmann::ordered_json pairs = nlohmann::ordered_json::array();
    for (const SlabCollision& c : s.collisions)
      pairs.push_back({c.face_a, c.face_b, c.shared_edge >= 0 ? nlohmann::ordered_json(c.shared_edge) : nlohmann::ordered_json()});
    per.push_back({{"drive_deg", to_degrees(s.drive)}, {"pairs", pairs}});
  }
  j["states"] = per;
  return j;
}

// Stacking at the end of the path (kernel/thick/stacking_order.hpp).
nlohmann::ordered_json stacking_json(const CreasePattern& p, const ThickReport& r) {
  const StackingOrder& st = r.stacking;
  nlohmann::ordered_json j;
  j["at_drive_deg"] = to_degrees(r.end.drive);
  j["end_of"] = r.end_is_extension ? "extension" : (r.trace.empty() ? "flat state" : "trace");
  j["flat_folded"] = st.flat_folded;
  j["max_tilt_rad"] = st.max_tilt;
  j["letter_disagreements"] = st.letter_disagreements;
  nlohmann::ordered_json creases = nlohmann::ordered_json::array();
  for (const CreaseStacking& c : st.creases) {
    nlohmann::ordered_json e;
    e["edge"] = c.edge;
    e["faces"] = {c.face_a, c.face_b};
    e["b_side_of_a"] = side_name(c.b_side_of_a);
    e["a_side_of_b"] = side_name(c.a_side_of_b);
    e["agrees_with_letter"] = c.has_letter ? nlohmann::ordered_json(c.agrees_with_letter) : nlohmann::ordered_json();
    creases.push_back(e);
  }
  j["creases"] = creases;
  if (st.flat_folded) {
    j["layers"] = st.layers;
    nlohmann::ordered_json panels = nlohmann::ordered_json::array();
    for (const StackedPanel& s : st.panels)
      panels.push_back({{"face", s.face}, {"layer", s.layer}, {"low", to_file_units(p, s.low)}, {"high", to_file_units(p, s.high)}});
    j["panels_bottom_to_top"] = panels;
    j["overlapping_pairs"] = st.overlaps.size();
    j["min_gap"] = to_file_units(p, st.min_gap);
  }
  return j;
}

}  // namespace

void add_thick_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("thick", "Thick panels: hinge placement, mobility, locked vertices, trace against zero thickness");
  struct Args {
    std::string pattern, hinges = "bennett", out, stl;
    double thickness = 0, at = 0;
    bool json = false, reverse = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold, or .svg in Origami Simulator's colours)")->required();
  cmd->add_option("--thickness", a->thickness, "panel thickness (> 0, the pattern's length units)")->required();
  cmd->add_option("--hinges", a->hinges,
                  "hinge placement: top, bottom or mid (every hinge on that face), valley (on the face each crease folds towards: "
                  "top for V, bottom for M), bennett (Bennett heights that keep the zero-thickness motion; default)");
  cmd->add_option("--out", a->out, "write the thick sheet as FOLD (rigidfold:thickness per face, rigidfold:hinge_heights per edge)");
  auto* stl = cmd->add_option("--stl", a->stl, "write the panels as closed slabs at --at as binary STL");
  auto* at = cmd->add_option("--at", a->at, "driving crease's fold angle for --stl (degrees, within the traced thick motion)")
                 ->check(finite_in(-180, 180, "degrees"));
  stl->needs(at);
  at->needs(stl);
  cmd->add_flag("--reverse", a->reverse,
                "compare with the zero-thickness motion traced the other way from flat (against the letters)");
  cmd->add_flag("--json", a->json, "print JSON (numbers round-trip exactly)");
  cmd->callback([a] {
    const ThickHinges hinges = parse_hinges(a->hinges);
    OutputSet outputs;
    outputs.add_input("PATTERN", a->pattern);
    if (!a->out.empty()) outputs.add_output("--out", a->out);
    if (!a->stl.empty()) outputs.add_output("--stl", a->stl);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    const CreasePattern p = read_pattern(a->pattern);
    const Topology t = build_topology(p, a->pattern);

    ThickRunRequest run_request;
    run_request.thickness = a->thickness;
    run_request.hinges = hinges;
    run_request.reverse = a->reverse;
    if (!a->stl.empty()) run_request.slabs_at = to_radians(a->at);
    ThickRun run;
    try {
      run = run_thick(p, t, run_request);
    } catch (const InputError& e) {
      const std::string what = e.message();
      if (e.place() == "thickness") throw InputError("--thickness", what);
      if (e.place() == "hinges") throw InputError("--hinges", what);
      if (e.place() == "pattern") throw InputError(a->pattern, what);
      if (e.place() == "at") throw InputError("--at", what);
      throw;
    }
    const ThickReportRequest& request = run.request;
    const ThickReport& r = run.report;
    const std::vector<PanelSlab>& slabs = r.slabs;

    nlohmann::ordered_json j;
    j["file"] = a->pattern;
    j["thickness"] = a->thickness;
    j["hinges"] = to_string(hinges);
    nlohmann::ordered_json heights = nlohmann::ordered_json::array();
    for (double h : r.edge_heights) heights.push_back(to_file_units(p, h));
    j["hinge_heights"] = heights;
    const ThickMobilityReport& m = r.mobility;
    nlohmann::ordered_json mob;
    mob["dof"] = m.dof;
    mob["rank_cut"] = m.rank.threshold;
    mob["smallest_kept_singular_value"] = m.rank.sigma_kept;
    mob["largest_dropped_singular_value"] = m.rank.sigma_dropped;
    mob["flat_state_residual"] = m.state_residual;
    mob["locked_vertices"] = m.locked_vertices;
    mob["off_motion_vertices"] = m.off_motion_vertices;
    nlohmann::ordered_json vertices = nlohmann::ordered_json::array();
    for (const ThickVertexMobility& v : m.vertices)
      vertices.push_back({{"vertex", v.vertex}, {"creases", v.creases}, {"dof_alone", v.dof_alone}, {"off_motion_residual", v.off_motion}});
    mob["vertices"] = vertices;
    j["flat_state"] = mob;
    nlohmann::ordered_json zero;
    zero["driving_crease"] = request.zero.drive;
    zero["direction"] = a->reverse ? "against the letters" : "the letters' way";
    zero["states"] = request.zero.states.size();
    zero["max_residual"] = request.zero.max_residual;
    if (!request.zero.note.empty()) zero["note"] = request.zero.note;
    j["zero_thickness"] = zero;
    nlohmann::ordered_json trace;
    trace["driving_crease"] = r.drive;
    trace["max_deviation_rad"] = r.max_deviation;
    trace["max_residual"] = r.max_trace_residual;
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (const ThickTraceStep& s : r.trace)
      steps.push_back({{"drive_deg", to_degrees(s.drive)},
                       {"residual", s.residual},
                       {"deviation_rad", s.deviation},
                       {"worst_edge", s.worst_edge},
                       {"dof", s.dof},
                       {"fold_angles_deg", fold_angles_deg(s.rho)}});
    trace["steps"] = steps;
    if (!r.trace_note.empty()) trace["note"] = r.trace_note;
    nlohmann::ordered_json extension = nlohmann::ordered_json::array();
    for (const ThickTraceStep& s : r.extension)
      extension.push_back({{"drive_deg", to_degrees(s.drive)}, {"residual", s.residual}});
    trace["extension"] = extension;
    j["trace"] = trace;
    j["slab_interference"] = interference_json(p, r);
    j["stacking"] = stacking_json(p, r);

    if (!a->out.empty()) {
      nlohmann::ordered_json doc = fold_to_json(r.sheet.pattern);
      nlohmann::ordered_json per_face = nlohmann::ordered_json::array();
      for (int f : r.sheet.flat_face_of_face) per_face.push_back(to_file_units(p, slabs[f].top - slabs[f].bottom));
      doc["rigidfold:thickness"] = per_face;
      nlohmann::ordered_json per_edge = nlohmann::ordered_json::array();
      for (int e = 0; e < r.sheet.pattern.num_edges(); ++e)
        per_edge.push_back(e < p.num_edges() ? nlohmann::ordered_json(to_file_units(p, r.edge_heights[e])) : nlohmann::ordered_json());
      doc["rigidfold:hinge_heights"] = per_edge;
      outputs.stage(a->out, dump_fold_json(doc));
      j["out"] = a->out;
    }
    if (run.at) {
      const ThickSlabsAt& at = *run.at;
      outputs.stage(a->stl, polygons_stl(at.polygons, p.length_exponent, "rigidfold thick panels (binary STL)"));
      nlohmann::ordered_json s;
      s["file"] = a->stl;
      s["drive_deg"] = a->at;
      s["residual"] = at.state.residual;
      s["relative_mismatch"] = at.placed.relative_mismatch();
      s["dof"] = at.state.dof;
      s["fold_angles_deg"] = fold_angles_deg(at.state.rho);
      j["stl"] = s;
    }
    outputs.commit();

    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    char line[320];
    std::snprintf(line, sizeof line, "%s: thickness %.9g, hinges %s\n", a->pattern.c_str(), a->thickness, to_string(hinges));
    std::cout << line;
    std::snprintf(line, sizeof line, "  flat state: DOF %d (smallest kept singular value %.3g, cut %.3g), %zu locked vertex(es), %zu off the zero-thickness motion\n",
                  m.dof, m.rank.sigma_kept, m.rank.threshold, m.locked_vertices.size(), m.off_motion_vertices.size());
    std::cout << line;
    for (const ThickVertexMobility& v : m.vertices)
      if (v.dof_alone == 0 || v.off_motion > request.closure_tolerance) {
        std::snprintf(line, sizeof line, "    vertex %d: %s, off the zero-thickness motion by %.3g\n", v.vertex,
                      v.dof_alone == 0 ? "locked alone" : "mobile alone", v.off_motion);
        std::cout << line;
      }
    if (!r.trace.empty()) {
      std::snprintf(line, sizeof line, "  trace: crease %d to %.6g deg in %zu steps, largest |rho_thick - rho_zero| %.3g rad, closure <= %.3g rad\n",
                    r.drive, to_degrees(r.trace.back().drive), r.trace.size(), r.max_deviation, r.max_trace_residual);
      std::cout << line;
    }
    if (!r.trace_note.empty()) std::cout << "  " << r.trace_note << "\n";
    if (!r.extension.empty()) {
      std::snprintf(line, sizeof line, "  extension: %zu zero-thickness state(s) past the trace close on the thick sheet, to %.6g deg\n",
                    r.extension.size(), to_degrees(r.extension.back().drive));
      std::cout << line;
    }
    const SlabInterference& in = r.interference;
    if (in.passed()) {
      std::snprintf(line, sizeof line, "  slab interference: none at %zu states (margin %.3g)\n", in.states.size(),
                    to_file_units(p, in.margin));
    } else {
      const SlabInterferenceState& s = in.states[in.first_state];
      const SlabCollision& c = s.collisions.front();
      std::snprintf(line, sizeof line,
                    "  slab interference: %lld collision(s) over %zu states; first at %.6g deg: panels %d and %d%s%s\n",
                    in.collision_count, in.states.size(), to_degrees(s.drive), c.face_a, c.face_b,
                    c.shared_edge >= 0 ? " across crease " : " (no shared crease)",
                    c.shared_edge >= 0 ? std::to_string(c.shared_edge).c_str() : "");
    }
    std::cout << line;
    const StackingOrder& st = r.stacking;
    if (st.flat_folded)
      std::snprintf(line, sizeof line,
                    "  stacking at %.6g deg (folded flat): %d layer(s), %zu overlapping pair(s), least gap %.3g, %d crease(s) against their letter\n",
                    to_degrees(r.end.drive), st.layers, st.overlaps.size(), to_file_units(p, st.min_gap), st.letter_disagreements);
    else
      std::snprintf(line, sizeof line, "  stacking at %.6g deg (not folded flat, tilt %.3g rad): %d crease(s) against their letter\n",
                    to_degrees(r.end.drive), st.max_tilt, st.letter_disagreements);
    std::cout << line;
    if (!a->out.empty()) std::cout << "  thick sheet written to " << a->out << "\n";
    if (!a->stl.empty()) std::cout << "  slabs at " << a->at << " deg written to " << a->stl << "\n";
  });
}

}  // namespace rigidfold::cli
