// rigidfold info PATTERN.fold [--json]: counts, vertex degrees, sector sums,
// Kawasaki/Maekawa per interior vertex, and topology of every component.
#include <cstdio>
#include <iostream>
#include <map>

#include "app/commands.hpp"
#include "app/provenance.hpp"
#include "app/number_flags.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/flat_foldability.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::cli {
namespace {

nlohmann::ordered_json info_json(const std::string& path, const CreasePattern& p, const Topology& t, double tol_deg) {
  using Json = nlohmann::ordered_json;
  Json j;
  j["file"] = path;
  j["vertices"] = p.num_vertices();
  j["edges"] = p.num_edges();
  j["faces"] = p.num_faces();
  j["faces_derived"] = p.faces_derived;
  j["coordinates"] = p.coords_2d ? "2D" : "3D";
  std::map<char, int> counts;
  for (auto a : p.assignments) ++counts[assignment_letter(a)];
  Json assign = Json::object();
  for (auto [c, n] : counts) assign[std::string(1, c)] = n;
  j["assignments"] = assign;
  j["interior_vertices"] = t.interior_vertices.size();
  std::map<int, int> degree_histogram;
  for (int v : t.interior_vertices) ++degree_histogram[static_cast<int>(t.stars[v].fans[0].edges.size())];
  Json hist = Json::object();
  for (auto [d, n] : degree_histogram) hist[std::to_string(d)] = n;
  j["interior_degree_histogram"] = hist;

  Json comps = Json::array();
  for (const auto& c : t.components)
    comps.push_back({{"vertices", c.vertices}, {"edges", c.edges}, {"faces", c.faces},
                     {"euler_characteristic", c.euler_characteristic}, {"boundary_loops", c.boundary_loops},
                     {"genus", c.genus}, {"holes", c.holes}});
  j["components"] = comps;

  const auto ff = flat_foldability(p, t, to_radians(tol_deg));
  j["tolerance_deg"] = tol_deg;
  int kawasaki_ok = 0, maekawa_ok = 0, developable = 0;
  Json verts = Json::array();
  for (const auto& r : ff) {
    kawasaki_ok += r.kawasaki;
    maekawa_ok += r.maekawa.value_or(false);
    developable += std::fabs(r.developability_defect) <= 1e-9;
    Json vj;
    vj["vertex"] = r.vertex;
    vj["degree"] = r.degree;
    vj["sector_sum_deg"] = to_degrees(r.sector_sum);
    vj["kawasaki_residual_deg"] = r.kawasaki_residual ? Json(to_degrees(*r.kawasaki_residual)) : Json(nullptr);
    vj["kawasaki"] = r.kawasaki;
    vj["mountains"] = r.mountains;
    vj["valleys"] = r.valleys;
    vj["unassigned"] = r.unassigned;
    vj["maekawa"] = r.maekawa ? Json(*r.maekawa) : Json(nullptr);
    Json sectors = Json::array();
    for (double s : t.stars[r.vertex].fans[0].sectors) sectors.push_back(to_degrees(s));
    vj["sectors_deg"] = sectors;
    vj["creases"] = t.stars[r.vertex].fans[0].edges;
    verts.push_back(vj);
  }
  j["summary"] = {{"developable", developable}, {"kawasaki", kawasaki_ok}, {"maekawa", maekawa_ok},
                  {"flat_foldable_locally", kawasaki_ok == static_cast<int>(ff.size()) && maekawa_ok == static_cast<int>(ff.size())}};
  if (!p.coords_2d) {
    const Eigen::VectorXd rho = reference_fold_angles(p, t);
    double max_abs = 0;
    for (int e = 0; e < rho.size(); ++e) max_abs = std::max(max_abs, std::fabs(rho[e]));
    j["reference_max_fold_deg"] = to_degrees(max_abs);
  }
  j["interior"] = verts;
  j["warnings"] = p.warnings;
  return j;
}

void print_info_text(const nlohmann::ordered_json& j) {
  std::cout << j["file"].get<std::string>() << "\n";
  std::cout << "  vertices " << j["vertices"] << ", edges " << j["edges"] << ", faces " << j["faces"]
            << (j["faces_derived"].get<bool>() ? " (derived)" : "") << ", " << j["coordinates"].get<std::string>() << "\n";
  std::cout << "  assignments";
  for (auto it = j["assignments"].begin(); it != j["assignments"].end(); ++it) std::cout << " " << it.key() << ":" << it.value();
  std::cout << "\n  interior vertices " << j["interior_vertices"] << " (degree:count";
  for (auto it = j["interior_degree_histogram"].begin(); it != j["interior_degree_histogram"].end(); ++it)
    std::cout << " " << it.key() << ":" << it.value();
  std::cout << ")\n";
  int k = 0;
  for (const auto& c : j["components"])
    std::cout << "  component " << k++ << ": V " << c["vertices"] << " E " << c["edges"] << " F " << c["faces"] << ", Euler characteristic "
              << c["euler_characteristic"] << ", boundary loops " << c["boundary_loops"] << ", holes " << c["holes"] << ", genus "
              << c["genus"] << "\n";
  const auto& s = j["summary"];
  std::cout << "  (tolerance " << j["tolerance_deg"].get<double>() << " deg) developable " << s["developable"] << ", Kawasaki " << s["kawasaki"] << ", Maekawa " << s["maekawa"] << " of "
            << j["interior_vertices"] << " interior vertices\n";
  const auto& verts = j["interior"];
  const std::size_t shown = std::min<std::size_t>(verts.size(), 40);
  if (shown > 0) std::cout << "  vertex  deg  sector sum(deg)  Kawasaki res(deg)  M  V  U  Kawasaki  Maekawa\n";
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& v = verts[i];
    char line[200];
    const std::string kres = v["kawasaki_residual_deg"].is_null() ? "      -" : std::to_string(v["kawasaki_residual_deg"].get<double>());
    std::snprintf(line, sizeof line, "  %6d  %3d  %14.9f  %17s  %2d %2d %2d  %-8s  %s\n", v["vertex"].get<int>(), v["degree"].get<int>(),
                  v["sector_sum_deg"].get<double>(), kres.c_str(), v["mountains"].get<int>(), v["valleys"].get<int>(),
                  v["unassigned"].get<int>(), v["kawasaki"].get<bool>() ? "yes" : "no",
                  v["maekawa"].is_null() ? "-" : (v["maekawa"].get<bool>() ? "yes" : "no"));
    std::cout << line;
  }
  if (verts.size() > shown) std::cout << "  ... " << verts.size() - shown << " more (use --json)\n";
  for (const auto& w : j["warnings"]) std::cout << "  warning: " << w.get<std::string>() << "\n";
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Counts, vertex degrees, sector sums, Kawasaki/Maekawa, topology");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto tol = std::make_shared<double>(1e-7);
  cmd->add_option("pattern", *path, "crease pattern (.fold, or .svg in Origami Simulator's colours)")->required();
  cmd->add_flag("--json", *json, "print one JSON object");
  cmd->add_option("--tolerance-deg", *tol, "tolerance of the Kawasaki and developability checks, degrees (files with float32 or 6-digit coordinates need ~1e-3)")
      ->check(finite_in(1e-9, 10.0, "degrees"));  // below ~1e-12 deg the sector sums' own rounding would fail Kawasaki
  cmd->callback([path, json, tol] {
    const CreasePattern p = read_pattern(*path);
    const Topology t = build_topology(p, *path);
    const auto j = info_json(*path, p, t, *tol);
    if (*json) std::cout << document_text(j) << "\n";
    else print_info_text(j);
  });
}

}  // namespace rigidfold::cli
