#include "design/sorce/sorce_svg.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {

namespace {

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", x);
  return buf;
}

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -std::numeric_limits<double>::infinity();
  double y0 = std::numeric_limits<double>::infinity(), y1 = -std::numeric_limits<double>::infinity();
  void add(const Vec2& p) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
};

struct Sampled {
  std::vector<Vec2> left, right;
  Box box;
};

Sampled sample(const FoldMotion& m, int samples) {
  SampledProfiles p = sample_profiles(m, samples);
  Sampled s;
  s.left = std::move(p.left);
  s.right = std::move(p.right);
  for (const Vec2& q : s.left) s.box.add(q);
  for (const Vec2& q : s.right) s.box.add(q);
  for (double h : {m.thickness_left, m.thickness_right}) {
    s.box.add(Vec2(s.box.x0, h / 2));
    s.box.add(Vec2(s.box.x0, -h / 2));
  }
  return s;
}

std::string polyline(const std::vector<Vec2>& pts, const char* cls, const SvgOptions& o) {
  std::string out = std::string("<polyline class=\"") + cls + "\" fill=\"none\" stroke-width=\"" + num(o.stroke) + "\" points=\"";
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (k) out += ' ';
    out += num(pts[k].x());
    out += ',';
    out += num(pts[k].y());
  }
  return out + "\"/>\n";
}

std::string slab(double x_from, double x_to, double h, const char* cls, const SvgOptions& o) {
  if (!(h > 0.0)) return "";
  std::string out;
  for (double y : {h / 2, -h / 2})
    out += std::string("<line class=\"") + cls + "\" stroke-dasharray=\"" + num(4 * o.stroke) + "\" stroke-width=\"" + num(o.stroke / 2) +
           "\" x1=\"" + num(x_from) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x_to) + "\" y2=\"" + num(y) + "\"/>\n";
  return out;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string group(const FoldMotion& m, const Sampled& s, const SvgOptions& o, double dx, double dy) {
  std::string out = "<g class=\"fold\" transform=\"translate(" + num(dx) + "," + num(dy) + ") scale(1,-1)\">\n";
  out += slab(std::min(s.box.x0, 0.0), 0.0, m.thickness_left, "left-slab", o);
  out += slab(0.0, std::max(s.box.x1, 0.0), m.thickness_right, "right-slab", o);
  out += polyline(s.left, "left", o);
  out += polyline(s.right, "right", o);
  return out + "</g>\n";
}

}  // namespace

std::string fold_profiles_svg_group(const FoldMotion& motion, const SvgOptions& options, double dx, double dy) {
  return group(motion, sample(motion, options.samples), options, dx, dy);
}

std::string folds_profiles_svg(const std::vector<NamedFold>& folds, const SvgOptions& o) {
  if (folds.empty()) throw InputError("folds", "no fold to draw");
  std::vector<Sampled> s;
  for (const NamedFold& f : folds) s.push_back(sample(f.motion, o.samples));
  double gap = 0.0, y_top = -std::numeric_limits<double>::infinity(), y_bottom = std::numeric_limits<double>::infinity();
  for (const Sampled& f : s) {
    gap = std::max(gap, 0.2 * (f.box.x1 - f.box.x0));
    y_top = std::max(y_top, f.box.y1);
    y_bottom = std::min(y_bottom, f.box.y0);
  }
  const double height = y_top - y_bottom, label = 0.1 * height + 4 * o.stroke;
  // Folds side by side: each fold's origin placed so its box starts where the previous ended.
  std::string body;
  double x = 0.0;
  for (std::size_t j = 0; j < folds.size(); ++j) {
    const double dx = x - s[j].box.x0, dy = y_top + label;  // y flips: model y_top sits at the label's foot
    body += "<text x=\"" + num(x) + "\" y=\"" + num(0.8 * label) + "\" font-size=\"" + num(0.6 * label) + "\">" +
            xml_escape(folds[j].name) + "</text>\n";
    body += group(folds[j].motion, s[j], o, dx, dy);
    x += s[j].box.x1 - s[j].box.x0 + gap;
  }
  const double width = std::max(x - gap, o.stroke), total_height = height + label + 2 * o.stroke;
  const double ppu = o.width_px > 0 ? o.width_px / width : o.pixels_per_unit;
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + num(width) + " " + num(total_height) + "\" width=\"" +
                    num(width * ppu) + "\" height=\"" + num(total_height * ppu) + "\">\n";
  out += "<style>.left{stroke:#1f5fbf}.right{stroke:#c0392b}.left-slab{stroke:#7fa7df}.right-slab{stroke:#df8f86}</style>\n";
  return out + body + "</svg>\n";
}

std::string vertex_profiles_svg(const SorceVertex& v, const SvgOptions& o) {
  std::vector<NamedFold> folds;
  for (int j = 0; j < 4; ++j) folds.push_back({"fold " + std::to_string(j + 1), v.folds[j]});
  return folds_profiles_svg(folds, o);
}

}  // namespace rigidfold::sorce
