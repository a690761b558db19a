#pragma once
// Binary STL read back for tests: triangles (float32 as written), a closed-manifold check
// on the exact float vertices, and the enclosed volume (divergence theorem).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace rigidfold::testing {

struct StlTriangle {
  Eigen::Vector3d normal, v[3];
  std::uint16_t attribute = 0;
};

inline std::uint32_t stl_u32(const std::string& s, std::size_t at) {
  std::uint32_t x = 0;
  for (int k = 0; k < 4; ++k) x |= static_cast<std::uint32_t>(static_cast<unsigned char>(s[at + k])) << (8 * k);
  return x;
}
inline double stl_f32(const std::string& s, std::size_t at) {
  const std::uint32_t bits = stl_u32(s, at);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Expects rigidfold's header and a size that matches the count.
inline std::vector<StlTriangle> parse_stl(const std::string& bytes) {
  EXPECT_GE(bytes.size(), 84u);
  if (bytes.size() < 84) return {};
  EXPECT_EQ(bytes.substr(0, 9), "rigidfold");
  const std::uint32_t n = stl_u32(bytes, 80);
  EXPECT_EQ(bytes.size(), 84u + 50u * n);
  std::vector<StlTriangle> out;
  for (std::uint32_t k = 0; k < n && 84 + 50 * (std::size_t{k} + 1) <= bytes.size(); ++k) {
    const std::size_t at = 84 + 50 * std::size_t{k};
    StlTriangle t;
    for (int i = 0; i < 3; ++i) t.normal[i] = stl_f32(bytes, at + 4 * i);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) t.v[j][i] = stl_f32(bytes, at + 12 + 12 * j + 4 * i);
    t.attribute = static_cast<std::uint16_t>(static_cast<unsigned char>(bytes[at + 48]) | (static_cast<unsigned char>(bytes[at + 49]) << 8));
    out.push_back(t);
  }
  return out;
}

// Closed, consistently oriented surface: every directed edge (a, b) between exact vertex
// positions occurs once, and its reverse (b, a) once. Returns the number of offending edges.
inline int open_or_misoriented_edges(const std::vector<StlTriangle>& tris) {
  using Key = std::tuple<double, double, double>;
  auto key = [](const Eigen::Vector3d& p) { return Key(p.x(), p.y(), p.z()); };
  std::map<std::pair<Key, Key>, int> directed;
  for (const StlTriangle& t : tris)
    for (int j = 0; j < 3; ++j) ++directed[{key(t.v[j]), key(t.v[(j + 1) % 3])}];
  int bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
  }
  return bad;
}

// Volume enclosed by outward triangles (sum of signed tetrahedra from the origin).
inline double enclosed_volume(const std::vector<StlTriangle>& tris) {
  double v = 0.0;
  for (const StlTriangle& t : tris) v += t.v[0].dot(t.v[1].cross(t.v[2])) / 6.0;
  return v;
}

}  // namespace rigidfold::testing
