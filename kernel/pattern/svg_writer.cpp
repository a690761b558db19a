#include "kernel/pattern/svg_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "kernel/geometry/flat_development.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/length_scale.hpp"

namespace rigidfold {
namespace {

// Shortest decimal that reads back to the same double; -0 written as 0.
std::string number(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x + 0.0);
  return std::string(buf, r.ptr);
}

// The opacity op with op * pi == |rho| in double arithmetic (the reader's product), found
// among the few doubles next to |rho| / pi; the nearest of them when none is exact.
double opacity_for(double rho) {
  const double target = std::fabs(rho);
  const double guess = std::min(1.0, target / std::numbers::pi);
  double best = guess;
  double best_error = std::fabs(guess * std::numbers::pi - target);
  double down = guess, up = guess;
  for (int k = 0; k < 4 && best_error > 0; ++k) {
    down = std::nextafter(down, 0.0);
    up = std::min(1.0, std::nextafter(up, 2.0));
    for (double c : {down, up}) {
      const double err = std::fabs(c * std::numbers::pi - target);
      if (err < best_error) best = c, best_error = err;
    }
  }
  return best;
}

}  // namespace

std::string svg_stroke_colour(Assignment a) {
  switch (a) {
    case Assignment::Boundary: return "#000000";
    case Assignment::Mountain: return "#ff0000";
    case Assignment::Valley: return "#0000ff";
    case Assignment::Flat: return "#ffff00";
    case Assignment::Unassigned: return "#ff00ff";
    case Assignment::Cut: return "#00ff00";
    case Assignment::Join: return "";
  }
  return "";
}

std::string write_svg_string(const CreasePattern& input, const std::string& source) {
  if (input.edges.empty()) throw InputError(source, "no edges to draw");
  for (int e = 0; e < input.num_edges(); ++e) {
    const std::string place = source + ": edges_assignment[" + std::to_string(e) + "]";
    if (input.assignments[e] == Assignment::Join)
      throw InputError(place, "J (join) has no colour in Origami Simulator's SVG convention");
    const auto& rho = input.fold_angles[e];
    if (rho && ((input.assignments[e] == Assignment::Mountain && *rho > 0) || (input.assignments[e] == Assignment::Valley && *rho < 0)))
      throw InputError(source + ": edges_foldAngle[" + std::to_string(e) + "]",
                       std::string(input.assignments[e] == Assignment::Mountain ? "a mountain with a positive" : "a valley with a negative") +
                           " fold angle: an SVG opacity cannot say it");
  }
  const FlatDevelopment dev = flat_development(input, source);
  const CreasePattern& p = dev.pattern;

  // File units, y flipped (0 - y: no -0).
  std::vector<Eigen::Vector2d> xy;
  xy.reserve(p.vertices.size());
  for (const auto& v : p.vertices) {
    const Eigen::Vector3d f = to_file_units(p, v);
    xy.emplace_back(f.x(), 0.0 - f.y());
  }
  Eigen::Vector2d lo = xy[p.edges[0][0]], hi = lo;
  for (const auto& e : p.edges)
    for (int v : e) lo = lo.cwiseMin(xy[v]), hi = hi.cwiseMax(xy[v]);
  // hypot: the diagonal of a pattern of side 1e300 stays finite (the squared norm would not).
  const double size = std::hypot(hi.x() - lo.x(), hi.y() - lo.y());
  const double margin = 0.02 * size;
  // Every number written must be finite and the drawing must keep its size: a viewBox or
  // stroke width of inf, or a pattern below the range of doubles' full precision, is refused.
  if (!std::isfinite(lo.x() - margin) || !std::isfinite(lo.y() - margin) || !std::isfinite(hi.x() - lo.x() + 2 * margin) ||
      !std::isfinite(hi.y() - lo.y() + 2 * margin))
  {
    char text[128];
    std::snprintf(text, sizeof text, "SVG: the pattern's size (%.3g in the file's units) does not fit an SVG's numbers", size);
    throw InputError(source, text);
  }
  if (!(size / 400 >= std::numeric_limits<double>::min()))
    throw InputError(source, "SVG: the pattern's size in the file's units is too small for an SVG stroke width");

  std::string s;
  s.reserve(200 + 120 * p.edges.size());
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<!-- crease pattern written by rigidfold (Origami Simulator colours: black B, red M, blue V, yellow F, magenta U, "
       "green C; stroke-opacity x 180 deg = |fold angle| of M and V; y = -FOLD y) -->\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" viewBox=\"" + number(lo.x() - margin) + " " + number(lo.y() - margin) +
       " " + number(hi.x() - lo.x() + 2 * margin) + " " + number(hi.y() - lo.y() + 2 * margin) + "\">\n";
  s += "<g fill=\"none\" stroke-linecap=\"round\" stroke-width=\"" + number(size / 400) + "\">\n";
  for (int e = 0; e < p.num_edges(); ++e) {
    const Assignment a = p.assignments[e];
    const Eigen::Vector2d &u = xy[p.edges[e][0]], &v = xy[p.edges[e][1]];
    s += "<line x1=\"" + number(u.x()) + "\" y1=\"" + number(u.y()) + "\" x2=\"" + number(v.x()) + "\" y2=\"" + number(v.y()) +
         "\" stroke=\"" + svg_stroke_colour(a) + "\"";
    if (has_fold_sign(a)) {
      const auto& rho = p.fold_angles[e];
      s += " stroke-opacity=\"" + number(rho ? opacity_for(*rho) : 0.0) + "\"";
    }
    s += "/>\n";
  }
  s += "</g>\n</svg>\n";
  return s;
}

}  // namespace rigidfold
