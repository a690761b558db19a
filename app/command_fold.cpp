// rigidfold fold PATTERN.fold --angles ANGLES.json --out FOLDED.fold [--obj FOLDED.obj] [--stl FOLDED.stl] [--json]
// Places the faces for the given fold angles and reports the closure mismatch.
// ANGLES.json: {"<edge index>": degrees, ...} or an array with one entry (or null) per edge.
// Creases not listed keep the pattern's edges_foldAngle (0 where it has none).
#include <cmath>
#include <iostream>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/summary_stream.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/geometry/fold_angles_input.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {

void add_fold_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("fold", "Fold a pattern to given fold angles; write the folded state and report closure mismatch");
  struct Args {
    std::string pattern, angles, out, obj, stl;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold)")->required();
  cmd->add_option("--angles", a->angles, "JSON: {\"edge\": degrees} or array of degrees per edge")->required();
  cmd->add_option("--out", a->out, "output FOLD with a foldedForm frame")->required();
  cmd->add_option("--obj", a->obj, "also write the folded faces as OBJ");
  cmd->add_option("--stl", a->stl, "also write the folded faces as binary STL (triangulated, float32)");
  cmd->add_flag("--json", a->json, "print the report as JSON");
  cmd->callback([a] {
    // Every path checked against the others before any work; both outputs committed together.
    OutputSet outputs;
    outputs.add_input("PATTERN", a->pattern);
    outputs.add_input("--angles", a->angles);
    outputs.add_output("--out", a->out);
    if (!a->obj.empty()) outputs.add_output("--obj", a->obj);
    if (!a->stl.empty()) outputs.add_output("--stl", a->stl);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    const CreasePattern p = read_fold(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    const Eigen::VectorXd rho = read_fold_angles_json(a->angles, p, t);
    const FoldedGeometry g = place_faces(p, t, rho, reference_fold_angles(p, t));
    outputs.stage(a->out, write_fold_string(with_folded_frame(p, g, rho, "folded by rigidfold")));
    if (!a->obj.empty()) outputs.stage(a->obj, folded_obj(p, g));
    if (!a->stl.empty()) outputs.stage(a->stl, folded_stl(p, g));
    outputs.commit();
    nlohmann::ordered_json j;
    j["pattern"] = a->pattern;
    j["out"] = a->out;
    j["closure_mismatch"] = to_file_units(p, g.max_mismatch);  // the file's length units
    j["relative_mismatch"] = g.relative_mismatch();
    j["worst_edge"] = g.worst_edge;
    j["non_tree_hinges"] = g.non_tree_hinges;
    if (a->json) {
      std::cout << document_text(j) << "\n";
    } else {
      std::cout << "folded " << a->pattern << " -> " << a->out << (a->obj.empty() ? "" : " and " + a->obj) << (a->stl.empty() ? "" : " and " + a->stl) << "\n";
      std::cout << "  closure mismatch " << to_file_units(p, g.max_mismatch) << " (relative " << g.relative_mismatch() << ") over "
                << g.non_tree_hinges << " non-tree hinges";
      if (g.worst_edge >= 0) std::cout << ", worst at edge " << g.worst_edge;
      std::cout << "\n";
    }
  });
}

}  // namespace rigidfold::cli
