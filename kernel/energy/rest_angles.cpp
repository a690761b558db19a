#include "kernel/energy/rest_angles.hpp"

#include <cmath>
#include <string>

#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/fold_angles_input.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/read_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

namespace {

bool is_folded_form(const nlohmann::ordered_json& frame) {
  if (!frame.is_object()) return false;
  const auto it = frame.find("frame_classes");
  if (it == frame.end() || !it->is_array()) return false;
  for (const auto& c : *it)
    if (c.is_string() && c.get<std::string>() == "foldedForm") return true;
  return false;
}

double finite_number(const nlohmann::ordered_json& value, const std::string& place) {
  if (!value.is_number()) throw InputError(place, "must be a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw InputError(place, "must be finite");
  return x;
}

}  // namespace

Eigen::VectorXd rest_angles_from_frame(const CreasePattern& pattern, int frame) {
  const auto frames_it = pattern.extra.find("file_frames");
  if (frames_it == pattern.extra.end() || !frames_it->is_array() || frames_it->empty())
    throw InputError("file_frames", "the file has no frames, so no folded rest state");
  const auto& frames = *frames_it;
  if (frame < 0) {
    for (std::size_t i = 0; i < frames.size(); ++i)
      if (is_folded_form(frames[i])) {
        frame = static_cast<int>(i);
        break;
      }
    if (frame < 0) throw InputError("file_frames", "no frame has frame_classes \"foldedForm\"");
  }
  if (frame >= static_cast<int>(frames.size()))
    throw InputError("file_frames", "frame " + std::to_string(frame) + " does not exist (" +
                                        std::to_string(frames.size()) + " frames)");
  const auto& f = frames[frame];
  const std::string place = "file_frames[" + std::to_string(frame) + "]";
  if (!f.is_object()) throw InputError(place, "must be an object");
  const int m = pattern.num_edges();

  if (const auto it = f.find("edges_foldAngle"); it != f.end()) {
    if (!it->is_array() || static_cast<int>(it->size()) != m)
      throw InputError(place + ".edges_foldAngle", "needs one angle per edge (" + std::to_string(m) + ")");
    Eigen::VectorXd rest(m);
    for (int e = 0; e < m; ++e) {
      const std::string pe = place + ".edges_foldAngle[" + std::to_string(e) + "]";
      const double deg = (*it)[e].is_null() ? 0.0 : finite_number((*it)[e], pe);
      if (std::fabs(deg) > 180.0) throw InputError(pe, "must lie in [-180, 180] deg");
      rest[e] = to_radians(deg);
    }
    return rest;
  }

  const auto it = f.find("vertices_coords");
  if (it == f.end())
    throw InputError(place, "has neither edges_foldAngle nor vertices_coords to take the rest state from");
  if (!it->is_array() || static_cast<int>(it->size()) != pattern.num_vertices())
    throw InputError(place + ".vertices_coords",
                     "needs one point per vertex (" + std::to_string(pattern.num_vertices()) + ")");
  // Measure the angles on a copy carrying the frame's coordinates. Fold angles do not
  // depend on the scale, but keep the kernel's power-of-two scaling for size ~1 lengths.
  CreasePattern folded = pattern;
  folded.coords_2d = false;
  for (int v = 0; v < pattern.num_vertices(); ++v) {
    const auto& p = (*it)[v];
    const std::string pv = place + ".vertices_coords[" + std::to_string(v) + "]";
    if (!p.is_array() || p.size() < 2 || p.size() > 3) throw InputError(pv, "must be a 2D or 3D point");
    Eigen::Vector3d x(finite_number(p[0], pv), finite_number(p[1], pv), p.size() == 3 ? finite_number(p[2], pv) : 0.0);
    folded.vertices[v] = std::ldexp(1.0, -pattern.length_exponent) * x;
  }
  const Topology topo = build_topology(folded, place);
  return reference_fold_angles(folded, topo);
}

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

Eigen::VectorXd read_rest_state(const std::string& path, const CreasePattern& pattern, const Topology& topology) {
  if (ends_with(path, ".json")) return read_fold_angles_json(path, pattern, topology);
  if (!ends_with(path, ".fold")) throw InputError("--rest", "must be a .json of fold angles or a .fold of the same pattern: " + path);
  const CreasePattern rest = read_pattern(path);
  if (rest.num_vertices() != pattern.num_vertices() || rest.num_edges() != pattern.num_edges())
    throw InputError(path, "has " + std::to_string(rest.num_vertices()) + " vertices and " + std::to_string(rest.num_edges()) +
                               " edges; the pattern has " + std::to_string(pattern.num_vertices()) + " and " +
                               std::to_string(pattern.num_edges()));
  for (int e = 0; e < pattern.num_edges(); ++e)
    if (rest.edges[e] != pattern.edges[e])
      throw InputError(path + ": edges_vertices[" + std::to_string(e) + "]", "differs from the pattern's");
  if (rest.fold_angles_in_file) return stored_fold_angles(rest);
  if (!rest.coords_2d) return reference_fold_angles(rest, build_topology(rest, path));
  throw InputError(path, "has neither edges_foldAngle nor 3D coordinates: no rest state in it");
}

}  // namespace rigidfold
