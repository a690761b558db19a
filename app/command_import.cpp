// rigidfold import CP.svg|CP.opx|CP.cp --out CP.fold [--merge-tolerance REL] [--snap-loose-ends DIST]
//                 [--strict-lines] [--json]
// Reads an SVG crease pattern in Origami Simulator's colours (kernel/pattern/svg_reader.hpp),
// an ORIPA .opx (kernel/pattern/opx_reader.hpp) or a .cp (kernel/pattern/cp_reader.hpp),
// the format chosen by the content as every command does (kernel/pattern/read_pattern.hpp;
// a FOLD file is refused: it needs no import), and writes it as FOLD; prints what the import
// did (segments per letter, crossings split, points merged and the tolerance used, ignored
// elements, lines drawn twice and merged). A piece drawn by two lines is merged by the rule of
// svg_reader.hpp ("Lines drawn twice": the later line wins, but a crease does not replace the
// outline or a cut), each pair warned and listed under "merged_lines" in --json;
// --strict-lines refuses such a file instead (two letters or fold angles on one piece).
// Exit 0, or 2 on bad input.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <numbers>

#include "app/commands.hpp"
#include "app/number_flags.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/svg_reader.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {
namespace {

// One pair of lines drawing the same piece (svg_reader.hpp, MergedLines); coordinates as the
// file gives them (SVG user units or ORIPA's, y down), fold angles in degrees (null: none).
nlohmann::ordered_json merged_lines_json(const MergedLines& m) {
  using Json = nlohmann::ordered_json;
  auto letter = [](Assignment a) { return std::string(1, assignment_letter(a)); };
  auto degrees = [](const std::optional<double>& a) { return a ? Json(*a * 180 / std::numbers::pi) : Json(nullptr); };
  Json j;
  j["lines"] = {m.first, m.second};
  j["assignments"] = {letter(m.first_letter), letter(m.second_letter)};
  j["fold_angles_deg"] = {degrees(m.first_fold_angle), degrees(m.second_fold_angle)};
  j["kept"] = letter(m.kept_letter);
  j["kept_fold_angle_deg"] = degrees(m.kept_fold_angle);
  j["rule"] = std::string(merged_lines_rule_name(m.rule));
  j["from"] = {m.from[0], m.from[1]};
  j["to"] = {m.to[0], m.to[1]};
  j["stretches"] = m.stretches;
  j["pieces"] = m.pieces;
  return j;
}

nlohmann::ordered_json import_json(const std::string& in, const std::string& out, PatternFormat format, const CreasePattern& p,
                                   const Topology& t, const SvgImportSummary& s) {
  using Json = nlohmann::ordered_json;
  Json j;
  j["file"] = in;
  j["out"] = out;
  j["format"] = std::string(pattern_format_name(format));
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
              {"overwritten_edges", s.overwritten_edges},
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
  Json merged = Json::array();
  for (const MergedLines& m : s.merged_lines) merged.push_back(merged_lines_json(m));
  j["merged_lines"] = merged;
  j["warnings"] = p.warnings;
  return j;
}

void print_import_text(const nlohmann::ordered_json& j) {
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
            << "), " << s["duplicate_edges"] << " duplicate lines, " << s["overwritten_edges"]
            << " pieces drawn in two letters (one kept, see the warnings), " << s["collinear_vertices_removed"]
            << " collinear vertices removed, " << s["loose_ends_snapped"] << " loose line ends joined (snap distance "
            << s["loose_end_snap"].get<double>() << ")\n";
  for (const auto& w : j["warnings"]) std::cout << "  warning: " << w.get<std::string>() << "\n";
}

}  // namespace

void add_import_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("import", "SVG crease pattern (Origami Simulator colours), ORIPA .opx or .cp -> FOLD");
  struct Args {
    std::string in, out;
    double merge = SvgReadOptions{}.merge_tolerance;
    double snap = SvgReadOptions{}.loose_end_snap;
    bool strict_lines = false;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->in,
                  "crease pattern (.svg: red M, blue V, black B, yellow F, magenta U, green C; ORIPA .opx; .cp); the format is "
                  "read from the content")
      ->required();
  cmd->add_option("--out", a->out, "FOLD file to write")->required();
  cmd->add_option("--merge-tolerance", a->merge, "points closer than this fraction of the pattern size are one vertex (default 1e-4)")
      ->check(CLI::Range(1e-12, 0.099));
  cmd->add_option("--snap-loose-ends", a->snap,
                  "SVG: a line stopping this close (user units) short of a vertex or line is joined to it "
                  "(default 3, Origami Simulator's vertex tolerance, at most 1% of the pattern size; 0: removed as dangling)")
      ->check(finite_in(0.0, 1e9, "user units"));
  cmd->add_flag("--strict-lines", a->strict_lines,
                "refuse a file drawing one piece of line twice in two letters or fold angles (default: the later line wins, "
                "but a crease does not replace the outline or a cut; each merge is warned)");
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
    options.strict_lines = a->strict_lines;
    const std::string text = read_input_file(a->in);
    const PatternFormat format = pattern_format_to_read(text, a->in);
    if (format == PatternFormat::Fold) {
      if (std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c); })) throw InputError(a->in, "file is empty");
      throw InputError(a->in, "a FOLD file needs no import (import reads SVG, ORIPA .opx and .cp; other commands read FOLD directly)");
    }
    // For .opx and .cp: elements are the file's, drawn elements its crease lines.
    SvgImportSummary summary;
    const CreasePattern p = parse_pattern(text, a->in, options, &summary);
    const Topology t = build_topology(p, a->in);
    outputs.stage(a->out, write_fold_string(p));
    outputs.commit();
    const auto j = import_json(a->in, a->out, format, p, t, summary);
    if (a->json) std::cout << document_text(j) << "\n";
    else print_import_text(j);
  });
}

}  // namespace rigidfold::cli
