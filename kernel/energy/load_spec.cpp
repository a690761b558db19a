#include "kernel/energy/load_spec.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"

namespace rigidfold {

namespace {

int index_value(const nlohmann::ordered_json& v, const std::string& place, int count, const char* what) {
  if (!v.is_number_integer() && !v.is_number_unsigned()) throw InputError(place, std::string("must be an integer ") + what + " index");
  if (v.is_number_integer() && v.get<long long>() < 0) throw InputError(place, std::string("must be a ") + what + " index >= 0");
  const auto i = v.get<unsigned long long>();
  if (i >= static_cast<unsigned long long>(count))
    throw InputError(place, std::string(what) + " " + std::to_string(i) + " does not exist (" + std::to_string(count) + ")");
  return static_cast<int>(i);
}

bool incident(const CreasePattern& p, int e, int v) { return p.edges[e][0] == v || p.edges[e][1] == v; }

}  // namespace

VertexHeightLoad load_from_spec(const nlohmann::ordered_json& spec, const CreasePattern& pattern, const Topology& topology,
                                const std::string& source) {
  const std::string at = source + ": ";
  if (!spec.is_object()) throw InputError(source, "must be a JSON object {vertex, height[, supports]}");
  for (const auto& [key, value] : spec.items()) {
    if (key == "force") throw InputError(at + "force", "force control is not supported; prescribe the vertex height (\"height\")");
    if (key != "vertex" && key != "height" && key != "supports")
      throw InputError(at + key, "is not a key of a load spec (vertex, height, supports)");
  }
  VertexHeightLoad load;
  if (!spec.contains("vertex")) throw InputError(at + "vertex", "is required");
  load.vertex = index_value(spec["vertex"], at + "vertex", pattern.num_vertices(), "vertex");
  if (std::find(topology.interior_vertices.begin(), topology.interior_vertices.end(), load.vertex) ==
      topology.interior_vertices.end())
    throw InputError(at + "vertex", "vertex " + std::to_string(load.vertex) + " is not an interior vertex (no closed fan of faces)");
  if (!spec.contains("height")) throw InputError(at + "height", "is required");
  if (!spec["height"].is_number()) throw InputError(at + "height", "must be a number (length)");
  const double height_in_file_units = spec["height"].get<double>();
  if (!std::isfinite(height_in_file_units)) throw InputError(at + "height", "must be finite");
  // The kernel works on the pattern normalised by 2^length_exponent (length_scale.hpp): the
  // height is a length of the file, so it is normalised with it.
  load.height = std::ldexp(height_in_file_units, -pattern.length_exponent);
  if (!std::isfinite(load.height) || (load.height == 0.0) != (height_in_file_units == 0.0))
    throw InputError(at + "height", "cannot be expressed at the pattern's scale (2^" + std::to_string(pattern.length_exponent) + ")");
  if (const auto it = spec.find("supports"); it != spec.end()) {
    if (!it->is_array()) throw InputError(at + "supports", "must be an array of edge indices");
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string place = at + "supports[" + std::to_string(i) + "]";
      const int e = index_value((*it)[i], place, pattern.num_edges(), "edge");
      if (!incident(pattern, e, load.vertex) || !topology.edge_is_hinge[e])
        throw InputError(place, "edge " + std::to_string(e) + " is not a crease of vertex " + std::to_string(load.vertex));
      if (std::find(load.support_edges.begin(), load.support_edges.end(), e) != load.support_edges.end())
        throw InputError(place, "edge " + std::to_string(e) + " is given twice");
      load.support_edges.push_back(e);
    }
  } else {
    for (int e = 0; e < pattern.num_edges(); ++e)
      if (incident(pattern, e, load.vertex) && topology.edge_is_hinge[e] && pattern.assignments[e] == Assignment::Valley)
        load.support_edges.push_back(e);
  }
  if (load.support_edges.size() < 3)
    throw InputError(at + "supports", std::to_string(load.support_edges.size()) +
                                          " support(s); a plane needs at least 3 (default: the vertex's valley creases)");
  return load;
}

VertexHeightLoad read_load_spec(const std::string& path, const CreasePattern& pattern, const Topology& topology) {
  return load_from_spec(parse_ordered_json_input(read_input_file(path), path), pattern, topology, path);
}

}  // namespace rigidfold
