#include "design/strings/miura_string.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/validate_pattern.hpp"
#include "kernel/solve/portable_random.hpp"

namespace rigidfold::design {

namespace {

std::string at(const char* field, int i) { return std::string(field) + "[" + std::to_string(i) + "]"; }

// x of the vertices V_i.
std::vector<double> vertex_x(const MiuraString& s) {
  std::vector<double> x(s.size());
  double acc = 0;
  for (int i = 0; i < s.size(); ++i) x[i] = (acc += s.lengths[i]);
  return x;
}

}  // namespace

void validate_string(const MiuraString& s, bool check_width) {
  const int n = s.size();
  if (n < 1) throw std::invalid_argument("alpha1: a string needs at least one vertex");
  if (static_cast<int>(s.alpha2.size()) != n) throw std::invalid_argument("alpha2: needs one value per vertex");
  if (static_cast<int>(s.lengths.size()) != n + 1) throw std::invalid_argument("lengths: needs N + 1 values");
  for (int i = 0; i < n; ++i) {
    if (!(s.alpha1[i] > 0 && s.alpha1[i] < std::numbers::pi / 2)) throw std::invalid_argument(at("alpha1", i) + ": must be in (0, pi/2)");
    if (!(s.alpha2[i] > 0 && s.alpha2[i] < std::numbers::pi / 2)) throw std::invalid_argument(at("alpha2", i) + ": must be in (0, pi/2)");
  }
  for (int k = 0; k <= n; ++k)
    if (!(s.lengths[k] > 0) || !std::isfinite(s.lengths[k])) throw std::invalid_argument(at("lengths", k) + ": must be finite and > 0");
  if (!check_width) return;
  if (!(s.width > 0) || !std::isfinite(s.width)) throw std::invalid_argument("width: must be finite and > 0");
  const double w = max_string_width(s);
  if (!(s.width < w))
    throw std::invalid_argument("width: peripheral creases would cross or leave the strip; the width must be below " +
                                std::to_string(w));
}

double max_string_width(const MiuraString& s) {
  // Peripheral crease ends at x_i + h cot(alpha): they must increase strictly along the
  // strip and stay within (0, x_end) (the crease starts at x_i > 0 and leans forward, so
  // only the right end and the neighbour to the right can be hit).
  const auto x = vertex_x(s);
  const double x_end = x.back() + s.lengths.back();
  double h_max = std::numeric_limits<double>::infinity();
  for (const auto* alpha : {&s.alpha1, &s.alpha2}) {
    for (int i = 0; i < s.size(); ++i) {
      const double ci = 1 / std::tan((*alpha)[i]);
      const double next_x = i + 1 < s.size() ? x[i + 1] : x_end;
      const double next_c = i + 1 < s.size() ? 1 / std::tan((*alpha)[i + 1]) : 0.0;
      // x_i + h c_i < next_x + h next_c  <=>  h (c_i - next_c) < next_x - x_i
      if (ci > next_c) h_max = std::min(h_max, (next_x - x[i]) / (ci - next_c));
    }
  }
  return 2 * h_max;
}

CreasePattern build_string_pattern(const MiuraString& s, const Eigen::VectorXd& edge_fold_angles) {
  validate_string(s);
  const int n = s.size();
  const StringPatternIndex ix{n};
  const auto x = vertex_x(s);
  const double x_end = x.back() + s.lengths.back();
  const double h = s.width / 2;
  CreasePattern p;
  p.coords_2d = true;
  p.vertices.emplace_back(0, 0, 0);
  for (int i = 0; i < n; ++i) p.vertices.emplace_back(x[i], 0, 0);
  p.vertices.emplace_back(x_end, 0, 0);
  for (int i = 0; i < n; ++i) p.vertices.emplace_back(x[i] + h / std::tan(s.alpha1[i]), h, 0);
  for (int i = 0; i < n; ++i) p.vertices.emplace_back(x[i] + h / std::tan(s.alpha2[i]), -h, 0);
  const int T0 = n + 2, B0 = 2 * n + 2, TL = 3 * n + 2, TR = TL + 1, BL = TL + 2, BR = TL + 3;
  p.vertices.emplace_back(0, h, 0);
  p.vertices.emplace_back(x_end, h, 0);
  p.vertices.emplace_back(0, -h, 0);
  p.vertices.emplace_back(x_end, -h, 0);
  const int num_creases = 3 * n + 1;
  const bool with_angles = edge_fold_angles.size() > 0;
  auto crease = [&](int a, int b) {
    const int e = p.num_edges();
    p.edges.push_back({a, b});
    const double rho = with_angles ? edge_fold_angles[e] : 0.0;
    p.assignments.push_back(rho < 0 ? Assignment::Mountain : Assignment::Valley);
    p.fold_angles.push_back(with_angles ? std::optional<double>(rho) : std::nullopt);
  };
  auto boundary = [&](int a, int b) {
    p.edges.push_back({a, b});
    p.assignments.push_back(Assignment::Boundary);
    p.fold_angles.push_back(std::nullopt);
  };
  for (int k = 0; k <= n; ++k) crease(ix.spine_vertex(k), ix.spine_vertex(k + 1));
  for (int i = 0; i < n; ++i) crease(ix.vertex_of(i), T0 + i);
  for (int i = 0; i < n; ++i) crease(ix.vertex_of(i), B0 + i);
  (void)num_creases;
  // Boundary: left end, top chain, right end, bottom chain.
  boundary(BL, 0);
  boundary(0, TL);
  boundary(TL, T0);
  for (int i = 0; i + 1 < n; ++i) boundary(T0 + i, T0 + i + 1);
  boundary(T0 + n - 1, TR);
  boundary(TR, n + 1);
  boundary(n + 1, BR);
  boundary(BR, B0 + n - 1);
  for (int i = n - 1; i > 0; --i) boundary(B0 + i, B0 + i - 1);
  boundary(B0, BL);
  // Faces, counter-clockwise.
  for (int k = 0; k <= n; ++k) {
    const int top_left = k == 0 ? TL : T0 + k - 1, top_right = k == n ? TR : T0 + k;
    p.faces.push_back({ix.spine_vertex(k), ix.spine_vertex(k + 1), top_right, top_left});
  }
  for (int k = 0; k <= n; ++k) {
    const int bot_left = k == 0 ? BL : B0 + k - 1, bot_right = k == n ? BR : B0 + k;
    p.faces.push_back({bot_left, bot_right, ix.spine_vertex(k + 1), ix.spine_vertex(k)});
  }
  p.fold_angles_in_file = with_angles;
  p.extra["file_spec"] = 1.1;
  p.extra["file_creator"] = "rigidfold string";
  p.extra["file_classes"] = nlohmann::ordered_json::array({"singleModel"});
  p.extra["frame_title"] = "origami string of " + std::to_string(n) + " Miura vertices";
  p.extra["frame_classes"] = nlohmann::ordered_json::array({"creasePattern"});
  p.extra["frame_attributes"] = nlohmann::ordered_json::array({"2D"});
  try {
    complete_and_validate(p, "string pattern");
  } catch (const InputError& e) {
    // The closed form holds for alpha down to 1e-300 deg, but a drawn crease at such an
    // angle lies on the spine within the pattern's resolution (1e-10 of its size).
    throw InputError(e.place(), e.message() +
                                    " (the spec's crease pattern cannot be drawn: an alpha this close to 0 or 90 deg puts a "
                                    "peripheral crease on another crease at these segment lengths and width)");
  }
  return p;
}

std::string string_pattern_svg(const CreasePattern& pattern, double scale) {
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& v : pattern.vertices) {
    lo = lo.cwiseMin(v.head<2>());
    hi = hi.cwiseMax(v.head<2>());
  }
  const double margin = 0.05 * (hi - lo).maxCoeff();
  const double w = (hi.x() - lo.x() + 2 * margin) * scale, h = (hi.y() - lo.y() + 2 * margin) * scale;
  std::ostringstream out;
  out.precision(10);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\" viewBox=\"0 0 " << w << " "
      << h << "\">\n";
  out << "<!-- rigidfold origami string: black = cut (boundary), red dashed = mountain, blue = valley -->\n";
  auto px = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector2d((v.x() - lo.x() + margin) * scale, (hi.y() - v.y() + margin) * scale);  // y up
  };
  for (int e = 0; e < pattern.num_edges(); ++e) {
    const auto a = px(pattern.vertices[pattern.edges[e][0]]), b = px(pattern.vertices[pattern.edges[e][1]]);
    const Assignment as = pattern.assignments[e];
    const char* style = as == Assignment::Boundary ? "stroke=\"#000000\""
                        : as == Assignment::Mountain ? "stroke=\"#d00000\" stroke-dasharray=\"6,3\""
                        : as == Assignment::Valley   ? "stroke=\"#0050d0\""
                                                     : "stroke=\"#808080\"";
    out << "<line x1=\"" << a.x() << "\" y1=\"" << a.y() << "\" x2=\"" << b.x() << "\" y2=\"" << b.y() << "\" " << style
        << " stroke-width=\"1\" class=\"" << assignment_letter(as) << "\"/>\n";
  }
  out << "</svg>\n";
  return out.str();
}

MiuraString random_miura_string(int n, std::uint64_t seed, double alpha_min, double alpha_max, double width_fraction) {
  SplitMix64 stream{seed};
  MiuraString s;
  for (int i = 0; i < n; ++i) {
    s.alpha1.push_back(alpha_min + (alpha_max - alpha_min) * stream.uniform());
    s.alpha2.push_back(alpha_min + (alpha_max - alpha_min) * stream.uniform());
  }
  for (int k = 0; k <= n; ++k) s.lengths.push_back(0.8 + 0.4 * stream.uniform());
  s.width = width_fraction * max_string_width(s);
  return s;
}

}  // namespace rigidfold::design
