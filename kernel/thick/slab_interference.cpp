#include "kernel/thick/slab_interference.hpp"
#include "kernel/math/cross2.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/no_answer_error.hpp"

namespace rigidfold {

namespace {


// One shrunk slab in its panel's flat frame: polygon (counter-clockwise seen from +z) and
// z range, plus its FCL mesh.
struct LocalSlab {
  std::vector<Eigen::Vector2d> polygon;
  double lo = 0, hi = 0;
  std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> mesh;
};

// The polygon moved in by m on every side: vertex i where the inward offset lines of its two
// sides meet. Throws when the margin is too large for the polygon (a side turns round).
std::vector<Eigen::Vector2d> inset(const std::vector<Eigen::Vector2d>& p, double m, int face) {
  const std::size_t n = p.size();
  std::vector<Eigen::Vector2d> normal(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d d = (p[(i + 1) % n] - p[i]).normalized();
    normal[i] = Eigen::Vector2d(-d.y(), d.x());  // left of a counter-clockwise side: inward
  }
  std::vector<Eigen::Vector2d> q(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = normal[(i + n - 1) % n];
    const Eigen::Vector2d& b = normal[i];
    const double c = 1.0 + a.dot(b);
    if (!(c > 1e-6)) throw std::invalid_argument("slab interference: face " + std::to_string(face) + " folds back on itself at a corner");
    q[i] = p[i] + m * (a + b) / c;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!((q[(i + 1) % n] - q[i]).dot(p[(i + 1) % n] - p[i]) > 0))
      throw std::invalid_argument("slab interference: the margin is too large for face " + std::to_string(face));
  return q;
}

bool inside_polygon(const std::vector<Eigen::Vector2d>& q, const Eigen::Vector2d& x) {
  bool in = false;
  for (std::size_t i = 0, j = q.size() - 1; i < q.size(); j = i++)
    if ((q[i].y() > x.y()) != (q[j].y() > x.y()) &&
        x.x() < q[j].x() + (x.y() - q[j].y()) * (q[i].x() - q[j].x()) / (q[i].y() - q[j].y()))
      in = !in;
  return in;
}

struct Scene {
  const std::vector<LocalSlab>* slabs = nullptr;
  const std::vector<Eigen::Isometry3d>* poses = nullptr;
  std::vector<std::pair<int, int>> pairs;
};

// Is a point of slab a (the mean of its polygon's vertices at mid-height, inside a convex
// slab) strictly inside slab b? With no crossing surfaces, that means a lies inside b.
bool point_inside(const Scene& s, int a, int b) {
  const LocalSlab& sa = (*s.slabs)[a];
  const LocalSlab& sb = (*s.slabs)[b];
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& q : sa.polygon) c += q;
  c /= static_cast<double>(sa.polygon.size());
  const Eigen::Vector3d world = (*s.poses)[a] * Eigen::Vector3d(c.x(), c.y(), 0.5 * (sa.lo + sa.hi));
  const Eigen::Vector3d local = (*s.poses)[b].inverse() * world;
  return local.z() > sb.lo && local.z() < sb.hi && inside_polygon(sb.polygon, local.head<2>());
}

bool on_overlap(fcl::CollisionObjectd* o1, fcl::CollisionObjectd* o2, void* data) {
  auto* scene = static_cast<Scene*>(data);
  int a = static_cast<int>(reinterpret_cast<std::intptr_t>(o1->getUserData()));
  int b = static_cast<int>(reinterpret_cast<std::intptr_t>(o2->getUserData()));
  if (a == b) return false;
  if (a > b) std::swap(a, b);
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  if (fcl::collide(o1, o2, request, result) > 0 || point_inside(*scene, a, b) || point_inside(*scene, b, a))
    scene->pairs.emplace_back(a, b);
  return false;  // keep going: every pair
}

}  // namespace

SlabInterference slab_interference(const CreasePattern& flat, const Topology& topology, const ThickHeightSheet& sheet,
                                   const std::vector<PanelSlab>& slabs, const std::vector<double>& drives,
                                   const std::vector<Eigen::VectorXd>& states, double margin) {
  const int nf = flat.num_faces();
  if (static_cast<int>(slabs.size()) != nf) throw std::invalid_argument("slab interference: one slab per face needed");
  if (drives.size() != states.size()) throw std::invalid_argument("slab interference: one driving angle per state needed");
  double thinnest = std::numeric_limits<double>::infinity();
  for (const PanelSlab& s : slabs) thinnest = std::min(thinnest, s.top - s.bottom);
  if (!(margin > 0) || !(margin < 0.25 * thinnest))
    throw std::invalid_argument("slab interference: the margin must be > 0 and below a quarter of the thinnest slab");

  // Sheet face of each flat face (its motion is the panel's).
  std::vector<int> sheet_face(nf, -1);
  for (int s = 0; s < static_cast<int>(sheet.flat_face_of_face.size()); ++s) {
    const int f = sheet.flat_face_of_face[s];
    if (f >= 0 && f < nf && sheet_face[f] < 0) sheet_face[f] = s;
  }
  // Hinge shared by each pair of faces.
  std::map<std::pair<int, int>, int> shared;
  for (int e = 0; e < flat.num_edges(); ++e) {
    if (!topology.edge_is_hinge[e]) continue;
    int a = topology.edge_faces[e][0], b = topology.edge_faces[e][1];
    if (a > b) std::swap(a, b);
    shared[{a, b}] = e;
  }

  // Shrunk slabs in their flat frames.
  std::vector<LocalSlab> local(nf);
  for (int f = 0; f < nf; ++f) {
    if (sheet_face[f] < 0) throw std::invalid_argument("slab interference: face " + std::to_string(f) + " has no face in the sheet");
    const std::vector<int>& face = flat.faces[f];
    std::vector<Eigen::Vector2d> p;
    for (int v : face) p.push_back(flat.vertices[v].head<2>());
    double area2 = 0;
    for (std::size_t i = 0; i < p.size(); ++i) area2 += cross2(p[i], p[(i + 1) % p.size()]);
    const bool reversed = area2 < 0;
    if (reversed) std::reverse(p.begin(), p.end());
    LocalSlab& s = local[f];
    s.polygon = inset(p, margin, f);
    s.lo = slabs[f].bottom + margin;
    s.hi = slabs[f].top - margin;
    // Triangles of the caps from the face's own ear clipping (same vertex order as p before
    // any reversal; orientation does not matter to FCL's collision test).
    const std::size_t n = p.size();
    std::map<int, int> position;
    for (std::size_t i = 0; i < n; ++i) position[face[i]] = reversed ? static_cast<int>(n - 1 - i) : static_cast<int>(i);
    std::vector<fcl::Vector3d> points;
    for (const Eigen::Vector2d& q : s.polygon) points.emplace_back(q.x(), q.y(), s.lo);
    for (const Eigen::Vector2d& q : s.polygon) points.emplace_back(q.x(), q.y(), s.hi);
    std::vector<fcl::Triangle> triangles;
    const int ni = static_cast<int>(n);
    for (const std::array<int, 3>& t : triangulate_face(flat, face)) {
      const int i = position[t[0]], j = position[t[1]], k = position[t[2]];
      triangles.emplace_back(i, j, k);
      triangles.emplace_back(ni + i, ni + j, ni + k);
    }
    for (int i = 0; i < ni; ++i) {
      const int j = (i + 1) % ni;
      triangles.emplace_back(i, j, ni + j);
      triangles.emplace_back(i, ni + j, ni + i);
    }
    s.mesh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    s.mesh->beginModel();
    s.mesh->addSubModel(points, triangles);
    s.mesh->endModel();
  }

  SlabInterference out;
  out.margin = margin;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const FoldedGeometry placed =
        place_faces(sheet.pattern, sheet.topology, sheet.sheet_edge_angles(states[k]), sheet.reference_edge_angles);
    if (!(placed.max_mismatch <= 0.1 * margin)) {
      std::ostringstream m;
      m << "slab interference: the thick sheet placed at driving angle " << drives[k] << " rad leaves cracks of "
        << placed.max_mismatch << " (> margin / 10 = " << 0.1 * margin << ")";
      throw NoAnswerError(m.str(), placed.max_mismatch);
    }
    std::vector<Eigen::Isometry3d> poses(nf);
    for (int f = 0; f < nf; ++f) poses[f] = placed.face_motions[sheet_face[f]];
    std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects(nf);
    std::vector<fcl::CollisionObjectd*> raw(nf);
    for (int f = 0; f < nf; ++f) {
      objects[f] = std::make_unique<fcl::CollisionObjectd>(local[f].mesh, fcl::Transform3d(poses[f].matrix()));
      objects[f]->computeAABB();
      objects[f]->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(f)));
      raw[f] = objects[f].get();
    }
    Scene scene;
    scene.slabs = &local;
    scene.poses = &poses;
    fcl::DynamicAABBTreeCollisionManagerd manager;
    manager.registerObjects(raw);
    manager.setup();
    manager.collide(&scene, on_overlap);
    std::sort(scene.pairs.begin(), scene.pairs.end());
    scene.pairs.erase(std::unique(scene.pairs.begin(), scene.pairs.end()), scene.pairs.end());
    SlabInterferenceState state;
    state.drive = drives[k];
    state.placement_mismatch = placed.max_mismatch;
    for (const auto& [a, b] : scene.pairs) {
      const auto it = shared.find({a, b});
      state.collisions.push_back({a, b, it == shared.end() ? -1 : it->second});
    }
    out.collision_count += static_cast<long long>(state.collisions.size());
    if (out.first_state < 0 && !state.collisions.empty()) out.first_state = static_cast<int>(k);
    out.states.push_back(std::move(state));
  }
  return out;
}

}  // namespace rigidfold
