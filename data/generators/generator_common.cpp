#include "data/generators/generator_common.hpp"

#include <cctype>
#include <cmath>

#include "kernel/geometry/fold_angles.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/pattern/validate_pattern.hpp"

namespace rigidfold::generators {

void require(bool ok, const std::string& param, const std::string& what) {
  if (!ok) throw InputError(param, what);
}

std::vector<Assignment> parse_assignment_letters(const std::string& letters, const std::string& param) {
  std::vector<Assignment> out;
  for (std::size_t i = 0; i < letters.size(); ++i) {
    const char c = letters[i];
    if (c == ' ' || c == ',' || c == '_') continue;
    const auto a = assignment_from_letter(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    if (!a)
      throw InputError(param, std::string("'") + c + "' at position " + std::to_string(i) +
                                  " is not a FOLD assignment letter (M, V, F, U, B, C, J)");
    out.push_back(*a);
  }
  return out;
}

std::string assignment_letters(const std::vector<Assignment>& assignment) {
  std::string s;
  for (auto a : assignment) s.push_back(assignment_letter(a));
  return s;
}

namespace {

// FOLD metadata of a generated pattern, then validation.
void stamp_and_validate(CreasePattern& p, const std::string& title, const std::string& frame_title, bool folded_3d,
                        const nlohmann::ordered_json& generator_parameters) {
  p.coords_2d = !folded_3d;
  p.extra["file_spec"] = 1.1;
  p.extra["file_creator"] = "rigidfold generate";
  p.extra["file_title"] = title;
  p.extra["file_classes"] = nlohmann::ordered_json::array({"singleModel"});
  p.extra["frame_title"] = frame_title;
  p.extra["frame_classes"] = nlohmann::ordered_json::array({folded_3d ? "foldedForm" : "creasePattern"});
  p.extra["frame_attributes"] = nlohmann::ordered_json::array({folded_3d ? "3D" : "2D"});
  p.extra["rigidfold:generator"] = generator_parameters;
  complete_and_validate(p, title);
}

}  // namespace

CreasePattern finish_pattern(CreasePattern p, const std::string& title, const std::string& frame_title,
                             const nlohmann::ordered_json& generator_parameters) {
  stamp_and_validate(p, title, frame_title, false, generator_parameters);
  return p;
}

CreasePattern finish_folded_pattern(CreasePattern p, const std::string& title, const std::string& frame_title,
                                    const nlohmann::ordered_json& generator_parameters) {
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  stamp_and_validate(p, title, frame_title, true, generator_parameters);
  const Eigen::VectorXd rho = reference_fold_angles(p, build_topology(p, title));
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.assignments[e] == Assignment::Boundary) continue;
    p.assignments[e] = rho[e] >= 0 ? Assignment::Valley : Assignment::Mountain;
    p.fold_angles[e] = rho[e];
  }
  return p;
}

double deg_rounded(double radians) { return std::round(to_degrees(radians) * 1e9) / 1e9; }

}  // namespace rigidfold::generators
