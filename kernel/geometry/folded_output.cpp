#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/cross2.hpp"
#include "kernel/pattern/length_scale.hpp"
#include "kernel/pattern/topology.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace rigidfold {

CreasePattern with_folded_frame(const CreasePattern& pattern, const FoldedGeometry& folded,
                                const Eigen::VectorXd& fold_angles, const std::string& title) {
  CreasePattern out = pattern;
  nlohmann::ordered_json frame = nlohmann::ordered_json::object();
  frame["frame_title"] = title;
  frame["frame_classes"] = {"foldedForm"};
  frame["frame_attributes"] = {"3D"};
  frame["frame_parent"] = 0;
  frame["frame_inherit"] = true;
  nlohmann::ordered_json coords = nlohmann::ordered_json::array();
  for (const auto& v0 : folded.vertices) {
    const Eigen::Vector3d v = to_file_units(pattern, v0);  // the file's length units
    coords.push_back({v[0], v[1], v[2]});
  }
  frame["vertices_coords"] = std::move(coords);
  nlohmann::ordered_json angles = nlohmann::ordered_json::array();
  for (int e = 0; e < fold_angles.size(); ++e) angles.push_back(fold_angles[e] * 180.0 / std::numbers::pi);
  frame["edges_foldAngle"] = std::move(angles);
  frame["rigidfold:closure_mismatch"] = to_file_units(pattern, folded.max_mismatch);
  if (!out.extra.contains("file_frames")) out.extra["file_frames"] = nlohmann::ordered_json::array();
  out.extra["file_frames"].push_back(std::move(frame));
  return out;
}

std::string folded_obj(const CreasePattern& pattern, const FoldedGeometry& folded) {
  std::string s = "# rigidfold folded state\n";
  char buf[128];
  for (const auto& v0 : folded.vertices) {
    const Eigen::Vector3d v = to_file_units(pattern, v0);
    std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", v[0], v[1], v[2]);
    s += buf;
  }
  for (const auto& f : pattern.faces) {
    s += "f";
    for (int v : f) {
      s += ' ';  // appended piecewise: GCC 12 -Wrestrict false positive on " " + string&&
      s += std::to_string(v + 1);
    }
    s += "\n";
  }
  return s;
}

namespace {


void put_u32(std::string& out, std::uint32_t x) {
  for (int k = 0; k < 4; ++k) out += static_cast<char>((x >> (8 * k)) & 0xffu);
}
void put_f32(std::string& out, double x) {
  const float f = static_cast<float>(x);
  std::uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  put_u32(out, bits);  // little-endian whatever the host's byte order
}

// STL holds float32 coordinates: a pattern whose coordinates (the file's units) pass float32's
// largest value would be written as inf, and one smaller than float32's normal range keeps
// 24 significant bits of its size (so its details) only down to 2^-126 * 2^24 = 2e-31; at
// 1e-300 every vertex would round to 0. Such a pattern is refused (std::invalid_argument, exit
// 2), naming why, instead of writing a file that does not hold it.
void check_float32_range(const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Eigen::Vector3d& x : points) {
    largest = std::max(largest, x.cwiseAbs().maxCoeff());
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  char text[160];
  if (!(largest <= std::numeric_limits<float>::max())) {
    std::snprintf(text, sizeof text, "STL: coordinates up to %.3g (the file's units) do not fit float32 (largest %.3g): "
                  "rescale the pattern first", largest, static_cast<double>(std::numeric_limits<float>::max()));
    throw std::invalid_argument(text);
  }
  const double size = points.empty() ? 0.0 : (hi - lo).maxCoeff();
  const double smallest = std::ldexp(static_cast<double>(std::numeric_limits<float>::min()), 24);
  if (!points.empty() && size < smallest) {
    std::snprintf(text, sizeof text, "STL: the model's size %.3g (the file's units) is below what float32 holds to its "
                  "precision (%.3g): rescale the pattern first", size, smallest);
    throw std::invalid_argument(text);
  }
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_face(const CreasePattern& pattern, const std::vector<int>& face) {
  const int m = static_cast<int>(face.size());
  Eigen::Vector3d n = newell_normal(pattern, face);
  if (m < 3 || !(n.norm() > 0)) throw std::invalid_argument("face with no area cannot be triangulated");
  n.normalize();
  // In-plane axes: any unit vector perpendicular to n, and n x it (counter-clockwise about n).
  Eigen::Vector3d u = std::fabs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  u = (u - u.dot(n) * n).normalized();
  const Eigen::Vector3d w = n.cross(u);
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int v : face) c += pattern.vertices[v];
  c /= m;
  std::vector<Eigen::Vector2d> q(m);
  double scale2 = 0;
  for (int i = 0; i < m; ++i) {
    const Eigen::Vector3d d = pattern.vertices[face[i]] - c;
    q[i] = Eigen::Vector2d(d.dot(u), d.dot(w));
    scale2 = std::max(scale2, q[i].squaredNorm());
  }
  // Orientation test with a margin of rounding: |cross| below it counts as collinear.
  const double eps = 1e-13 * scale2;
  auto orient = [&](int a, int b, int p) { return cross2(q[b] - q[a], q[p] - q[a]); };
  std::vector<int> ring(m);
  for (int i = 0; i < m; ++i) ring[i] = i;
  std::vector<std::array<int, 3>> out;
  out.reserve(m - 2);
  while (ring.size() > 3) {
    const int r = static_cast<int>(ring.size());
    bool clipped = false;
    for (int k = 0; k < r && !clipped; ++k) {
      const int a = ring[(k + r - 1) % r], b = ring[k], cc = ring[(k + 1) % r];
      const double turn = orient(a, b, cc);
      if (std::fabs(turn) <= eps) {
        // b on the straight side from a to cc: no triangle, the side passes through it.
        if ((q[b] - q[a]).dot(q[cc] - q[b]) > 0) {
          ring.erase(ring.begin() + k);
          clipped = true;
        }
        continue;
      }
      if (turn < 0) continue;  // reflex corner
      // An ear: no other corner inside the triangle or on its sides.
      bool empty = true;
      for (int j : ring) {
        if (j == a || j == b || j == cc) continue;
        if (orient(a, b, j) >= -eps && orient(b, cc, j) >= -eps && orient(cc, a, j) >= -eps) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.push_back({face[a], face[b], face[cc]});
      ring.erase(ring.begin() + k);
      clipped = true;
    }
    if (!clipped) throw std::invalid_argument("face crosses itself: no ear to clip");
  }
  if (orient(ring[0], ring[1], ring[2]) > eps) out.push_back({face[ring[0]], face[ring[1]], face[ring[2]]});
  if (out.empty()) throw std::invalid_argument("face with no area cannot be triangulated");
  return out;
}

std::string folded_stl(const CreasePattern& pattern, const FoldedGeometry& folded) {
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangle_face;
  for (int f = 0; f < pattern.num_faces(); ++f) {
    std::vector<std::array<int, 3>> t;
    try {
      t = triangulate_face(pattern, pattern.faces[f]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("STL: face " + std::to_string(f) + ": " + e.what());
    }
    triangles.insert(triangles.end(), t.begin(), t.end());
    triangle_face.insert(triangle_face.end(), t.size(), f);
  }
  if (triangles.size() >= (std::size_t{1} << 32)) throw std::invalid_argument("STL: 2^32 triangles or more");
  std::vector<Eigen::Vector3d> corners;  // every triangle's corners, placed, in the file's units
  corners.reserve(3 * triangles.size());
  for (std::size_t k = 0; k < triangles.size(); ++k)
    for (int v : triangles[k]) corners.push_back(to_file_units(pattern, folded.face_motions[triangle_face[k]] * pattern.vertices[v]));
  check_float32_range(corners);
  std::string out(80, ' ');
  const std::string title = "rigidfold folded state (binary STL, float32 little-endian)";  // not "solid...": not ASCII STL
  out.replace(0, title.size(), title);
  out.reserve(84 + 50 * triangles.size());
  put_u32(out, static_cast<std::uint32_t>(triangles.size()));
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const int f = triangle_face[k];
    const Eigen::Isometry3d& motion = folded.face_motions[f];
    const Eigen::Vector3d normal = (motion.linear() * newell_normal(pattern, pattern.faces[f])).normalized();
    for (int i = 0; i < 3; ++i) put_f32(out, normal[i]);
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i) put_f32(out, corners[3 * k + c][i]);
    out += '\0';
    out += '\0';
  }
  return out;
}

std::string polygons_stl(const std::vector<std::vector<Eigen::Vector3d>>& polygons, int length_exponent,
                         const std::string& title) {
  CreasePattern carrier;  // one polygon at a time, so triangulate_face does the work
  carrier.coords_2d = false;
  carrier.length_exponent = length_exponent;
  std::vector<std::array<Eigen::Vector3d, 3>> triangles;
  std::vector<Eigen::Vector3d> normals;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    carrier.vertices = polygons[k];
    std::vector<int> face(polygons[k].size());
    for (std::size_t i = 0; i < face.size(); ++i) face[i] = static_cast<int>(i);
    std::vector<std::array<int, 3>> t;
    try {
      t = triangulate_face(carrier, face);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("STL: polygon " + std::to_string(k) + ": " + e.what());
    }
    const Eigen::Vector3d normal = newell_normal(carrier, face).normalized();
    for (const auto& tri : t) {
      triangles.push_back({to_file_units(carrier, polygons[k][tri[0]]), to_file_units(carrier, polygons[k][tri[1]]),
                           to_file_units(carrier, polygons[k][tri[2]])});
      normals.push_back(normal);
    }
  }
  if (triangles.size() >= (std::size_t{1} << 32)) throw std::invalid_argument("STL: 2^32 triangles or more");
  std::vector<Eigen::Vector3d> corners;
  corners.reserve(3 * triangles.size());
  for (const auto& t : triangles) corners.insert(corners.end(), t.begin(), t.end());
  check_float32_range(corners);
  std::string out(80, ' ');
  out.replace(0, std::min<std::size_t>(title.size(), 80), title.substr(0, 80));
  out.reserve(84 + 50 * triangles.size());
  put_u32(out, static_cast<std::uint32_t>(triangles.size()));
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    for (int i = 0; i < 3; ++i) put_f32(out, normals[k][i]);
    for (const Eigen::Vector3d& x : triangles[k])
      for (int i = 0; i < 3; ++i) put_f32(out, x[i]);
    out += '\0';
    out += '\0';
  }
  return out;
}

}  // namespace rigidfold
