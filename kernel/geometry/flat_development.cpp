#include "kernel/geometry/flat_development.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <set>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/planar_arrangement.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

FlatDevelopment flat_development(const CreasePattern& pattern, const std::string& source) {
  FlatDevelopment out;
  bool flat = true;
  for (const auto& v : pattern.vertices) flat = flat && v.z() == 0;
  if (pattern.coords_2d || flat) {
    out.pattern = pattern;
    out.pattern.coords_2d = true;
    return out;
  }
  const Topology t = build_topology(pattern, source);
  int holes = 0;
  for (const auto& c : t.components) holes += c.holes;
  if (holes > 0)
    throw InputError(source, "the sheet has " + std::to_string(holes) +
                                 (holes == 1 ? " hole" : " holes") +
                                 " (a tube or a sheet with holes): it has no development into the plane without a cut, so no flat crease pattern");
  if (t.components.size() != 1)
    throw InputError(source, "the sheet has " + std::to_string(t.components.size()) +
                                 " pieces: each unfolds in its own plane and nothing places them relative to each other");
  if (pattern.faces.empty()) throw InputError(source, "no faces to unfold");

  // Unfold: every fold angle 0, measured from the given state's own fold angles.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(pattern.num_edges());
  const FoldedGeometry g = place_faces(pattern, t, zero, reference_fold_angles(pattern, t));
  out.relative_mismatch = g.relative_mismatch();
  if (!(g.relative_mismatch() <= kDevelopmentTolerance))
    throw InputError(source, "the folded form is not developable: unfolded to flat, its faces disagree by " +
                                 short_text(g.relative_mismatch()) + " of the pattern size" +
                                 (g.worst_edge >= 0 ? " at edge " + std::to_string(g.worst_edge) : std::string()) + " (more than " +
                                 short_text(kDevelopmentTolerance) + "): some vertex's sectors do not sum to 360 deg");

  // The sheet's plane: the summed Newell normal of the unfolded faces (counter-clockwise
  // faces seen from their normals), the first edge of face 0 as +x.
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (const auto& f : pattern.faces)
    for (std::size_t k = 0; k < f.size(); ++k) n += g.vertices[f[k]].cross(g.vertices[f[(k + 1) % f.size()]]);
  const Eigen::Vector3d o = g.vertices[pattern.faces[0][0]];
  Eigen::Vector3d u = g.vertices[pattern.faces[0][1]] - o;
  if (!(n.norm() > 0) || !(u.norm() > 0)) throw InputError(source, "the unfolded sheet spans no area");
  n.normalize();
  u = (u - u.dot(n) * n).normalized();
  const Eigen::Vector3d w = n.cross(u);
  out.pattern = pattern;
  out.pattern.coords_2d = true;
  double off_plane = 0;
  for (int v = 0; v < pattern.num_vertices(); ++v) {
    const Eigen::Vector3d d = g.vertices[v] - o;
    off_plane = std::max(off_plane, std::fabs(d.dot(n)));
    out.pattern.vertices[v] = Eigen::Vector3d(d.dot(u) + 0.0, d.dot(w) + 0.0, 0.0);
  }
  if (!(off_plane <= kDevelopmentTolerance * g.pattern_size))
    throw InputError(source, "the unfolded sheet is not plane: a vertex lies " + short_text(off_plane / g.pattern_size) +
                                 " of the pattern size off its plane");
  out.unfolded = true;

  // The development must not overlap itself: its edges, as a planar arrangement, are the
  // pattern's edges again (no crossing, no vertex inside another edge, which would split it,
  // no two vertices together).
  std::vector<LabelledSegment> segments;
  std::set<int> used;
  for (int e = 0; e < pattern.num_edges(); ++e) {
    LabelledSegment s;
    s.a = out.pattern.vertices[pattern.edges[e][0]].head<2>();
    s.b = out.pattern.vertices[pattern.edges[e][1]].head<2>();
    s.source = e;
    segments.push_back(s);
    used.insert(pattern.edges[e][0]);
    used.insert(pattern.edges[e][1]);
  }
  ArrangementOptions ao;
  ao.tolerance = kDevelopmentTolerance * g.pattern_size;
  ao.remove_collinear_degree2 = false;
  const PlanarArrangement arr = build_planar_arrangement(segments, ao);
  if (arr.crossings > 0 || arr.merged_points > 0 || arr.vertices.size() != used.size() || arr.edges.size() != segments.size())
    throw InputError(source, "the unfolded sheet overlaps itself (" + std::to_string(arr.crossings) + " edge crossings, " +
                                 std::to_string(arr.edges.size()) + " edges where it has " + std::to_string(segments.size()) + ", " +
                                 std::to_string(arr.vertices.size()) + " vertices where it has " + std::to_string(used.size()) +
                                 "): it has no flat crease pattern");
  return out;
}

}  // namespace rigidfold
