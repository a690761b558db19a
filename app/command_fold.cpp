// rigidfold fold PATTERN.fold --angles ANGLES.json --out FOLDED.fold [--obj FOLDED.obj] [--stl FOLDED.stl] [--json]
// rigidfold fold PATTERN.fold --target T.json|T.fold [--hold E,...] --out FOLDED.fold [...]
// Places the faces for the given fold angles and reports the closure mismatch; with --target,
// first finds the closed state nearest to the target angles (design/target/nearest_state.hpp).
// ANGLES.json: {"<edge index>": degrees, ...} or an array with one entry (or null) per edge.
// Creases not listed keep the pattern's edges_foldAngle (0 where it has none).
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

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
#include "kernel/pattern/no_answer_error.hpp"
#include "design/target/nearest_state.hpp"
#include "report/nearest_state_json.hpp"
#include "report/repair_text.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {
namespace {

struct FoldArgs {
  std::string pattern, angles, target, out, obj, stl;
  std::vector<int> hold;
  bool json = false;
};

// The fold angles to place: the user's, or the closed state nearest the target (no answer: exit 3).
Eigen::VectorXd angles_to_place(const FoldArgs& a, const CreasePattern& p, const Topology& t, std::optional<NearestState>& nearest) {
  if (a.target.empty()) return read_fold_angles_json(a.angles, p, t);
  NearestStateOptions options;
  options.held_edges = a.hold;
  nearest = nearest_closed_state(p, t, read_fold_angles_input(a.target, p, t), options);
  if (!nearest->converged) throw NoAnswerError("--target: " + nearest->message, nearest->residual);
  return nearest->angles;
}


}  // namespace

void add_fold_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("fold", "Fold a pattern to given fold angles; write the folded state and report closure mismatch");
  auto a = std::make_shared<FoldArgs>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold)")->required();
  auto* angles = cmd->add_option("--angles", a->angles, "JSON: {\"edge\": degrees} or array of degrees per edge");
  auto* target = cmd->add_option("--target", a->target, "fold to the closed state nearest these angles (JSON as --angles, or a FOLD of the same pattern with edges_foldAngle)");
  angles->excludes(target);
  target->excludes(angles);
  cmd->add_option("--hold", a->hold, "with --target: creases kept at their target angle (comma-separated edge indices)")->delimiter(',')->needs(target);
  cmd->add_option("--out", a->out, "output FOLD with a foldedForm frame")->required();
  cmd->add_option("--obj", a->obj, "also write the folded faces as OBJ");
  cmd->add_option("--stl", a->stl, "also write the folded faces as binary STL (triangulated, float32)");
  cmd->add_flag("--json", a->json, "print the report as JSON");
  cmd->callback([a] {
    // Every path checked against the others before any work; both outputs committed together.
    OutputSet outputs;
    outputs.add_input("PATTERN", a->pattern);
    if (a->angles.empty() && a->target.empty()) throw InputError("--angles", "one of --angles or --target is required");
    outputs.add_input(a->target.empty() ? "--angles" : "--target", a->target.empty() ? a->angles : a->target);
    outputs.add_output("--out", a->out);
    if (!a->obj.empty()) outputs.add_output("--obj", a->obj);
    if (!a->stl.empty()) outputs.add_output("--stl", a->stl);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    const CreasePattern p = read_fold(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    std::optional<NearestState> nearest;
    const Eigen::VectorXd rho = angles_to_place(*a, p, t, nearest);
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
    if (nearest) j["nearest_state"] = report::nearest_state_json(*nearest);
    if (a->json) {
      std::cout << document_text(j) << "\n";
    } else {
      std::cout << "folded " << a->pattern << " -> " << a->out << (a->obj.empty() ? "" : " and " + a->obj) << (a->stl.empty() ? "" : " and " + a->stl) << "\n";
      std::cout << "  closure mismatch " << to_file_units(p, g.max_mismatch) << " (relative " << g.relative_mismatch() << ") over "
                << g.non_tree_hinges << " non-tree hinges";
      if (g.worst_edge >= 0) std::cout << ", worst at edge " << g.worst_edge;
      std::cout << "\n";
      if (nearest) std::cout << report::nearest_state_text(a->target, *nearest);
    }
  });
}

}  // namespace rigidfold::cli
