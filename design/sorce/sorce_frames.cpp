#include "design/sorce/sorce_frames.hpp"

#include <map>
#include <utility>

#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"

namespace rigidfold::sorce {
namespace {

void check_sizes(const CreasePattern& pattern, const PoseFrames& frames) {
  if (frames.poses.size() != frames.times.size() || frames.fold_angles.size() != frames.times.size())
    throw InputError("poses", "one pose set and one set of fold angles per time");
  for (std::size_t i = 0; i < frames.times.size(); ++i)
    if (static_cast<int>(frames.poses[i].size()) != pattern.num_faces() || frames.fold_angles[i].size() != pattern.num_edges())
      throw InputError("poses[" + std::to_string(i) + "]", "needs one pose per face and one fold angle per edge");
}

}  // namespace

CreasePattern exploded_frames(const CreasePattern& pattern, const PoseFrames& frames) {
  check_sizes(pattern, frames);
  std::map<std::pair<int, int>, int> edge_of;
  for (int e = 0; e < pattern.num_edges(); ++e) {
    edge_of[{pattern.edges[e][0], pattern.edges[e][1]}] = e;
    edge_of[{pattern.edges[e][1], pattern.edges[e][0]}] = e;
  }
  CreasePattern out;
  out.length_exponent = pattern.length_exponent;
  out.coords_2d = false;
  std::vector<int> source_edge, corner_face;
  for (int f = 0; f < pattern.num_faces(); ++f) {
    const std::vector<int>& face = pattern.faces[f];
    const int first = out.num_vertices();
    std::vector<int> cycle;
    for (std::size_t k = 0; k < face.size(); ++k) {
      out.vertices.push_back(pattern.vertices[face[k]]);
      corner_face.push_back(f);
      cycle.push_back(first + static_cast<int>(k));
    }
    for (std::size_t k = 0; k < face.size(); ++k) {
      const auto it = edge_of.find({face[k], face[(k + 1) % face.size()]});
      const int e = it == edge_of.end() ? -1 : it->second;
      out.edges.push_back({cycle[k], cycle[(k + 1) % face.size()]});
      out.assignments.push_back(e < 0 ? Assignment::Boundary : pattern.assignments[e]);
      out.fold_angles.push_back(std::nullopt);
      source_edge.push_back(e);
    }
    out.faces.push_back(cycle);
  }
  for (std::size_t i = 0; i < frames.times.size(); ++i) {
    FoldedGeometry placed;
    placed.face_motions = frames.poses[i];
    for (int v = 0; v < out.num_vertices(); ++v) placed.vertices.push_back(frames.poses[i][corner_face[v]] * out.vertices[v]);
    Eigen::VectorXd angles(out.num_edges());
    for (int e = 0; e < out.num_edges(); ++e) angles[e] = source_edge[e] < 0 ? 0.0 : frames.fold_angles[i][source_edge[e]];
    std::string title = "SORCE panels at t = ";
    title += short_text(frames.times[i]);
    out = with_folded_frame(out, placed, angles, title);
    nlohmann::ordered_json& frame = out.extra["file_frames"].back();
    frame.erase("rigidfold:closure_mismatch");  // each panel is placed on its own: no hinge to mismatch
    frame["rigidfold:sorce_t"] = frames.times[i];
  }
  return out;
}

std::string pose_table_csv(const CreasePattern& pattern, const PoseFrames& frames) {
  check_sizes(pattern, frames);
  std::string s = "t,face,r00,r01,r02,r10,r11,r12,r20,r21,r22,tx,ty,tz\n";
  for (std::size_t i = 0; i < frames.times.size(); ++i)
    for (int f = 0; f < pattern.num_faces(); ++f) {
      const Eigen::Isometry3d& p = frames.poses[i][f];
      auto field = [&s](const std::string& x) {
        s += ',';
        s += x;
      };
      s += round_trip_text(frames.times[i]);
      field(std::to_string(f));
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) field(round_trip_text(p.linear()(r, c)));
      const Eigen::Vector3d tr = to_file_units(pattern, p.translation());
      for (int k = 0; k < 3; ++k) field(round_trip_text(tr[k]));
      s += '\n';
    }
  return s;
}

}  // namespace rigidfold::sorce
