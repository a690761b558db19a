#include "kernel/energy/stiffness_spec.hpp"

#include <cmath>
#include <string>

#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"

namespace rigidfold {

namespace {

bool has_spring(Assignment a) {
  return a == Assignment::Mountain || a == Assignment::Valley || a == Assignment::Unassigned;
}

double stiffness_value(const nlohmann::ordered_json& v, const std::string& place) {
  if (!v.is_number()) throw InputError(place, "must be a number (stiffness, energy / rad^2)");
  const double k = v.get<double>();
  if (!std::isfinite(k) || k < 0.0) throw InputError(place, "must be a finite number >= 0");
  return k;
}

double positive(const nlohmann::ordered_json& object, const char* key, const std::string& place, bool required,
                double fallback) {
  const auto it = object.find(key);
  if (it == object.end()) {
    if (required) throw InputError(place + "." + key, "is required");
    return fallback;
  }
  if (!it->is_number()) throw InputError(place + "." + key, "must be a number");
  const double x = it->get<double>();
  if (!std::isfinite(x) || !(x > 0.0)) throw InputError(place + "." + key, "must be a finite number > 0");
  return x;
}

}  // namespace

Eigen::VectorXd stiffness_from_spec(const nlohmann::ordered_json& spec, const CreasePattern& pattern,
                                    const std::string& source) {
  const std::string at = source + ": ";
  if (!spec.is_object()) throw InputError(source, "must be a JSON object (keys default, material, mountain, valley, unassigned, edges)");
  for (const auto& [key, value] : spec.items())
    if (key != "default" && key != "material" && key != "mountain" && key != "valley" && key != "unassigned" && key != "edges")
      throw InputError(at + key, "is not a key of a stiffness spec (default, material, mountain, valley, unassigned, edges)");
  const int m = pattern.num_edges();
  Eigen::VectorXd k = Eigen::VectorXd::Zero(m);
  const double base = spec.contains("default") ? stiffness_value(spec["default"], at + "default") : 1.0;
  for (int e = 0; e < m; ++e)
    if (has_spring(pattern.assignments[e])) k[e] = base;

  if (const auto it = spec.find("material"); it != spec.end()) {
    const std::string place = at + "material";
    if (!it->is_object()) throw InputError(place, "must be an object {youngs_modulus, thickness, flexure_length[, length_scale]}");
    for (const auto& [key, value] : it->items())
      if (key != "youngs_modulus" && key != "thickness" && key != "flexure_length" && key != "length_scale")
        throw InputError(place + "." + key, "is not a material key (youngs_modulus, thickness, flexure_length, length_scale)");
    const double E = positive(*it, "youngs_modulus", place, true, 0.0);
    const double h = positive(*it, "thickness", place, true, 0.0);
    const double l = positive(*it, "flexure_length", place, true, 0.0);
    const double s = positive(*it, "length_scale", place, false, 1.0);
    const double unit = std::ldexp(1.0, pattern.length_exponent);
    for (int e = 0; e < m; ++e) {
      if (!has_spring(pattern.assignments[e])) continue;
      const auto& ed = pattern.edges[e];
      const double width = s * unit * (pattern.vertices[ed[1]] - pattern.vertices[ed[0]]).norm();
      try {
        k[e] = flexure_stiffness(E, width, h, l);
      } catch (const InputError& err) {
        throw InputError(place, "gives no finite stiffness for edge " + std::to_string(e) + " (" + err.what() + ")");
      }
    }
  }

  const struct {
    const char* key;
    Assignment letter;
  } letters[] = {{"mountain", Assignment::Mountain}, {"valley", Assignment::Valley}, {"unassigned", Assignment::Unassigned}};
  for (const auto& l : letters)
    if (const auto it = spec.find(l.key); it != spec.end()) {
      const double v = stiffness_value(*it, at + l.key);
      for (int e = 0; e < m; ++e)
        if (pattern.assignments[e] == l.letter) k[e] = v;
    }

  if (const auto it = spec.find("edges"); it != spec.end()) {
    if (!it->is_object()) throw InputError(at + "edges", "must be an object {\"edge index\": stiffness}");
    for (const auto& [key, value] : it->items()) {
      const std::string place = at + "edges.\"" + key + "\"";
      bool digits = !key.empty() && key.size() <= 9;
      for (char c : key) digits = digits && c >= '0' && c <= '9';
      if (!digits || (key.size() > 1 && key[0] == '0'))
        throw InputError(place, "must be an edge index (0-based, decimal, no leading zeros)");
      const long e = std::stol(key);
      if (e >= m) throw InputError(place, "edge " + key + " does not exist (" + std::to_string(m) + " edges)");
      if (!has_spring(pattern.assignments[e]))
        throw InputError(place, "edge " + key + " is not a crease (B, C, F and J edges carry no spring)");
      k[e] = stiffness_value(value, place);
    }
  }
  return k;
}

Eigen::VectorXd read_stiffness_spec(const std::string& path, const CreasePattern& pattern) {
  return stiffness_from_spec(parse_ordered_json_input(read_input_file(path), path), pattern, path);
}

}  // namespace rigidfold
