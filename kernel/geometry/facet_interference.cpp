#include "kernel/geometry/facet_interference.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>

namespace rigidfold {
namespace {

using Tri = std::array<Eigen::Vector3d, 3>;

// Segment p-q pierces the interior of triangle t (strictly, beyond eps).
bool pierces(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Tri& t, double eps) {
  Eigen::Vector3d nrm = (t[1] - t[0]).cross(t[2] - t[0]);
  const double area2 = nrm.norm();
  if (area2 <= eps * eps) return false;  // degenerate triangle
  nrm /= area2;
  const double dp = nrm.dot(p - t[0]), dq = nrm.dot(q - t[0]);
  if (!((dp > eps && dq < -eps) || (dp < -eps && dq > eps))) return false;
  const Eigen::Vector3d x = p + (dp / (dp - dq)) * (q - p);
  // Barycentric coordinates, scaled to lengths (distance of x from each edge line).
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d& a = t[i];
    const Eigen::Vector3d& b = t[(i + 1) % 3];
    const Eigen::Vector3d edge = b - a;
    const double dist = nrm.dot(edge.cross(x - a)) / edge.norm();  // > 0 inside (CCW about nrm)
    if (dist <= eps) return false;
  }
  return true;
}

bool triangles_cross(const Tri& a, const Tri& b, double eps) {
  for (int i = 0; i < 3; ++i) {
    if (pierces(a[i], a[(i + 1) % 3], b, eps)) return true;
    if (pierces(b[i], b[(i + 1) % 3], a, eps)) return true;
  }
  return false;
}

struct Scene {
  std::vector<std::vector<Tri>> triangles;  // per face
  double eps = 0;
  std::vector<std::pair<int, int>> pairs;
  long long candidates = 0;
};

bool on_overlap(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* scene = static_cast<Scene*>(data);
  int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
  int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
  if (a == b) return false;
  if (a > b) std::swap(a, b);
  ++scene->candidates;
  for (const Tri& ta : scene->triangles[a])
    for (const Tri& tb : scene->triangles[b])
      if (triangles_cross(ta, tb, scene->eps)) {
        scene->pairs.emplace_back(a, b);
        return false;
      }
  return false;  // keep going: report every pair
}

}  // namespace

FacetInterference find_facet_interference(const CreasePattern& pattern, const std::vector<Eigen::Vector3d>& positions,
                                          double relative_tolerance) {
  if (static_cast<int>(positions.size()) != pattern.num_vertices())
    throw std::invalid_argument("find_facet_interference: one position per vertex needed");
  FacetInterference out;
  if (pattern.faces.empty()) return out;
  Eigen::Vector3d lo = positions[0], hi = positions[0];
  for (const auto& x : positions) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  Scene scene;
  scene.eps = relative_tolerance * std::max((hi - lo).norm(), 1e-300);
  const int nf = static_cast<int>(pattern.faces.size());
  scene.triangles.resize(nf);
  std::vector<std::shared_ptr<fcl::BVHModel<fcl::AABBd>>> models(nf);
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects(nf);
  std::vector<fcl::CollisionObjectd*> raw(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& face = pattern.faces[f];
    std::vector<Eigen::Vector3d> pts;
    std::vector<fcl::Triangle> tris;
    for (int v : face) pts.push_back(positions[v]);
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      scene.triangles[f].push_back({positions[face[0]], positions[face[i]], positions[face[i + 1]]});
      tris.emplace_back(0, i, i + 1);
    }
    models[f] = std::make_shared<fcl::BVHModel<fcl::AABBd>>();
    models[f]->beginModel();
    models[f]->addSubModel(pts, tris);
    models[f]->endModel();
    objects[f] = std::make_unique<fcl::CollisionObjectd>(models[f]);
    objects[f]->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(f)));
    raw[f] = objects[f].get();
  }
  fcl::DynamicAABBTreeCollisionManagerd manager;
  manager.registerObjects(raw);
  manager.setup();
  manager.collide(&scene, on_overlap);
  std::sort(scene.pairs.begin(), scene.pairs.end());
  scene.pairs.erase(std::unique(scene.pairs.begin(), scene.pairs.end()), scene.pairs.end());
  out.face_pairs = std::move(scene.pairs);
  out.candidate_pairs = scene.candidates;
  return out;
}

}  // namespace rigidfold
