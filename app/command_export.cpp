// rigidfold export P.fold|P.svg [--svg OUT.svg] [--dxf OUT.dxf] [--json]
// Writes a crease pattern as an SVG in Origami Simulator's colours
// (kernel/pattern/svg_writer.hpp), the inverse of `rigidfold import`, and/or as an R12 DXF
// with one layer per letter (kernel/pattern/dxf_writer.hpp); at least one of the two. A 3D
// folded form is written as its flat development (kernel/geometry/flat_development.hpp); a
// tube or a sheet with holes has none and exits 2 saying why. Exit 0, or 2 on bad input.
#include <iostream>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "kernel/geometry/flat_development.hpp"
#include "kernel/pattern/dxf_writer.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/svg_writer.hpp"

namespace rigidfold::cli {

void add_export_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("export", "crease pattern (FOLD or SVG) -> SVG in Origami Simulator's colours and/or DXF");
  struct Args {
    std::string in, svg, dxf;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->in, "crease pattern (.fold, or .svg read as `import` reads it)")->required();
  cmd->add_option("--svg", a->svg, "SVG to write: red M, blue V, black B, yellow F, magenta U, green C; opacity x 180 deg = |fold angle|");
  cmd->add_option("--dxf", a->dxf, "DXF (R12) to write: one LINE per edge on layer B, M, V, F, U or C (ACI 7, 1, 5, 2, 6, 3)");
  cmd->add_flag("--json", a->json, "print one JSON object");
  cmd->callback([a] {
    // Every output checked against the input before any work (kernel/pattern/output_set.hpp).
    OutputSet outputs;
    outputs.add_input("PATTERN", a->in);
    if (a->svg.empty() && a->dxf.empty()) throw InputError("--svg", "give --svg OUT.svg and/or --dxf OUT.dxf");
    if (!a->svg.empty()) outputs.add_output("--svg", a->svg);
    if (!a->dxf.empty()) outputs.add_output("--dxf", a->dxf);
    const SummaryToStderrIfStdoutIsAnOutput to_stderr(outputs);
    const CreasePattern p = read_pattern(a->in);
    const FlatDevelopment dev = flat_development(p, a->in);
    // dev.pattern is flat: the writers do not unfold it again.
    if (!a->svg.empty()) outputs.stage(a->svg, write_svg_string(dev.pattern, a->in));
    if (!a->dxf.empty()) outputs.stage(a->dxf, write_dxf_string(dev.pattern, a->in));
    outputs.commit();
    nlohmann::ordered_json j;
    j["file"] = a->in;
    if (!a->svg.empty()) j["svg"] = a->svg;
    if (!a->dxf.empty()) j["dxf"] = a->dxf;
    j["vertices"] = dev.pattern.num_vertices();
    j["edges"] = dev.pattern.num_edges();
    j["faces"] = dev.pattern.num_faces();
    nlohmann::ordered_json letters = nlohmann::ordered_json::object();
    for (Assignment x : dev.pattern.assignments) {
      const std::string key(1, assignment_letter(x));
      letters[key] = letters.value(key, 0) + 1;
    }
    j["edges_by_assignment"] = letters;
    j["developed_from_3d"] = dev.unfolded;
    j["development_relative_mismatch"] = dev.relative_mismatch;
    if (a->json) {
      std::cout << document_text(j) << "\n";
    } else {
      std::cout << a->in << " -> " << (a->svg.empty() ? a->dxf : a->dxf.empty() ? a->svg : a->svg + " and " + a->dxf) << "\n  " << j["vertices"] << " vertices, " << j["edges"] << " edges " << letters.dump()
                << ", " << j["faces"] << " faces";
      if (dev.unfolded) std::cout << "; 3D folded form written as its development (relative mismatch " << dev.relative_mismatch << ")";
      std::cout << "\n";
    }
  });
}

}  // namespace rigidfold::cli
