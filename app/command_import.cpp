// rigidfold import CP.svg|CP.opx --out CP.fold [--merge-tolerance REL] [--snap-loose-ends DIST] [--json]
// Reads an SVG crease pattern in Origami Simulator's colours (kernel/pattern/svg_reader.hpp)
// or an ORIPA .opx (kernel/pattern/opx_reader.hpp, by extension) and writes it as FOLD;
// prints what the import did (segments per letter, crossings split, points merged and the
// tolerance used, ignored elements). Exit 0, or 2 on bad input.
#include <iostream>

#include "app/commands.hpp"
#include "app/number_flags.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/opx_reader.hpp"
#include "kernel/pattern/svg_reader.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {
namespace {

nlohmann::ordered_json import_json(const std::string& in, const std::string& out, const CreasePattern& p, const Topology& t,
                                   const SvgImportSummary& s) {
  using Json = nlohmann::ordered_json;
  Json j;
  j["file"] = in;
  j["out"] = out;
  Json by_letter = Json::object();
  for (int k = 0; k < 7; ++k)
    if (s.segments_by_letter[k] > 0) by_letter[std::string(1, assignment_letter(static_cast<Assignment>(k)))] = s.segments_by_letter[k];
  j["svg"] = {{"elements", s.elements},
              {"drawn_elements", s.drawn_elements},
              {"ignored_elements", s.ignored_elements},
              {"segments", s.segments},
              {"segments_by_assignment", by_letter},
              {"pattern_size", s.pattern_size},
              {"merge_tolerance", s.merge_tolerance},
              {"merge_tolerance_relative", s.merge_tolerance_relative},
              {"merged_points", s.merged_points},
              {"max_merge_distance", s.max_merge_distance},
              {"crossings_split", s.crossings},
              {"touches", s.touches},
              {"duplicate_edges", s.duplicate_edges},
              {"collinear_vertices_removed", s.collinear_vertices_removed},
              {"zero_length_segments", s.zero_length_segments},
              {"loose_end_snap", s.loose_end_snap},
              {"loose_ends_snapped", s.loose_ends_snapped},
              {"loose_ends_onto_lines", s.loose_ends_onto_lines},
              {"max_snap_distance", s.max_snap_distance}};
  Json edges = Json::object();
  for (Assignment a : p.assignments) {
    const std::string key(1, assignment_letter(a));
    edges[key] = edges.value(key, 0) + 1;
  }
  int chi = 0;
  for (const auto& c : t.components) chi += c.euler_characteristic;
  j["vertices"] = p.num_vertices();
  j["edges"] = p.num_edges();
  j["faces"] = p.num_faces();
  j["edges_by_assignment"] = edges;
  j["interior_vertices"] = t.interior_vertices.size();
  j["euler_characteristic"] = chi;
  j["warnings"] = p.warnings;
  return j;
}

void print_text(const nlohmann::ordered_json& j) {
  const auto& s = j["svg"];
  std::cout << j["file"].get<std::string>() << " -> " << j["out"].get<std::string>() << "\n";
  std::cout << "  " << s["segments"] << " segments from " << s["drawn_elements"] << " elements (" << s["segments_by_assignment"].dump()
            << "), " << s["ignored_elements"] << " elements ignored\n";
  std::cout << "  " << j["vertices"] << " vertices, " << j["edges"] << " edges " << j["edges_by_assignment"].dump() << ", "
            << j["faces"] << " faces, " << j["interior_vertices"] << " interior vertices, Euler characteristic "
            << j["euler_characteristic"] << "\n";
  std::cout << "  " << s["crossings_split"] << " crossings split, " << s["touches"] << " touching lines joined, " << s["merged_points"]
            << " points merged (tolerance " << s["merge_tolerance"].get<double>() << " = " << s["merge_tolerance_relative"].get<double>()
            << " x pattern size " << s["pattern_size"].get<double>() << "; largest move " << s["max_merge_distance"].get<double>()
            << "), " << s["duplicate_edges"] << " duplicate lines, " << s["collinear_vertices_removed"]
            << " collinear vertices removed, " << s["loose_ends_snapped"] << " loose line ends joined (snap distance "
            << s["loose_end_snap"].get<double>() << ")\n";
  for (const auto& w : j["warnings"]) std::cout << "  warning: " << w.get<std::string>() << "\n";
}

}  // namespace

void add_import_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("import", "SVG crease pattern (Origami Simulator colours) or ORIPA .opx -> FOLD");
  struct Args {
    std::string in, out;
    double merge = SvgReadOptions{}.merge_tolerance;
    double snap = SvgReadOptions{}.loose_end_snap;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->in, "crease pattern (.svg: red M, blue V, black B, yellow F, magenta U, green C; or ORIPA .opx)")->required();
  cmd->add_option("--out", a->out, "FOLD file to write")->required();
  cmd->add_option("--merge-tolerance", a->merge, "points closer than this fraction of the pattern size are one vertex (default 1e-4)")
      ->check(CLI::Range(1e-12, 0.099));
  cmd->add_option("--snap-loose-ends", a->snap,
                  "SVG: a line stopping this close (user units) short of a vertex or line is joined to it "
                  "(default 3, Origami Simulator's vertex tolerance, at most 1% of the pattern size; 0: removed as dangling)")
      ->check(finite_in(0.0, 1e9, "user units"));
  cmd->add_flag("--json", a->json, "print one JSON object");
  cmd->callback([a] {
    // The output checked against the input before any work (kernel/pattern/output_set.hpp).
    OutputSet outputs;
    outputs.add_input("PATTERN", a->in);
    outputs.add_output("--out", a->out);
    const SummaryToStderrIfStdoutIsAnOutput to_stderr(outputs);
    SvgReadOptions options;
    options.merge_tolerance = a->merge;
    options.loose_end_snap = a->snap;
    SvgImportSummary summary;
    OpxImportSummary opx;
    const CreasePattern p = is_opx_path(a->in) ? read_opx(a->in, options, &opx) : read_svg(a->in, options, &summary);
    if (is_opx_path(a->in)) summary = opx.arrangement;  // elements: the .opx's; drawn: its crease lines
    const Topology t = build_topology(p, a->in);
    outputs.stage(a->out, write_fold_string(p));
    outputs.commit();
    const auto j = import_json(a->in, a->out, p, t, summary);
    if (a->json) std::cout << document_text(j) << "\n";
    else print_text(j);
  });
}

}  // namespace rigidfold::cli
