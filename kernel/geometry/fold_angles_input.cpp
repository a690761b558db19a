#include "kernel/geometry/fold_angles_input.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"

namespace rigidfold {

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

}  // namespace

Eigen::VectorXd read_fold_angles_json(const std::string& path, const CreasePattern& p, const Topology& t) {
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

Eigen::VectorXd read_fold_angles_input(const std::string& path, const CreasePattern& p, const Topology& t) {
  if (!path.ends_with(".fold")) return read_fold_angles_json(path, p, t);
  const CreasePattern other = read_fold(path);
  if (other.num_edges() != p.num_edges())
    throw InputError(path, "has " + std::to_string(other.num_edges()) + " edges but the pattern has " + std::to_string(p.num_edges()));
  Eigen::VectorXd rho = stored_fold_angles(p);
  for (int e = 0; e < p.num_edges(); ++e) {
    const std::string where = path + ": edges_vertices[" + std::to_string(e) + "]";
    if (std::minmax(other.edges[e][0], other.edges[e][1]) != std::minmax(p.edges[e][0], p.edges[e][1]))
      throw InputError(where, "joins other vertices than the pattern's edge " + std::to_string(e) + " (the files are not the same pattern)");
    if (other.fold_angles[e]) set_angle(rho, p, t, e, *other.fold_angles[e], path + ": edges_foldAngle[" + std::to_string(e) + "]");
  }
  return rho;
}

}  // namespace rigidfold
