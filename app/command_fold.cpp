// rigidfold fold PATTERN.fold --angles ANGLES.json --out FOLDED.fold [--obj FOLDED.obj] [--json]
// Places the faces for the given fold angles and reports the closure mismatch.
// ANGLES.json: {"<edge index>": degrees, ...} or an array with one entry (or null) per edge.
// Creases not listed keep the pattern's edges_foldAngle (0 where it has none).
#include <cmath>
#include <iostream>

#include "app/commands.hpp"
#include "app/summary_stream.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {
namespace {

double angle_value(const nlohmann::json& v, const std::string& where) {
  if (!v.is_number()) throw InputError(where, "must be a number of degrees");
  const double d = v.get<double>();
  if (!std::isfinite(d) || std::fabs(d) > 180.0) throw InputError(where, "fold angle must be finite and within [-180, 180] deg");
  return to_radians(d);
}

void set_angle(Eigen::VectorXd& rho, const CreasePattern& p, const Topology& t, long e, double value, const std::string& where) {
  if (e < 0 || e >= p.num_edges()) throw InputError(where, "edge index " + std::to_string(e) + " out of range (" + std::to_string(p.num_edges()) + " edges)");
  if (!t.edge_is_hinge[e] && value != 0.0) throw InputError(where, "edge " + std::to_string(e) + " is not a crease between two faces; it cannot fold");
  const Assignment a = p.assignments[e];
  if ((a == Assignment::Flat || a == Assignment::Join) && value != 0.0)
    throw InputError(where, "edge " + std::to_string(e) + " is assigned " + std::string(1, assignment_letter(a)) + " (rigid); it cannot fold");
  rho[e] = value;
}

Eigen::VectorXd read_angles(const std::string& path, const CreasePattern& p, const Topology& t) {
  const nlohmann::json doc = parse_json_input(read_input_file(path), path);
  Eigen::VectorXd rho = stored_fold_angles(p);
  if (doc.is_object()) {
    for (auto it = doc.begin(); it != doc.end(); ++it) {
      const std::string where = path + ": " + it.key();
      std::size_t used = 0;
      long e = -1;
      try {
        e = std::stol(it.key(), &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != it.key().size()) throw InputError(where, "key must be an edge index");
      set_angle(rho, p, t, e, angle_value(it.value(), where), where);
    }
  } else if (doc.is_array()) {
    if (static_cast<int>(doc.size()) != p.num_edges())
      throw InputError(path, "array has " + std::to_string(doc.size()) + " entries but the pattern has " + std::to_string(p.num_edges()) + " edges");
    for (int e = 0; e < p.num_edges(); ++e) {
      if (doc[e].is_null()) continue;
      const std::string where = path + ": [" + std::to_string(e) + "]";
      set_angle(rho, p, t, e, angle_value(doc[e], where), where);
    }
  } else {
    throw InputError(path, "must be an object {\"edge\": degrees} or an array of degrees");
  }
  return rho;
}

}  // namespace

void add_fold_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("fold", "Fold a pattern to given fold angles; write the folded state and report closure mismatch");
  struct Args {
    std::string pattern, angles, out, obj;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("pattern", a->pattern, "crease pattern (.fold)")->required();
  cmd->add_option("--angles", a->angles, "JSON: {\"edge\": degrees} or array of degrees per edge")->required();
  cmd->add_option("--out", a->out, "output FOLD with a foldedForm frame")->required();
  cmd->add_option("--obj", a->obj, "also write the folded faces as OBJ");
  cmd->add_flag("--json", a->json, "print the report as JSON");
  cmd->callback([a] {
    // Every path checked against the others before any work; both outputs committed together.
    OutputSet outputs;
    outputs.add_input("PATTERN", a->pattern);
    outputs.add_input("--angles", a->angles);
    outputs.add_output("--out", a->out);
    if (!a->obj.empty()) outputs.add_output("--obj", a->obj);
    const SummaryToStderrIfStdoutIsAnOutput summary(outputs);
    const CreasePattern p = read_fold(a->pattern);
    const Topology t = build_topology(p, a->pattern);
    const Eigen::VectorXd rho = read_angles(a->angles, p, t);
    const FoldedGeometry g = place_faces(p, t, rho, reference_fold_angles(p, t));
    outputs.stage(a->out, write_fold_string(with_folded_frame(p, g, rho, "folded by rigidfold")));
    if (!a->obj.empty()) outputs.stage(a->obj, folded_obj(p, g));
    outputs.commit();
    nlohmann::ordered_json j;
    j["pattern"] = a->pattern;
    j["out"] = a->out;
    j["closure_mismatch"] = to_file_units(p, g.max_mismatch);  // the file's length units
    j["relative_mismatch"] = g.relative_mismatch();
    j["worst_edge"] = g.worst_edge;
    j["non_tree_hinges"] = g.non_tree_hinges;
    if (a->json) {
      std::cout << j.dump(2) << "\n";
    } else {
      std::cout << "folded " << a->pattern << " -> " << a->out << (a->obj.empty() ? "" : " and " + a->obj) << "\n";
      std::cout << "  closure mismatch " << to_file_units(p, g.max_mismatch) << " (relative " << g.relative_mismatch() << ") over "
                << g.non_tree_hinges << " non-tree hinges";
      if (g.worst_edge >= 0) std::cout << ", worst at edge " << g.worst_edge;
      std::cout << "\n";
    }
  });
}

}  // namespace rigidfold::cli
