#include "design/sorce/sorce_cam_interference.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold::sorce {
namespace {

using Model = fcl::BVHModel<fcl::OBBRSSd>;

struct Shell {
  int face = -1, edge = -1;  // edge -1: the slab
  std::shared_ptr<Model> model;
};

// One shell's polygons as an FCL mesh, each polygon ear-clipped (cam end caps are not convex),
// z shrunk toward the mid-plane by `shrink` (see the header: touching is not interference).
std::shared_ptr<Model> shell_model(const std::vector<Polygon3>& polygons, double shrink) {
  std::vector<fcl::Vector3d> v;
  std::vector<fcl::Triangle> tris;
  CreasePattern carrier;  // triangulate_face works on a pattern's vertices
  carrier.coords_2d = false;
  for (const Polygon3& poly : polygons) {
    carrier.vertices = poly;
    std::vector<int> face(poly.size());
    for (std::size_t i = 0; i < face.size(); ++i) face[i] = static_cast<int>(i);
    const auto t = triangulate_face(carrier, face);
    const int base = static_cast<int>(v.size());
    for (const Eigen::Vector3d& x : poly) v.emplace_back(x.x(), x.y(), x.z() * shrink);
    for (const auto& k : t) tris.emplace_back(base + k[0], base + k[1], base + k[2]);
  }
  auto m = std::make_shared<Model>();
  m->beginModel();
  m->addSubModel(v, tris);
  m->endModel();
  return m;
}

struct Scene {
  const std::vector<Shell>* shells = nullptr;
  const std::vector<std::vector<int>>* partner = nullptr;  // partner[s] = shells rolling on s
  double t = 0.0;
  std::vector<CamCollision>* out = nullptr;
  long long tested = 0;
};

bool on_overlap(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* scene = static_cast<Scene*>(data);
  int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
  int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
  const std::vector<Shell>& s = *scene->shells;
  if (s[a].face == s[b].face) return false;          // one printed part (slab pieces and cams overlap)
  if (s[a].edge < 0 && s[b].edge < 0) return false;  // slab against slab: the slab check's job
  const auto& pa = (*scene->partner)[a];
  if (std::find(pa.begin(), pa.end(), b) != pa.end()) return false;  // the rolling contact itself
  ++scene->tested;
  fcl::CollisionRequestd rq;
  fcl::CollisionResultd rs;
  if (fcl::collide(o1, o2, rq, rs) > 0) {
    if (s[a].face > s[b].face) std::swap(a, b);
    scene->out->push_back({scene->t, s[a].face, s[b].face, s[a].edge, s[b].edge});
  }
  return false;  // keep going: every pair
}

}  // namespace

CamInterference cam_interference(const CreasePattern& pattern, const PatternSorce& sorce, const PatternSolids& solids,
                                 int samples) {
  if (samples < 2) throw InputError("samples", "must be >= 2");
  const int nf = pattern.num_faces();
  if (static_cast<int>(solids.panels.size()) != nf || static_cast<int>(solids.cam_edge.size()) != nf)
    throw std::invalid_argument("cam_interference: one solid per face expected");
  const Topology topology = build_topology(pattern, "pattern");
  std::vector<Shell> shells;
  for (int f = 0; f < nf; ++f) {
    const PanelSolid& ps = solids.panels[f];
    const int n_shells = static_cast<int>(ps.shell_volumes.size());
    std::vector<std::vector<Polygon3>> by_shell(n_shells);
    for (std::size_t k = 0; k < ps.polygons.size(); ++k) by_shell[ps.shell_of_polygon[k]].push_back(ps.polygons[k]);
    const double shrink = 1.0 - 2e-9;
    for (int k = 0; k < n_shells; ++k) {
      Shell sh;
      sh.face = f;
      const bool cam = k >= 1 && k <= static_cast<int>(ps.cam_of_shell.size());  // after the cams: slab pieces
      sh.edge = cam ? solids.cam_edge[f][ps.cam_of_shell[k - 1]] : -1;
      sh.model = shell_model(by_shell[k], shrink);
      shells.push_back(std::move(sh));
    }
  }
  const int ns = static_cast<int>(shells.size());
  std::vector<std::vector<int>> partner(ns);
  int partners = 0;
  for (int a = 0; a < ns; ++a)
    for (int b = 0; b < ns; ++b)
      if (a != b && shells[a].edge >= 0 && shells[a].edge == shells[b].edge && shells[a].face != shells[b].face) {
        partner[a].push_back(b);
        if (a < b) ++partners;
      }
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  std::vector<fcl::CollisionObjectd*> raw;
  for (int k = 0; k < ns; ++k) {
    objects.push_back(std::make_unique<fcl::CollisionObjectd>(shells[k].model));
    objects.back()->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(k)));
    raw.push_back(objects.back().get());
  }
  CamInterference out;
  for (int i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / (samples - 1);
    out.times.push_back(t);
    const std::vector<Eigen::Isometry3d> poses = panel_poses(pattern, topology, sorce, t);
    for (int k = 0; k < ns; ++k) {
      objects[k]->setTransform(fcl::Transform3d(poses[shells[k].face].matrix()));
      objects[k]->computeAABB();
    }
    fcl::DynamicAABBTreeCollisionManagerd manager;
    manager.registerObjects(raw);
    manager.setup();
    Scene scene;
    scene.shells = &shells;
    scene.partner = &partner;
    scene.t = t;
    std::vector<CamCollision> hits;
    scene.out = &hits;
    manager.collide(&scene, on_overlap);
    std::sort(hits.begin(), hits.end(), [](const CamCollision& x, const CamCollision& y) {
      return std::tie(x.face_a, x.face_b, x.edge_a, x.edge_b) < std::tie(y.face_a, y.face_b, y.edge_a, y.edge_b);
    });
    out.collisions.insert(out.collisions.end(), hits.begin(), hits.end());
    out.pairs_tested += scene.tested;
    out.partner_pairs_skipped = partners;
  }
  return out;
}

}  // namespace rigidfold::sorce
