#pragma once
// A small SVG line plot: several series y(x) on one pair of axes, with ticks, a zero line,
// axis labels and a legend. Enough for the metamaterial tables' figures (the C++ side has no
// matplotlib).
// Inputs: series of (x, y) points (any units; non-finite points break the line); the y range
// is the finite values' range, or, when `clip_quantile` > 0, the [q, 1 - q] quantiles of all
// series' finite y widened by half their span (for ratios with poles): points outside it
// break the line. Output: the SVG document text (800 x 500 user units).
// Throws std::invalid_argument when a series' x and y differ in size or no point is finite.
#include <string>
#include <vector>

namespace rigidfold::metamaterial {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;
};

struct LinePlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  double clip_quantile = 0.0;  // in [0, 0.5)
};

std::string line_plot_svg(const LinePlot& plot);

}  // namespace rigidfold::metamaterial
