// rigidfold trace PATTERN.fold [--branch ID|all] [--drive EDGE] [--to DEG] [--steps N]
//                [--out FRAMES.fold] [--csv ANGLES.csv] [--json] [--ignore-assignment] [--general]
// Traces a folding motion of a pattern, driven by one crease, at N equally spaced driving
// angles (to*k/N, k = 1..N; the flat state is the key frame, not a step).
//
// Model (docs/DESIGN.md, "Model only what a scene needs"):
//   - multiplier propagation when it applies and the verdict is foldable: the motion is the
//     fold family tan(rho_e/2) = m_e * t_c, one branch per family component c (exact);
//   - otherwise (or with --general) the general loop-closure solver: a start by Newton
//     projection from a small fold of the driving crease (held), 1-DOF pseudo-arclength
//     continuation to the target, then at every driving angle a projection with the driving
//     crease held. One branch (id 0). If the DOF at the start is not 1, it says so and
//     traces nothing (exit 0; 3 if --out or --csv was asked). With --branch ID|all: every
//     branch through the flat state and
//     the bifurcations (kernel/analysis/branch_explorer.hpp), each traced to its end, steps at
//     the continuation's points; --to / --steps / --drive do not apply there.
//   - a sheet with holes (a tube): the two branches through its given 3D state, traced with
//     the SE(3) hole closures (kernel/analysis/reference_mobility.hpp); the given state is
//     the first step; branch 0 by default, --branch 1|all for the other; --to / --steps /
//     --drive do not apply.
//   - applicable but not foldable (for the assignment, or in any mode with
//     --ignore-assignment): nothing to trace; the obstruction is reported (exit 0).
//   - a thick FOLD (rigidfold thick --out; extension keys rigidfold:thickness and
//     rigidfold:hinge_heights): the thick model (kernel/thick/thick_check.hpp), its motion from
//     the flat state traced with the SE(3) closure of every thick vertex; --drive, --to, --steps
//     apply; --branch, --out, --csv are refused (exit 2).
//   Nothing traced while --out or --csv was asked for: exit 3 (no answer within tolerance),
//   each branch's reason and residual on stderr, no file written.
// Per step: every fold angle, the largest vertex-closure residual |log R_v| (rad), the
// face-placement closure mismatch (length units), and events:
//   "interference:eK"  crease K reaches +-180 deg (local interference limit);
//   "mv_switch:eK"     M/V crease K changes sign against its letter: starts folding against
//                      it (also at step 1 if it starts so) or returns to it;
//   "sign_change:eK"   U crease K changes sign.
// Outputs (kernel/pattern/output_set.hpp: paths checked against the pattern and each other
// before the work, all rendered and staged, then committed together):
//   --out  FOLD: the pattern as key frame plus one foldedForm frame per step;
//   --csv  step,drive_deg,max_residual_rad,mismatch,events,e0_deg,e1_deg,...
//   With several branches (--branch all) each file gets ".b<ID>" before its extension; a
//   stream (-, /dev/null, a FIFO) gets every branch in turn.
// Bad flags (--drive out of range / not a foldable crease / flat in the family, |--to| > 180
// or 0, --steps < 1, unknown branch) exit 2 naming the flag; no file is written.
// The motion itself comes from the kernel (kernel/analysis/trace_motion.hpp); this file
// parses the flags, renders the outputs and prints.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "app/terminal_progress.hpp"
#include "app/thick_flags.hpp"
#include "app/commands.hpp"
#include "app/number_flags.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_check.hpp"

namespace rigidfold::cli {
namespace {

using Json = nlohmann::ordered_json;

// ---- outputs ----------------------------------------------------------------------------

std::string branch_path(const std::string& path, int id, bool several) {
  if (!several) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + ".b" + std::to_string(id) + p.extension().string())).string();
}

// Mismatch in the file's length units (a rescaled pattern, length_scale.hpp, reports as read).
std::string csv_text(const MotionBranch& b, const CreasePattern& p) {
  const int num_edges = p.num_edges();
  std::string s = "step,drive_deg,max_residual_rad,mismatch,events";
  for (int e = 0; e < num_edges; ++e) {
    s += ",e";
    s += std::to_string(e);
    s += "_deg";
  }
  s += "\n";
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    const MotionStep& st = b.steps[k];
    std::string ev;
    for (const MotionEvent& x : st.events) {
      if (!ev.empty()) ev += ';';
      ev += std::string(to_string(x.kind)) + ":e" + std::to_string(x.edge);
    }
    s += std::to_string(k + 1) + "," + round_trip_text(to_degrees(st.drive)) + "," + round_trip_text(st.residual) + "," +
         round_trip_text(to_file_units(p, st.folded.max_mismatch)) + "," + ev;
    for (int e = 0; e < num_edges; ++e) {
      s += ',';
      s += round_trip_text(to_degrees(st.rho[e]));
    }
    s += "\n";
  }
  return s;
}

std::string frames_text(const MotionBranch& b, const CreasePattern& p) {
  CreasePattern out = p;
  CreasePattern bare = p;
  bare.extra.erase("file_frames");
  if (!out.extra.contains("file_frames")) out.extra["file_frames"] = Json::array();
  for (std::size_t k = 0; k < b.steps.size(); ++k) {
    const MotionStep& st = b.steps[k];
    const std::string title = "rigidfold trace: branch " + std::to_string(b.id) + ", step " + std::to_string(k + 1) +
                              ", crease " + std::to_string(b.drive) + " at " + degrees_text(st.drive) + " deg";
    CreasePattern one = with_folded_frame(bare, st.folded, st.rho, title);
    Json frame = one.extra["file_frames"].back();
    frame["rigidfold:max_residual_rad"] = st.residual;
    out.extra["file_frames"].push_back(std::move(frame));
  }
  return write_fold_string(out);
}

Json branch_json(const MotionBranch& b, const CreasePattern& p) {
  Json j;
  j["branch"] = b.id;
  j["traced"] = b.traced;
  j["driving_crease"] = b.drive;
  j["drive_assignment"] = b.drive >= 0 ? std::string(1, assignment_letter(p.assignments[b.drive])) : std::string();
  j["to_deg"] = to_degrees(b.to);
  j["reached_deg"] = b.traced ? Json(to_degrees(b.reached)) : Json(nullptr);
  j["steps"] = b.steps.size();
  if (b.dof >= 0) j["dof_at_start"] = b.dof;
  j["stop_reason"] = to_string(b.stop);
  j["stopped_by"] = b.stopped_by;
  j["max_residual"] = b.max_residual;
  j["max_mismatch"] = to_file_units(p, b.max_mismatch);  // the file's length units
  // The general solver's corrector (null: the branch did not run its continuation).
  j["linear_solver"] = b.linear_solver.empty() ? Json(nullptr) : Json(b.linear_solver);
  if (!b.linear_solver.empty()) j["factorizations"] = b.continuation.factorizations;
  Json ev = Json::array();
  for (const MotionEvent& e : b.events)
    ev.push_back({{"step", e.step}, {"kind", to_string(e.kind)}, {"edge", e.edge}, {"drive_deg", to_degrees(e.drive)},
                  {"angle_deg", to_degrees(e.angle)}});
  j["events"] = ev;
  j["message"] = b.message;
  return j;
}

std::optional<int> parse_branch_id(const std::string& text) {
  std::size_t used = 0;
  int id = -1;
  try {
    id = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || id < 0) throw InputError("--branch", "must be a branch id (0, 1, ...) or 'all'");
  return id;
}

// --steps within the documented limits (kernel/pattern/input_limits.hpp), checked before any
// step is computed: every step keeps its fold angles, placed vertices and face motions, and
// --out writes them all.
void check_steps(int steps, const CreasePattern& p) {
  if (steps < 1 || steps > kMaxTraceSteps)
    throw InputError("--steps", "must be between 1 and " + std::to_string(kMaxTraceSteps));
  const std::int64_t per_step = p.num_edges() + 3 * std::int64_t{p.num_vertices()} + 16 * std::int64_t{p.num_faces()};
  const std::int64_t most = std::max<std::int64_t>(1, kMaxTraceStepValues / per_step);
  if (steps > most)
    throw InputError("--steps", std::to_string(steps) + " steps of this pattern (" + std::to_string(p.num_edges()) + " edges, " +
                                    std::to_string(p.num_faces()) + " faces) would store " + std::to_string(steps * per_step) +
                                    " values, over the limit of " + std::to_string(kMaxTraceStepValues) + "; use at most " +
                                    std::to_string(most) + " steps");
}

// The kernel names the request's field ("drive"); the user typed the flag ("--drive").
MotionTrace trace_with_flag_names(const CreasePattern& p, const Topology& t, const TraceRequest& rq,
                                  const std::string& file) {
  try {
    return trace_motion(p, t, rq);
  } catch (const InputError& e) {
    const std::string what = e.message();
    throw InputError(e.place().empty() ? file : "--" + e.place(), what);
  }
}

// Why nothing was traced, branch by branch, with the residual each reached.
std::string nothing_traced_text(const MotionTrace& m) {
  std::string s = "nothing traced, so no --out/--csv written";
  if (!m.note.empty()) s += "; " + m.note;
  for (const MotionBranch& b : m.branches) {
    s += "; branch " + std::to_string(b.id) + ": " + (b.message.empty() ? std::string(to_string(b.stop)) : b.message);
    s += " (max closure residual " + round_trip_text(b.max_residual) + " rad)";
  }
  if (m.branches.empty()) s += "; no branch";
  return s;
}

void print_text(const std::string& file, const CreasePattern& p, const MotionTrace& m,
                const std::vector<std::pair<std::string, std::string>>& files) {
  std::cout << file << ": model " << m.model_name << "\n";
  if (!m.note.empty()) std::cout << "  " << m.note << "\n";
  std::cout << "  precision: " << m.coordinate_precision << "\n";
  for (const MotionBranch& b : m.branches) {
    std::cout << "  branch " << b.id << ": drive crease " << b.drive << " to " << degrees_text(b.to) << " deg";
    if (!b.traced) {
      std::cout << ": not traced\n    " << b.message << "\n";
      continue;
    }
    std::cout << ", " << b.steps.size() << " steps to " << degrees_text(b.reached) << " deg (" << b.stopped_by << ")\n";
    std::cout << "    max closure residual " << b.max_residual << " rad, max face-placement mismatch " << to_file_units(p, b.max_mismatch)
              << "\n";
    for (const MotionEvent& e : b.events)
      std::cout << "    step " << e.step << ": " << to_string(e.kind) << " at crease " << e.edge << " (drive "
                << degrees_text(e.drive) << " deg, crease " << degrees_text(e.angle) << " deg)\n";
    if (!b.message.empty()) std::cout << "    " << b.message << "\n";
  }
  for (const auto& f : files) std::cout << "  wrote " << f.first << "\n";
}

}  // namespace

void add_trace_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("trace", "Trace a folding branch: fold angles, closure residual and events per step");
  struct Args {
    std::string pattern, branch, out, csv;
    std::optional<int> drive;
    std::optional<double> to;
    int steps = 50;
    bool json = false, ignore = false, general = false;
    std::string tolerance = "auto";
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold, or .svg in Origami Simulator's colours)")->required();
  cmd->add_option("--branch", a->branch, "branch id (multiplier model: one per family component) or 'all'");
  cmd->add_option("--drive", a->drive, "driving crease (edge index); default: largest multiplier of the branch");
  cmd->add_option("--to", a->to, "final fold of the driving crease, deg in [-180, 180], not 0; default 170 in its assigned direction");
  cmd->add_option("--steps", a->steps, "number of equally spaced driving angles (default 50)");
  cmd->add_option("--out", a->out, "multi-frame FOLD: key frame plus one foldedForm frame per step");
  cmd->add_option("--csv", a->csv, "CSV: step,drive_deg,max_residual_rad,mismatch,events,e0_deg,...");
  cmd->add_flag("--json", a->json, "print the summary as JSON");
  cmd->add_flag("--ignore-assignment", a->ignore, "ignore the M-V assignment (any signs)");
  cmd->add_flag("--general", a->general, "force the general loop-closure solver");
  CLI::Option* tolerance_option = cmd->add_option("--tolerance", a->tolerance,
                  "how far each coordinate may lie from the true one, in the file's length unit: auto (default: read off "
                  "the input), exact, or a number >= 0 (as check --tolerance)");
  cmd->callback([a, tolerance_option] {
    // Every path checked against the others before any work; all outputs committed together.
    OutputSet outputs;
    outputs.add_input("PATTERN", a->pattern);
    if (!a->out.empty()) outputs.add_output("--out", a->out);
    if (!a->csv.empty()) outputs.add_output("--csv", a->csv);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    const CreasePattern p = read_pattern(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    check_steps(a->steps, p);
    if (a->to && (!std::isfinite(*a->to) || std::fabs(*a->to) > 180.0))
      throw InputError("--to", "fold angle must be finite and within [-180, 180] deg");
    if (is_thick_fold(p)) {  // `rigidfold thick --out`'s FOLD: traced with the thick model (kernel/thick/thick_check.hpp)
      if (!a->out.empty() || !a->csv.empty()) throw InputError(a->out.empty() ? "--csv" : "--out", "not written for a thick FOLD (its trace is printed; rigidfold thick --stl writes slabs)");
      if (!a->branch.empty()) throw InputError("--branch", "a thick FOLD has one traced motion (no branches)");
      refuse_flags_a_thick_fold_ignores({a->ignore, a->general, tolerance_option->count() > 0});
      ThickCheckRequest tq{a->drive, a->to ? std::optional<double>(to_radians(*a->to)) : std::nullopt, a->steps};
      tq.drive_place = "--drive", tq.to_place = "--to", tq.steps_place = "--steps";
      const ThickCheckReport r = thick_check(p, t, tq);
      Json j = {{"file", a->pattern}};
      j.update(thick_check_json(p, r, true));
      std::cout << (a->json ? document_text(j) + "\n" : a->pattern + ": " + to_string(r.verdict_class) + " (model: thick; as a mechanism: " + r.verdict + ")\n" + thick_check_text(p, r, true));
      return;
    }
    TraceRequest rq;
    rq.use_assignment = !a->ignore;
    rq.force_general = a->general;
    rq.all_branches = a->branch == "all";
    if (!a->branch.empty() && !rq.all_branches) rq.branch = parse_branch_id(a->branch);
    rq.drive = a->drive;
    if (a->to) rq.to = to_radians(*a->to);
    rq.steps = a->steps;
    rq.coordinate_tolerance = coordinate_tolerance_flag("--tolerance", a->tolerance);
    const MotionTrace m = [&] {
      TerminalProgress progress("trace");  // its line is erased before anything is printed
      rq.progress = progress.sink();
      return trace_with_flag_names(p, t, rq, a->pattern);
    }();

    // Files were asked for and no branch was traced: no answer (exit 3), nothing written.
    const bool wants_files = !a->out.empty() || !a->csv.empty();
    if (wants_files && std::none_of(m.branches.begin(), m.branches.end(), [](const MotionBranch& b) { return b.traced; }))
      throw NoAnswerError(nothing_traced_text(m));
    // Several branches: one file each (".b<ID>", declared and checked now), or, for a stream
    // target (-, a device, a FIFO), every branch in turn. Committed once all are rendered.
    const bool several = m.branches.size() > 1;
    std::vector<std::pair<std::string, std::string>> files;  // (path, flag) in the order written
    for (const MotionBranch& b : m.branches) {
      if (!b.traced) continue;
      for (const auto& [flag, base] : {std::pair<std::string, std::string>{"--out", a->out}, {"--csv", a->csv}}) {
        if (base.empty()) continue;
        std::string path = base;
        if (several && !outputs.writes_in_place(base)) {
          path = branch_path(base, b.id, true);
          outputs.add_output(flag, path);
        }
        outputs.stage(path, flag == "--out" ? frames_text(b, p) : csv_text(b, p));
        if (std::find_if(files.begin(), files.end(), [&](const auto& f) { return f.first == path; }) == files.end())
          files.emplace_back(path, flag);
      }
    }
    outputs.commit();

    Json j = {{"file", a->pattern}};
    j["assignment"] = a->ignore ? "ignored" : "as given (sign constraints)";
    j["model"] = m.model_name;
    j["note"] = m.note;
    j["coordinate_precision"] = m.coordinate_precision;
    bool traced = !m.branches.empty();
    for (const MotionBranch& b : m.branches) traced = traced && b.traced;
    j["traced"] = traced;
    Json bj = Json::array();
    double max_res = 0, max_mis = 0;
    for (const MotionBranch& b : m.branches) {
      bj.push_back(branch_json(b, p));
      max_res = std::max(max_res, b.max_residual);
      max_mis = std::max(max_mis, b.max_mismatch);
    }
    j["max_residual"] = max_res;
    j["max_mismatch"] = to_file_units(p, max_mis);
    if (m.branches.size() == 1)
      for (const char* key : {"branch", "driving_crease", "to_deg", "reached_deg", "steps", "stopped_by", "events", "message"})
        j[key] = bj[0][key];
    j["branches"] = bj;
    Json outs = Json::array();
    for (const auto& f : files) outs.push_back(f.first);
    j["outputs"] = outs;
    if (a->json) {
      std::cout << document_text(j) << "\n";
      return;
    }
    print_text(a->pattern, p, m, files);
  });
}

}  // namespace rigidfold::cli
