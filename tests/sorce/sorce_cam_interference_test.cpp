// Cam interference of SORCE solids along the path (design/sorce/sorce_cam_interference.hpp):
// FCL's verdicts against an independent point test (cam corners strictly inside the mate's
// convex slab, by its face planes), and the rolling partners' cams not counted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "design/sorce/sorce_cam_interference.hpp"
#include "tests/sorce/sorce_pattern_requests.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::kVertexA;
PatternSorceRequest vertex_a_request(double h) { return testing::single_vertex_request(h); }

// Depth of x inside the convex shell `polygons` (outward polygons): min over its planes of
// the distance behind the plane (> 0 strictly inside).
double depth_inside(const std::vector<Polygon3>& polygons, const Eigen::Vector3d& x) {
  double depth = 1e300;
  for (const Polygon3& p : polygons) {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();  // Newell normal, outward
    for (std::size_t k = 0; k < p.size(); ++k) n += p[k].cross(p[(k + 1) % p.size()]);
    n.normalize();
    depth = std::min(depth, -(x - p[0]).dot(n));
  }
  return depth;
}

std::vector<Polygon3> shell_polygons(const PanelSolid& s, int shell) {
  std::vector<Polygon3> out;
  for (std::size_t k = 0; k < s.polygons.size(); ++k)
    if (s.shell_of_polygon[k] == shell) out.push_back(s.polygons[k]);
  return out;
}

// Every sample t and cam whose corner lies inside its mate's slab by more than 1e-6 h: the
// pair (cam's face and crease, mate's slab) must be among FCL's collisions at that t.
int penetrations_missed_by_fcl(const CreasePattern& p, const PatternSorce& s, const PatternSolids& solids,
                               const CamInterference& c, double h, int* found) {
  const Topology topology = build_topology(p, "pattern");
  int missed = 0;
  *found = 0;
  for (double t : c.times) {
    const auto poses = panel_poses(p, topology, s, t);
    for (const CreaseJoint& j : s.creases) {
      if (!j.folds) continue;
      for (const auto& [f, g] : {std::pair{j.left_face, j.right_face}, std::pair{j.right_face, j.left_face}}) {
        const PanelSolid& ps = solids.panels[f];
        int shell = -1;
        for (std::size_t k = 0; k < ps.cam_of_shell.size(); ++k)
          if (solids.cam_edge[f][ps.cam_of_shell[k]] == j.edge) shell = static_cast<int>(k) + 1;
        if (shell < 0) continue;
        const std::vector<Polygon3> mate_slab = shell_polygons(solids.panels[g], 0);
        bool inside = false;
        for (const Polygon3& poly : shell_polygons(ps, shell))
          for (const Eigen::Vector3d& x : poly)
            inside = inside || depth_inside(mate_slab, poses[g].inverse() * (poses[f] * x)) > 1e-6 * h;
        if (!inside) continue;
        ++*found;
        bool listed = false;
        for (const CamCollision& k : c.collisions)
          listed = listed || (k.t == t && ((k.face_a == f && k.edge_a == j.edge && k.face_b == g && k.edge_b == -1) ||
                                           (k.face_b == f && k.edge_b == j.edge && k.face_a == g && k.edge_a == -1)));
        if (!listed) ++missed;
      }
    }
  }
  return missed;
}

TEST(SorceCamInterference, VertexALinearCamsHitTheirMatesSlabsWhereThePointTestSaysSo) {
  const CreasePattern p = read_fold(kVertexA);
  const double h = 0.1;
  const PatternSorce s = pattern_sorce(p, vertex_a_request(h));
  const PatternSolids solids = pattern_solids(p, s, 101);
  const CamInterference c = cam_interference(p, s, solids, 21);
  int found = 0;
  EXPECT_EQ(penetrations_missed_by_fcl(p, s, solids, c, h, &found), 0);
  std::printf("vertex A, linear offsets, h = 0.1: %zu cam collisions over 21 samples (%lld pairs tested); "
              "point test: %d cam-in-mate-slab penetrations\n",
              c.collisions.size(), c.pairs_tested, found);
  if (!c.collisions.empty())
    std::printf("  first: t %.3f faces %d %d cam edges %d %d\n", c.collisions[0].t, c.collisions[0].face_a,
                c.collisions[0].face_b, c.collisions[0].edge_a, c.collisions[0].edge_b);
  // Vertex A's linear cams protrude (fold report) and do cut into their mates: the case the
  // clearance cuts are for.
  EXPECT_GT(found, 0);
  EXPECT_EQ(c.partner_pairs_skipped, 4);  // one per folding crease
  for (const CamCollision& k : c.collisions) {
    EXPECT_LT(k.face_a, k.face_b);
    EXPECT_TRUE(k.edge_a >= 0 || k.edge_b >= 0);  // never slab against slab
  }
}

TEST(SorceCamInterference, CircularJointAloneDoesNotCountItsOwnRollingContact) {
  // One crease between two squares, made a circular CORE joint: its cams are arcs of radius
  // h/2 inside the slabs' faces, touching only each other (the rolling contact, skipped).
  const CreasePattern p = parse_fold(
      R"({"file_spec":1.1,"vertices_coords":[[0,0],[1,0],[2,0],[2,1],[1,1],[0,1]],)"
      R"("edges_vertices":[[1,4],[0,1],[1,2],[2,3],[3,4],[4,5],[5,0]],"edges_assignment":["V","B","B","B","B","B","B"],)"
      R"("faces_vertices":[[0,1,4,5],[1,2,3,4]]})",
      "two squares");
  const double h = 0.1;
  PatternSorceRequest rq;
  rq.thickness = h;
  rq.trace.drive = 0;
  rq.trace.to = M_PI;
  rq.trace.steps = 20;
  rq.circular_edges = {0};
  const PatternSorce s = pattern_sorce(p, rq);
  const PatternSolids solids = pattern_solids(p, s, 101);
  const CamInterference c = cam_interference(p, s, solids, 21);
  EXPECT_EQ(c.partner_pairs_skipped, 1);
  EXPECT_TRUE(c.collisions.empty()) << c.collisions.size() << " first at t " << c.collisions[0].t;
  EXPECT_GT(c.pairs_tested, 0);  // each cam met the other panel's slab in the broad phase
}

}}  // namespace
}  // namespace rigidfold::sorce
