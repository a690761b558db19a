// rigidfold report DIR --out OUTDIR: the main job. For every .fold in DIR:
//   - counts, topology, local flat-foldability (Kawasaki, Maekawa) per interior vertex;
//   - per flat-foldable degree-4 vertex, which of its two rigid folding modes agree with
//     the M/V assignment (a vertex with none is an exact local obstruction: the pattern
//     cannot fold rigidly with that assignment);
//   - where the file carries fold angles, the folded state (faces placed by spanning tree)
//     and its closure mismatch; the folded state is written to OUTDIR for the figures.
// Writes OUTDIR/report.json and OUTDIR/REPORT.md; python/plot_report.py draws the figures.
// OUTDIR must not be DIR, and no output may be one of the patterns (exit 2, nothing written).
//   - the rigid-foldability verdict (rigidfold check) with and without the assignment.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "app/terminal_progress.hpp"
#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "report/foldability_json.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/multiplier_propagation.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/flat_foldability.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

// The pattern's title: file_title, else frame_title, else the file name. FOLD says both are
// strings; one that is not is bad input, named by its key.
std::string title_of(const CreasePattern& p, const fs::path& file) {
  for (const char* key : {"file_title", "frame_title"}) {
    if (!p.extra.contains(key)) continue;
    const Json& v = p.extra.at(key);
    if (!v.is_string()) throw InputError(file.string() + ": " + key, "must be a string, found " + std::string(v.type_name()));
    return v.get<std::string>();
  }
  return file.stem().string();
}

// The folded state of `file`, if it carries fold angles, is staged in `outputs` (declared
// by the caller as out_dir/STEM.folded.fold).
Json analyse(const fs::path& file, const fs::path& out_dir, OutputSet& outputs, const ProgressSink& progress) {
  const auto start = std::chrono::steady_clock::now();
  const CreasePattern p = read_fold(file.string());
  const Topology t = build_topology(p, file.string());
  const auto ff = flat_foldability(p, t, 1e-9);
  Json j;
  j["name"] = file.stem().string();
  j["file"] = file.string();
  j["title"] = title_of(p, file);
  j["vertices"] = p.num_vertices();
  j["edges"] = p.num_edges();
  j["faces"] = p.num_faces();
  j["interior_vertices"] = t.interior_vertices.size();
  const auto& c = t.components.front();
  j["euler_characteristic"] = c.euler_characteristic;
  j["holes"] = c.holes;
  int kawasaki = 0, maekawa = 0, degree4 = 0, obstructed = 0;
  double worst_kawasaki = 0;
  Json vertices = Json::array();
  for (const auto& r : ff) {
    kawasaki += r.kawasaki;
    maekawa += r.maekawa.value_or(false);
    if (r.kawasaki_residual) worst_kawasaki = std::max(worst_kawasaki, std::fabs(*r.kawasaki_residual));
    Json v = {{"vertex", r.vertex}, {"degree", r.degree}, {"kawasaki", r.kawasaki},
              {"maekawa", r.maekawa ? Json(*r.maekawa) : Json(nullptr)}};
    const Fan& fan = t.stars[r.vertex].fans[0];
    if (fan.edges.size() == 4 && r.degree == 4 && r.kawasaki) {
      ++degree4;
      const std::vector<FlatFoldMode> modes = modes_matching_letters(p, fan);
      Json names = Json::array();
      for (FlatFoldMode m : modes) names.push_back(to_string(m));
      v["modes_matching_assignment"] = names;
      if (modes.empty() && r.unassigned == 0) ++obstructed;
    }
    vertices.push_back(v);
  }
  j["kawasaki_ok"] = kawasaki;
  j["maekawa_ok"] = maekawa;
  j["worst_kawasaki_residual_deg"] = to_degrees(worst_kawasaki);
  j["flat_foldable_degree4_vertices"] = degree4;
  j["locally_obstructed_vertices"] = obstructed;
  std::string local;
  if (obstructed > 0) local = std::to_string(obstructed) + " vertex/vertices admit no mode matching the assignment";
  else if (kawasaki == static_cast<int>(ff.size()) && maekawa == static_cast<int>(ff.size())) local = "every vertex locally flat-foldable";
  else local = "some vertices not flat-foldable";
  j["local_verdict"] = local;
  FoldabilityOptions with_letters, without_letters;
  without_letters.use_assignment = false;
  with_letters.progress = without_letters.progress = progress;
  j["check"] = report::foldability_json(check_foldability(p, t, with_letters));
  j["check_ignoring_assignment"] = report::foldability_json(check_foldability(p, t, without_letters));
  j["vertex_details"] = vertices;

  bool has_angles = false;
  for (const auto& a : p.fold_angles) has_angles = has_angles || (a && *a != 0.0);
  if (has_angles) {
    const Eigen::VectorXd rho = stored_fold_angles(p);
    const FoldedGeometry g = place_faces(p, t, rho, reference_fold_angles(p, t));
    const fs::path folded = out_dir / (file.stem().string() + ".folded.fold");
    outputs.stage(folded.string(), write_fold_string(with_folded_frame(p, g, rho, "folded by rigidfold report")));
    j["folded_file"] = folded.string();
    j["closure_mismatch"] = to_file_units(p, g.max_mismatch);  // the file's length units
    j["relative_closure_mismatch"] = g.relative_mismatch();
  }
  j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return j;
}

std::string markdown(const Json& report) {
  std::ostringstream md;
  md << "# rigidfold report\n\n";
  md << "Patterns from `" << report["input"].get<std::string>() << "`. The verdict comes from the cheapest exact model that "
        "applies: multiplier propagation where every interior vertex is a flat-foldable degree-4 vertex (a fold family "
        "with its closure residual, or a loop of vertices whose loop gain is not 1). Patterns outside that model go to "
        "the general loop-closure solver, which searches for a folded point near flat and traces it; sheets with holes "
        "(tubes) are checked from their given 3D state with one SE(3) closure per hole. Where a file carries fold angles, faces are "
        "placed by a spanning tree and the closure mismatch (relative to the pattern size) is the error of those angles.\n\n";
  md << "| pattern | V | E | F | interior | Kawasaki | Maekawa | verdict (M-V as given) | model | DOF | max residual (rad) | obstruction | verdict (M-V ignored) | local checks | closure mismatch of stored angles | time (s) |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& j : report["patterns"]) {
    md << "| " << j["name"].get<std::string>() << " | " << j["vertices"] << " | " << j["edges"] << " | " << j["faces"] << " | "
       << j["interior_vertices"] << " | " << j["kawasaki_ok"] << " | " << j["maekawa_ok"] << " | "
       << j["check"]["verdict_class"].get<std::string>() << " | " << j["check"]["model"].get<std::string>() << " | " << j["check"]["dof"]
       << " | " << j["check"]["max_residual"].get<double>() << " | "
       << (j["check"]["obstruction"].is_null() ? std::string("-") : j["check"]["obstruction"]["message"].get<std::string>()) << " | "
       << j["check_ignoring_assignment"]["verdict_class"].get<std::string>() << " | " << j["local_verdict"].get<std::string>() << " | "
       << (j.contains("relative_closure_mismatch") ? std::to_string(j["relative_closure_mismatch"].get<double>()) : "-") << " | "
       << j["seconds"].get<double>() << " |\n";
  }
  md << "\nFigures: `figures/*.png` (crease patterns, folded states, single-vertex modes).\n";
  return md.str();
}

}  // namespace

void add_report_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("report", "Main job: foldability report of every .fold in a directory");
  auto dir = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>("out/report");
  cmd->add_option("dir", *dir, "directory of .fold files")->required();
  cmd->add_option("--out", *out, "output directory (report.json, REPORT.md, folded states)");
  cmd->callback([dir, out] {
    if (!fs::is_directory(*dir)) throw InputError(*dir, "not a directory");
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(*dir))
      if (e.path().extension() == ".fold") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw InputError(*dir, "no .fold files");
    // Every output checked against every input before any work (--out may not be DIR: the
    // next run would read this run's outputs as patterns), then committed together.
    OutputSet outputs;
    outputs.add_input("DIR", *dir);
    for (const auto& f : files) outputs.add_input("DIR", f.string());
    outputs.add_output_directory("--out", *out);
    for (const auto& f : files) outputs.add_output("--out", (fs::path(*out) / (f.stem().string() + ".folded.fold")).string());
    const std::string json_path = (fs::path(*out) / "report.json").string(), md_path = (fs::path(*out) / "REPORT.md").string();
    outputs.add_output("--out", json_path);
    outputs.add_output("--out", md_path);
    Json report;
    report["input"] = *dir;
    report["patterns"] = Json::array();
    for (const auto& f : files) {
      {
        // Its line is erased before the file's summary line is printed.
        TerminalProgress progress("report, file " + std::to_string(report["patterns"].size() + 1) + " of " +
                                  std::to_string(files.size()) + " (" + f.filename().string() + ")");
        report["patterns"].push_back(analyse(f, *out, outputs, progress.sink()));
      }
      const auto& j = report["patterns"].back();
      std::cout << j["name"].get<std::string>() << ": " << j["check"]["verdict_class"].get<std::string>() << " (" << j["check"]["model"].get<std::string>()
                << "); " << j["local_verdict"].get<std::string>();
      if (j.contains("relative_closure_mismatch")) std::cout << "; folded state closure mismatch " << j["relative_closure_mismatch"].get<double>();
      std::cout << "\n";
    }
    outputs.stage(json_path, document_text(report) + "\n");
    outputs.stage(md_path, markdown(report));
    outputs.commit();
  });
}

}  // namespace rigidfold::cli
