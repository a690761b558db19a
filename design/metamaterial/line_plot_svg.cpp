#include "design/metamaterial/line_plot_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace rigidfold::metamaterial {
namespace {

constexpr double kWidth = 800, kHeight = 500;
constexpr double kLeft = 80, kRight = 160, kTop = 40, kBottom = 60;
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// About 5 round tick values covering [lo, hi] (at most 12; none when the range is below the
// values' resolution).
std::vector<double> ticks(double lo, double hi) {
  std::vector<double> t;
  const double raw = (hi - lo) / 5;
  if (!(raw > 0) || !std::isfinite(raw)) return t;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  const double first = std::ceil(lo / step);
  for (int i = 0; i < 12; ++i) {
    const double v = (first + i) * step;
    if (v > hi + 1e-9 * step) break;
    if (!t.empty() && v == t.back()) break;
    t.push_back(std::fabs(v) < 1e-12 * step ? 0.0 : v);
  }
  return t;
}

}  // namespace

std::string line_plot_svg(const LinePlot& plot) {
  double x0 = INFINITY, x1 = -INFINITY;
  std::vector<double> ys;
  for (const auto& s : plot.series) {
    if (s.x.size() != s.y.size()) throw std::invalid_argument("line plot: series '" + s.name + "': x and y differ in size");
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
        x0 = std::min(x0, s.x[i]);
        x1 = std::max(x1, s.x[i]);
        ys.push_back(s.y[i]);
      }
  }
  if (ys.empty()) throw std::invalid_argument("line plot: no finite point");
  std::sort(ys.begin(), ys.end());
  double y0 = ys.front(), y1 = ys.back();
  if (plot.clip_quantile > 0) {
    const auto at = [&](double q) { return ys[static_cast<std::size_t>(q * (ys.size() - 1))]; };
    const double lo = at(plot.clip_quantile), hi = at(1 - plot.clip_quantile), pad = 0.5 * (hi - lo);
    y0 = std::max(y0, lo - pad);
    y1 = std::min(y1, hi + pad);
  }
  if (y0 > 0 && plot.clip_quantile == 0) y0 = 0;  // dimensions: from 0
  if (y1 - y0 <= 0) {
    y0 -= 0.5;
    y1 += 0.5;
  }
  const double margin = 0.04 * (y1 - y0);  // curves off the frame
  y1 += margin;
  if (y0 < 0 || plot.clip_quantile > 0) y0 -= margin;
  if (x1 - x0 <= 0) x1 = x0 + 1;
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  auto sx = [&](double x) { return kLeft + (x - x0) / (x1 - x0) * pw; };
  auto sy = [&](double y) { return kTop + (y1 - y) / (y1 - y0) * ph; };

  std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"500\" viewBox=\"0 0 800 500\" "
       "font-family=\"sans-serif\" font-size=\"13\">\n";
  o += "<rect width=\"800\" height=\"500\" fill=\"white\"/>\n";
  o += "<text x=\"" + num(kLeft + pw / 2) + "\" y=\"24\" text-anchor=\"middle\" font-size=\"16\">" + escape(plot.title) +
       "</text>\n";
  // Ticks and grid.
  for (double t : ticks(x0, x1)) {
    o += "<line x1=\"" + num(sx(t)) + "\" y1=\"" + num(kTop) + "\" x2=\"" + num(sx(t)) + "\" y2=\"" + num(kTop + ph) +
         "\" stroke=\"#ddd\"/>\n";
    o += "<text x=\"" + num(sx(t)) + "\" y=\"" + num(kTop + ph + 18) + "\" text-anchor=\"middle\">" + num(t) + "</text>\n";
  }
  for (double t : ticks(y0, y1)) {
    o += "<line x1=\"" + num(kLeft) + "\" y1=\"" + num(sy(t)) + "\" x2=\"" + num(kLeft + pw) + "\" y2=\"" + num(sy(t)) +
         "\" stroke=\"" + (t == 0 ? "#888" : "#ddd") + "\"/>\n";
    o += "<text x=\"" + num(kLeft - 6) + "\" y=\"" + num(sy(t) + 4) + "\" text-anchor=\"end\">" + num(t) + "</text>\n";
  }
  o += "<rect x=\"" + num(kLeft) + "\" y=\"" + num(kTop) + "\" width=\"" + num(pw) + "\" height=\"" + num(ph) +
       "\" fill=\"none\" stroke=\"black\"/>\n";
  o += "<text x=\"" + num(kLeft + pw / 2) + "\" y=\"" + num(kHeight - 16) + "\" text-anchor=\"middle\">" +
       escape(plot.x_label) + "</text>\n";
  o += "<text transform=\"translate(22," + num(kTop + ph / 2) + ") rotate(-90)\" text-anchor=\"middle\">" +
       escape(plot.y_label) + "</text>\n";
  // Series: polylines broken at non-finite or clipped points.
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    const std::string colour = kColours[k % std::size(kColours)];
    std::string pts;
    auto flush = [&] {
      if (!pts.empty())
        o += "<polyline fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.8\" points=\"" + pts + "\"/>\n";
      pts.clear();
    };
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double x = s.x[i], y = s.y[i];
      if (!std::isfinite(x) || !std::isfinite(y) || y < y0 || y > y1) {
        flush();
        continue;
      }
      if (!pts.empty()) pts += " ";
      pts += num(sx(x));
      pts += ",";
      pts += num(sy(y));
    }
    flush();
    const double ly = kTop + 20 + 22 * k;
    o += "<line x1=\"" + num(kLeft + pw + 12) + "\" y1=\"" + num(ly) + "\" x2=\"" + num(kLeft + pw + 40) + "\" y2=\"" +
         num(ly) + "\" stroke=\"" + colour + "\" stroke-width=\"2\"/>\n";
    o += "<text x=\"" + num(kLeft + pw + 46) + "\" y=\"" + num(ly + 4) + "\">" + escape(s.name) + "</text>\n";
  }
  o += "</svg>\n";
  return o;
}

}  // namespace rigidfold::metamaterial
