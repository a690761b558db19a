#include "kernel/pattern/fold_io.hpp"
#include "kernel/math/angle_units.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdio>
#include <numbers>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/pattern/output_set.hpp"
#include "kernel/pattern/validate_pattern.hpp"

namespace rigidfold {
namespace {

using Json = nlohmann::ordered_json;


// Keys this module models; every other key goes to CreasePattern::extra.
bool is_modelled_key(const std::string& key) {
  return key == "vertices_coords" || key == "edges_vertices" || key == "edges_assignment" ||
         key == "edges_foldAngle" || key == "faces_vertices";
}

std::string place(const std::string& source, const std::string& path) { return source + ": " + path; }

const Json& require_array(const Json& doc, const std::string& key, const std::string& source) {
  const Json& v = doc.at(key);
  if (!v.is_array()) throw InputError(place(source, key), "must be an array, found " + std::string(v.type_name()));
  return v;
}

double finite_number(const Json& v, const std::string& source, const std::string& path) {
  if (!v.is_number()) throw InputError(place(source, path), "must be a number, found " + std::string(v.type_name()));
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw InputError(place(source, path), "number is not finite");
  return x;
}

int index_value(const Json& v, const std::string& source, const std::string& path) {
  if (!v.is_number_integer() && !v.is_number_unsigned()) {
    if (v.is_number_float()) {
      const double x = v.get<double>();
      if (std::isfinite(x) && x == std::floor(x) && std::fabs(x) < 2e9) return static_cast<int>(x);
    }
    throw InputError(place(source, path), "must be an integer index, found " + std::string(v.type_name()));
  }
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > 2000000000ULL) throw InputError(place(source, path), "index " + std::to_string(u) + " is too large");
    return static_cast<int>(u);
  }
  const auto i = v.get<std::int64_t>();
  if (i < 0) throw InputError(place(source, path), "index " + std::to_string(i) + " is negative");
  if (i > 2000000000LL) throw InputError(place(source, path), "index " + std::to_string(i) + " is too large");
  return static_cast<int>(i);
}

void read_vertices(const Json& doc, CreasePattern& p, const std::string& source) {
  if (!doc.contains("vertices_coords")) throw InputError(place(source, "vertices_coords"), "missing (a FOLD crease pattern needs vertex coordinates)");
  const Json& coords = require_array(doc, "vertices_coords", source);
  if (coords.empty()) throw InputError(place(source, "vertices_coords"), "is empty");
  int dim = -1;
  p.vertices.reserve(coords.size());
  for (std::size_t i = 0; i < coords.size(); ++i) {
    const std::string path = "vertices_coords[" + std::to_string(i) + "]";
    const Json& c = coords[i];
    if (!c.is_array()) throw InputError(place(source, path), "must be an array of 2 or 3 numbers, found " + std::string(c.type_name()));
    const int d = static_cast<int>(c.size());
    if (d != 2 && d != 3) throw InputError(place(source, path), "has " + std::to_string(d) + " coordinates; expected 2 or 3");
    if (dim == -1) dim = d;
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int k = 0; k < d; ++k) x[k] = finite_number(c[k], source, path + "[" + std::to_string(k) + "]");
    if (d != dim) {
      // A mix is tolerated only when the extra coordinate is zero: 2D points in a 3D file.
      if (d == 3 && x[2] != 0.0) throw InputError(place(source, path), "has 3 coordinates but earlier vertices have 2");
      dim = std::max(dim, d);
    }
    p.vertices.push_back(x);
  }
  p.coords_2d = true;
  for (const auto& v : p.vertices)
    if (v[2] != 0.0) p.coords_2d = false;
}

void read_edges(const Json& doc, CreasePattern& p, const std::string& source) {
  if (!doc.contains("edges_vertices")) return;
  const Json& ev = require_array(doc, "edges_vertices", source);
  p.edges.reserve(ev.size());
  for (std::size_t i = 0; i < ev.size(); ++i) {
    const std::string path = "edges_vertices[" + std::to_string(i) + "]";
    const Json& e = ev[i];
    if (!e.is_array() || e.size() != 2) throw InputError(place(source, path), "must be a pair of vertex indices");
    std::array<int, 2> pair{};
    for (int k = 0; k < 2; ++k) {
      const std::string ipath = path + "[" + std::to_string(k) + "]";
      pair[k] = index_value(e[k], source, ipath);
      if (pair[k] >= p.num_vertices())
        throw InputError(place(source, ipath), "vertex index " + std::to_string(pair[k]) + " out of range (" + std::to_string(p.num_vertices()) + " vertices)");
    }
    p.edges.push_back(pair);
  }
}

void read_faces(const Json& doc, CreasePattern& p, const std::string& source) {
  if (!doc.contains("faces_vertices")) return;
  const Json& fv = require_array(doc, "faces_vertices", source);
  p.faces.reserve(fv.size());
  for (std::size_t i = 0; i < fv.size(); ++i) {
    const std::string path = "faces_vertices[" + std::to_string(i) + "]";
    const Json& f = fv[i];
    if (!f.is_array()) throw InputError(place(source, path), "must be an array of vertex indices");
    std::vector<int> face;
    face.reserve(f.size());
    for (std::size_t k = 0; k < f.size(); ++k) {
      const std::string ipath = path + "[" + std::to_string(k) + "]";
      const int v = index_value(f[k], source, ipath);
      if (v >= p.num_vertices())
        throw InputError(place(source, ipath), "vertex index " + std::to_string(v) + " out of range (" + std::to_string(p.num_vertices()) + " vertices)");
      face.push_back(v);
    }
    p.faces.push_back(std::move(face));
  }
}

// FOLD allows edges to be omitted when faces are given: take the faces' sides.
void edges_from_faces(CreasePattern& p) {
  std::map<std::pair<int, int>, int> seen;
  for (const auto& f : p.faces)
    for (std::size_t k = 0; k < f.size(); ++k) {
      int a = f[k], b = f[(k + 1) % f.size()];
      auto key = std::minmax(a, b);
      if (a != b && !seen.count(key)) {
        seen[key] = p.num_edges();
        p.edges.push_back({a, b});
      }
    }
}

void read_assignments(const Json& doc, CreasePattern& p, const std::string& source) {
  p.assignments.assign(p.edges.size(), Assignment::Unassigned);
  if (!doc.contains("edges_assignment")) {
    p.warnings.push_back(source + ": edges_assignment missing; boundary edges set to B, others to U");
    p.assignments.clear();  // filled by complete_and_validate once faces are known
    return;
  }
  const Json& ea = require_array(doc, "edges_assignment", source);
  if (ea.size() != p.edges.size())
    throw InputError(place(source, "edges_assignment"), "has " + std::to_string(ea.size()) + " entries but there are " + std::to_string(p.edges.size()) + " edges");
  for (std::size_t i = 0; i < ea.size(); ++i) {
    const std::string path = "edges_assignment[" + std::to_string(i) + "]";
    if (!ea[i].is_string()) throw InputError(place(source, path), "must be a one-letter string (B, M, V, F, U, C or J)");
    const auto s = ea[i].get<std::string>();
    std::optional<Assignment> a;
    if (s.size() == 1) a = assignment_from_letter(s[0]);
    if (!a) throw InputError(place(source, path), "unknown assignment \"" + s + "\" (expected B, M, V, F, U, C or J)");
    p.assignments[i] = *a;
  }
}

void read_fold_angles(const Json& doc, CreasePattern& p, const std::string& source) {
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  if (!doc.contains("edges_foldAngle")) return;
  p.fold_angles_in_file = true;
  const Json& fa = require_array(doc, "edges_foldAngle", source);
  if (fa.size() != p.edges.size())
    throw InputError(place(source, "edges_foldAngle"), "has " + std::to_string(fa.size()) + " entries but there are " + std::to_string(p.edges.size()) + " edges");
  for (std::size_t i = 0; i < fa.size(); ++i) {
    if (fa[i].is_null()) continue;
    const std::string path = "edges_foldAngle[" + std::to_string(i) + "]";
    const double deg = finite_number(fa[i], source, path);
    if (std::fabs(deg) > 180.0) throw InputError(place(source, path), "fold angle " + std::to_string(deg) + " deg is outside [-180, 180]");
    p.fold_angles[i] = deg * kRadiansPerDegree;
  }
}

// file_frames (FOLD 1.2): an array of frame objects, file_frames[i] being frame i + 1 (frame
// 0 is the file's key frame). A frame_parent is a frame index in [0, frames], not the frame
// itself, and following parents ends (no cycle). Checked before any key is copied, so an
// invalid structure is never written back out.
void check_file_frames(const Json& frames, const std::string& source) {
  if (!frames.is_array()) throw InputError(place(source, "file_frames"), "must be an array of frames, found " + std::string(frames.type_name()));
  const std::size_t n = frames.size();
  std::vector<long> parent(n + 1, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::string path = "file_frames[" + std::to_string(i) + "]";
    if (!frames[i].is_object()) throw InputError(place(source, path), "must be a frame object, found " + std::string(frames[i].type_name()));
    const auto it = frames[i].find("frame_parent");
    if (it == frames[i].end()) continue;
    const std::string ppath = path + ".frame_parent";
    const long parent_index = index_value(*it, source, ppath);
    if (static_cast<std::size_t>(parent_index) > n)
      throw InputError(place(source, ppath), "frame " + std::to_string(parent_index) + " out of range (frames 0.." + std::to_string(n) +
                                                 ": 0 is the key frame, file_frames[i] is frame i + 1)");
    if (static_cast<std::size_t>(parent_index) == i + 1) throw InputError(place(source, ppath), "a frame cannot be its own parent");
    parent[i + 1] = parent_index;
  }
  // Walk each chain of parents once: 1 = on the chain being walked, 2 = known to end.
  std::vector<char> state(n + 1, 0);
  for (std::size_t start = 1; start <= n; ++start) {
    long f = static_cast<long>(start);
    while (f >= 0 && state[f] == 0) {
      state[f] = 1;
      f = parent[f];
    }
    if (f >= 0 && state[f] == 1)
      throw InputError(place(source, "file_frames[" + std::to_string(f - 1) + "].frame_parent"),
                       "frame parents form a cycle through frame " + std::to_string(f));
    for (long g = static_cast<long>(start); g >= 0 && state[g] == 1; g = parent[g]) state[g] = 2;
  }
}

}  // namespace

std::string read_text_file(const std::string& path) { return read_input_file(path); }

void write_text_file_atomically(const std::string& path, const std::string& text) {
  OutputSet out;
  out.add_output("", path);
  out.stage(path, text);
  out.commit();
}

CreasePattern parse_fold(const std::string& text, const std::string& source) {
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(source, "file is empty");
  const Json doc = parse_ordered_json_input(text, source);
  if (!doc.is_object()) throw InputError(source, "top level must be a JSON object, found " + std::string(doc.type_name()));

  if (const auto frames = doc.find("file_frames"); frames != doc.end()) check_file_frames(*frames, source);
  CreasePattern p;
  for (auto it = doc.begin(); it != doc.end(); ++it)
    if (!is_modelled_key(it.key())) p.extra[it.key()] = it.value();

  read_vertices(doc, p, source);
  read_edges(doc, p, source);
  read_faces(doc, p, source);
  if (!doc.contains("edges_vertices")) {
    if (p.faces.empty()) throw InputError(place(source, "edges_vertices"), "missing, and no faces_vertices to take edges from");
    edges_from_faces(p);
  }
  if (p.edges.empty()) throw InputError(place(source, "edges_vertices"), "is empty");
  read_assignments(doc, p, source);
  read_fold_angles(doc, p, source);
  complete_and_validate(p, source);
  return p;
}

CreasePattern read_fold(const std::string& path) { return parse_fold(read_text_file(path), path); }

nlohmann::ordered_json fold_to_json(const CreasePattern& p) {
  Json doc = Json::object();
  // Kept keys in their original order (file_frames last), then the modelled arrays.
  if (!p.extra.contains("file_spec")) doc["file_spec"] = 1.1;
  if (!p.extra.contains("file_creator")) doc["file_creator"] = "rigidfold";
  for (auto it = p.extra.begin(); it != p.extra.end(); ++it)
    if (it.key() != "file_frames") doc[it.key()] = it.value();

  Json coords = Json::array();
  for (const auto& v0 : p.vertices) {
    const Eigen::Vector3d v = to_file_units(p, v0);  // exact: a power of two (length_scale.hpp)
    if (p.coords_2d) coords.push_back({v[0], v[1]});
    else coords.push_back({v[0], v[1], v[2]});
  }
  doc["vertices_coords"] = std::move(coords);
  Json edges = Json::array();
  for (const auto& e : p.edges) edges.push_back({e[0], e[1]});
  doc["edges_vertices"] = std::move(edges);
  Json assign = Json::array();
  for (auto a : p.assignments) assign.push_back(std::string(1, assignment_letter(a)));
  doc["edges_assignment"] = std::move(assign);
  bool any_angle = false;
  for (const auto& a : p.fold_angles) any_angle = any_angle || a.has_value();
  if (any_angle || p.fold_angles_in_file) {
    Json angles = Json::array();
    for (std::size_t e = 0; e < p.fold_angles.size(); ++e) {
      const auto& a = p.fold_angles[e];
      const Assignment letter = e < p.assignments.size() ? p.assignments[e] : Assignment::Unassigned;
      // FOLD 1.2 has numbers only: a boundary, flat or join edge has fold angle 0. A crease
      // whose angle the input left out (null) stays null, as read.
      if (a) angles.push_back(*a * kDegreesPerRadian);
      else if (letter == Assignment::Boundary || letter == Assignment::Flat || letter == Assignment::Join) angles.push_back(0.0);
      else angles.push_back(nullptr);
    }
    doc["edges_foldAngle"] = std::move(angles);
  }
  Json faces = Json::array();
  for (const auto& f : p.faces) faces.push_back(f);
  doc["faces_vertices"] = std::move(faces);
  if (p.extra.contains("file_frames")) doc["file_frames"] = p.extra["file_frames"];
  return doc;
}

// One top-level key per line and one array element per line: diff-friendly, and far
// smaller than fully indented JSON for large patterns. Strings that are not UTF-8 (a title
// taken from a file name) get U+FFFD: a FOLD file is JSON, and failing here would be late.
std::string dump_fold_json(const nlohmann::ordered_json& doc) {
  const auto text = [](const Json& v) { return v.dump(-1, ' ', false, Json::error_handler_t::replace); };
  std::string out = "{\n";
  bool first = true;
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    if (!first) out += ",\n";
    first = false;
    out += "  " + text(Json(it.key())) + ": ";
    const Json& v = it.value();
    const bool nested = v.is_array() && !v.empty() && (v.front().is_array() || v.front().is_object());
    if (!nested) {
      out += text(v);
      continue;
    }
    out += "[\n";
    for (std::size_t i = 0; i < v.size(); ++i) {
      out += "    " + text(v[i]);
      out += (i + 1 < v.size()) ? ",\n" : "\n";
    }
    out += "  ]";
  }
  out += "\n}\n";
  return out;
}

std::string write_fold_string(const CreasePattern& p) { return dump_fold_json(fold_to_json(p)); }

void write_fold(const CreasePattern& p, const std::string& path) { write_text_file_atomically(path, write_fold_string(p)); }

}  // namespace rigidfold
