// Global facet interference (kernel/geometry/facet_interference.hpp): FCL broad phase, strict
// piercing test. Hand-made face pairs (crossing, touching at a vertex, coplanar layers), the
// folded Miura (layers, never crossing) and a strip whose outer panels cross.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "data/generators/miura.hpp"
#include "kernel/geometry/facet_interference.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {


// Two triangles as separate faces (no shared vertex unless `share`).
CreasePattern two_triangles(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b, bool share) {
  CreasePattern p;
  for (const auto& v : a) p.vertices.push_back(v);
  const int base = share ? 2 : 3;
  for (int i = share ? 1 : 0; i < 3; ++i) p.vertices.push_back(b[i]);
  p.faces.push_back({0, 1, 2});
  if (share) p.faces.push_back({0, base + 1, base + 2});
  else p.faces.push_back({3, 4, 5});
  return p;
}

TEST(FacetInterference, CrossingTouchingAndCoplanarPairs) {
  using V = Eigen::Vector3d;
  const std::vector<V> flat{V(0, 0, 0), V(2, 0, 0), V(0, 2, 0)};
  // A triangle standing through the first one.
  const std::vector<V> through{V(0.5, 0.5, -1), V(0.5, 0.5, 1), V(1.5, -1, 0.2)};
  const CreasePattern crossing = two_triangles(flat, through, false);
  EXPECT_EQ(find_facet_interference(crossing, crossing.vertices).face_pairs.size(), 1u);
  // Moved clear of it (x + 3): no crossing.
  std::vector<V> clear = through;
  for (auto& v : clear) v.x() += 3;
  const CreasePattern apart = two_triangles(flat, clear, false);
  EXPECT_TRUE(find_facet_interference(apart, apart.vertices).face_pairs.empty());
  // Sharing vertex 0 and leaving upward: contact at a point, not interference.
  const std::vector<V> hinge{V(0, 0, 0), V(1, 1, 1), V(-1, 1, 1)};
  const CreasePattern touching = two_triangles(flat, hinge, true);
  EXPECT_TRUE(find_facet_interference(touching, touching.vertices).face_pairs.empty());
  // Sharing vertex 0 but passing through the first face: interference.
  const std::vector<V> pierce{V(0, 0, 0), V(1, 0.5, -1), V(0.5, 1, 1)};
  const CreasePattern piercing = two_triangles(flat, pierce, true);
  EXPECT_EQ(find_facet_interference(piercing, piercing.vertices).face_pairs.size(), 1u);
  // Coplanar overlapping layers (a flat-folded stack): contact, not interference.
  const std::vector<V> layer{V(0.2, 0.2, 0), V(1.5, 0.2, 0), V(0.2, 1.5, 0)};
  const CreasePattern stacked = two_triangles(flat, layer, false);
  EXPECT_TRUE(find_facet_interference(stacked, stacked.vertices).face_pairs.empty());
}

TEST(FacetInterference, FoldedMiuraLayersNeverCross) {
  generators::MiuraParams m;
  m.rows = m.cols = 6;
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  for (double deg : {30.0, 90.0, 150.0, 175.0}) {
    const Eigen::VectorXd rho = fold_angle_vector(generators::miura_fold_angles(p, m, deg * kPi / 180));
    const FoldedGeometry g = place_faces(p, t, rho, reference_fold_angles(p, t));
    const FacetInterference fi = find_facet_interference(p, g.vertices);
    EXPECT_TRUE(fi.face_pairs.empty()) << deg << " deg: faces " << fi.face_pairs.front().first << ", "
                                        << fi.face_pairs.front().second;
    std::cout << "  miura 6x6 at " << deg << " deg: " << fi.candidate_pairs << " AABB pairs tested, none cross\n";
  }
}

// A strip of three panels, wide - narrow - wide, with two parallel valley creases folded
// alike: the outer panels (not adjacent) rise toward each other and cross above the middle
// one once they lean past it. Face placement of the fold angles, then the global test.
TEST(FacetInterference, StripWhoseOuterPanelsCross) {
  CreasePattern p;
  const double xs[4] = {0.0, 2.0, 2.5, 4.5};  // panel widths 2, 0.5, 2
  for (double x : xs) p.vertices.emplace_back(x, 0.0, 0.0);
  for (double x : xs) p.vertices.emplace_back(x, 1.0, 0.0);
  auto edge = [&](int a, int b, Assignment k) {
    p.edges.push_back({a, b});
    p.assignments.push_back(k);
  };
  edge(1, 5, Assignment::Valley);  // crease 0
  edge(2, 6, Assignment::Valley);  // crease 1
  for (int i = 0; i < 3; ++i) {
    edge(i, i + 1, Assignment::Boundary);
    edge(i + 4, i + 5, Assignment::Boundary);
  }
  edge(0, 4, Assignment::Boundary);
  edge(3, 7, Assignment::Boundary);
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  p.faces = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}};
  const Topology t = build_topology(p);
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
  // An outer panel's free edge is at horizontal distance -2 cos(rho) inward of its crease; the
  // two meet over the middle of the 0.5 gap when -2 cos(rho) >= 0.25, i.e. rho >= 97.2 deg.
  for (double deg : {60.0, 90.0, 150.0, 175.0}) {
    rho[0] = rho[1] = deg * kPi / 180;
    const FoldedGeometry g = place_faces(p, t, rho, reference_fold_angles(p, t));
    const FacetInterference fi = find_facet_interference(p, g.vertices);
    std::cout << "  strip folded " << deg << " deg: " << fi.face_pairs.size() << " crossing pair(s)\n";
    if (deg < 95) {
      EXPECT_TRUE(fi.face_pairs.empty()) << deg;
    } else {
      ASSERT_EQ(fi.face_pairs.size(), 1u) << deg;
      EXPECT_EQ(fi.face_pairs[0], (std::pair<int, int>{0, 2}));
    }
  }
}

}}  // namespace
}  // namespace rigidfold
