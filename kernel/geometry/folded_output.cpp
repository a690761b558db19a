#include "kernel/geometry/folded_output.hpp"
#include "kernel/pattern/length_scale.hpp"

#include <cstdio>
#include <numbers>

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
    for (int v : f) s += " " + std::to_string(v + 1);
    s += "\n";
  }
  return s;
}

}  // namespace rigidfold
