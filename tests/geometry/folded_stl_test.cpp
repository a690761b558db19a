// Binary STL of a folded state (kernel/geometry/folded_output.hpp, folded_stl): the bytes
// parsed back here give the triangle count of the faces' triangulations, unit normals that
// agree with each triangle's winding, and a total area equal to the crease pattern's flat
// area (rigid folding keeps every face), within the rounding of the vertices to float32.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/stl_mesh.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::parse_stl;
using testing::StlTriangle;

// Float32 rounding: each coordinate moves by at most 2^-24 of the largest |coordinate| M, so
// a triangle's doubled area (b - a) x (c - a) changes by at most
// 2 * sqrt(3) * 2^-24 * M * 2 * (|b - a| + |c - a|) to first order (each difference moves
// by <= 2 sqrt(3) 2^-24 M); summed over the triangles, with a factor 2 for second order.
void check_stl(const CreasePattern& p, const Topology& t, const FoldedGeometry& g, const std::string& name) {
  SCOPED_TRACE(name);
  const auto tris = parse_stl(folded_stl(p, g));
  std::size_t expected = 0;
  for (const auto& f : p.faces) expected += f.size() - 2;  // no bundled face has a vertex on a straight side
  EXPECT_EQ(tris.size(), expected);
  double M = 0;
  for (const auto& tr : tris)
    for (const auto& v : tr.v) M = std::max(M, v.cwiseAbs().maxCoeff());
  const double u = std::ldexp(1.0, -24);
  double area = 0, bound = 0;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const auto& tr = tris[k];
    EXPECT_NEAR(tr.normal.norm(), 1.0, 2 * u) << "triangle " << k;  // each component rounded to float
    EXPECT_EQ(tr.attribute, 0);
    const Eigen::Vector3d c = (tr.v[1] - tr.v[0]).cross(tr.v[2] - tr.v[0]);
    ASSERT_GT(c.norm(), 0) << "triangle " << k;
    // The winding's normal is the written normal, up to the tilt float rounding gives it:
    // 4 sqrt(3) u M (|b - a| + |c - a|) / |c| radians at most.
    const double tilt = 4 * std::sqrt(3.0) * u * M * ((tr.v[1] - tr.v[0]).norm() + (tr.v[2] - tr.v[0]).norm()) / c.norm();
    EXPECT_GT(c.normalized().dot(tr.normal), 1 - tilt - 2 * u) << "triangle " << k;
    area += 0.5 * c.norm();
    bound += 2 * 0.5 * 4 * std::sqrt(3.0) * u * M * ((tr.v[1] - tr.v[0]).norm() + (tr.v[2] - tr.v[0]).norm());
  }
  double flat = 0;
  for (double a : t.face_areas) flat += a;
  flat = std::ldexp(flat, 2 * p.length_exponent);
  EXPECT_NEAR(area, flat, bound) << "flat area " << flat;
}

TEST(FoldedStl, BundledPatternsFoldedToTheirAnglesKeepTheirArea) {
  int folded = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled")) {
    if (entry.path().extension() != ".fold") continue;
    const CreasePattern p = read_fold(entry.path().string());
    const Topology t = build_topology(p, entry.path().string());
    // The file's fold angles (0 where none) from its own reference state: the bundled 12 x 12
    // Miura folds, a flat pattern stays flat, the tube keeps its given 3D state.
    const Eigen::VectorXd ref = reference_fold_angles(p, t);
    Eigen::VectorXd rho = ref;
    for (int e = 0; e < p.num_edges(); ++e)
      if (p.fold_angles[e] && t.edge_is_hinge[e]) rho[e] = *p.fold_angles[e];
    const FoldedGeometry g = place_faces(p, t, rho, ref);
    if ((rho - ref).cwiseAbs().maxCoeff() > 0.1) ++folded;
    check_stl(p, t, g, entry.path().string());
  }
  EXPECT_GE(folded, 1);
}

CreasePattern one_face(const std::vector<Eigen::Vector3d>& corners) {
  CreasePattern p;
  p.vertices = corners;
  std::vector<int> f;
  for (int i = 0; i < static_cast<int>(corners.size()); ++i) {
    p.edges.push_back({i, (i + 1) % static_cast<int>(corners.size())});
    p.assignments.push_back(Assignment::Boundary);
    p.fold_angles.push_back(std::nullopt);
    f.push_back(i);
  }
  p.faces = {f};
  return p;
}

double area2d(const CreasePattern& p, const std::array<int, 3>& t) {
  const Eigen::Vector3d a = p.vertices[t[0]], b = p.vertices[t[1]], c = p.vertices[t[2]];
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

TEST(FoldedStl, EarClippingCoversANonConvexFaceCounterClockwise) {
  // An L of area 3 whose fan from vertex 0 would leave the face (the reflex corner 3).
  const CreasePattern p = one_face({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
  const auto tris = triangulate_face(p, p.faces[0]);
  ASSERT_EQ(tris.size(), 4u);
  double total = 0;
  for (const auto& t : tris) {
    EXPECT_GT(area2d(p, t), 0);  // counter-clockwise, none degenerate
    // Its centroid lies inside the L (not in the missing square [1,2] x [1,2]).
    const Eigen::Vector3d c = (p.vertices[t[0]] + p.vertices[t[1]] + p.vertices[t[2]]) / 3;
    EXPECT_FALSE(c.x() > 1 && c.y() > 1) << c.transpose();
    total += area2d(p, t);
  }
  EXPECT_NEAR(total, 3.0, 1e-15);
  // A vertex on a straight side gives no zero-area triangle.
  const CreasePattern q = one_face({{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  double tq = 0;
  for (const auto& t : triangulate_face(q, q.faces[0])) {
    EXPECT_GT(area2d(q, t), 1e-3);
    tq += area2d(q, t);
  }
  EXPECT_NEAR(tq, 1.0, 1e-15);
  // A face that crosses itself (a bow tie) has no triangulation.
  const CreasePattern bow = one_face({{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}});
  EXPECT_THROW(triangulate_face(bow, bow.faces[0]), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold
