#include "kernel/pattern/coordinate_precision.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace rigidfold {
namespace {

// Fewest decimals d (0..17) whose decimal rounding of c reads back as c within two units in
// its last place: a coordinate that went through arithmetic after it was written (an SVG's
// translate, y -> 0 - y) is 621.6779999999999 for the 621.678 of the file.
int decimal_places(double c) {
  if (c == 0.0 || !std::isfinite(c)) return 0;
  char buf[64];
  const double slack = 2 * (std::nextafter(std::abs(c), std::numeric_limits<double>::infinity()) - std::abs(c));
  for (int d = 0; d <= 17; ++d) {
    std::snprintf(buf, sizeof buf, "%.*f", d, c);
    if (std::abs(std::strtod(buf, nullptr) - c) <= slack) return d;
  }
  return -1;  // not a number of at most 17 decimals (e.g. 3.7e-19): not decimal-rounded
}

int magnitude(double c) { return c == 0.0 ? 0 : static_cast<int>(std::floor(std::log10(std::abs(c)))); }

}  // namespace

CoordinatePrecision coordinate_precision(const CreasePattern& p) {
  CoordinatePrecision out;
  // Stored coordinates may be normalised by a power of two (exact); the written numbers
  // are the stored ones times 2^length_exponent, which is what the digits are counted on.
  const double unit = std::ldexp(1.0, p.length_exponent);
  int max_significant = 0, max_decimals = 0;
  bool beyond_decimals = false;
  for (const Eigen::Vector3d& v : p.vertices)
    for (int k = 0; k < 3; ++k) {
      const double c = v[k] * unit;
      if (c == 0.0) continue;
      const int d = decimal_places(c);
      if (d < 0) {
        beyond_decimals = true;
        continue;
      }
      max_decimals = std::max(max_decimals, d);
      max_significant = std::max(max_significant, d + magnitude(c) + 1);
    }
  out.decimal_places = max_decimals;
  out.significant_digits = max_significant;
  out.rounded = !beyond_decimals && max_significant <= 15;
  out.vertex_rounding.assign(p.vertices.size(), 0.0);
  if (!out.rounded) {
    bool all_float = !p.vertices.empty();
    double scale = 0.0;
    for (const Eigen::Vector3d& v : p.vertices)
      for (int k = 0; k < 3; ++k) {
        const double c = v[k] * unit;
        all_float = all_float && std::isfinite(c) && static_cast<double>(static_cast<float>(c)) == c;
        scale = std::max(scale, std::abs(c));
      }
    if (all_float && scale > 0) {
      out.single_precision = out.rounded = true;
      out.significant_digits = 8;  // a float32 carries 24 bits: 7.2 decimal digits
      for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        double m = 0.0;
        for (int k = 0; k < 3; ++k) m = std::max(m, std::abs(p.vertices[i][k] * unit));
        out.vertex_rounding[i] = (std::ldexp(scale, -24) + std::ldexp(m, -51)) / unit;
        out.max_rounding = std::max(out.max_rounding, out.vertex_rounding[i]);
      }
      return out;
    }
  }
  for (std::size_t i = 0; i < p.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double c = p.vertices[i][k] * unit;
      double u = std::max(0.5 * std::pow(10.0, -max_decimals),
                          0.5 * std::pow(10.0, magnitude(c) - max_significant + 1));
      if (c == 0.0) u = 0.5 * std::pow(10.0, -max_decimals);
      // Plus the two units in the last place decimal_places allows (2^-51 |c|).
      u = (std::max(u, std::ldexp(std::abs(c), -52)) + std::ldexp(std::abs(c), -51)) / unit;  // back to stored units
      out.vertex_rounding[i] = std::max(out.vertex_rounding[i], u);
      out.max_rounding = std::max(out.max_rounding, u);
    }
  return out;
}

CoordinatePrecision stated_precision(const CreasePattern& p, double tolerance) {
  CoordinatePrecision out;
  out.stated = true;
  out.rounded = tolerance > 0;
  const double stored = tolerance / std::ldexp(1.0, p.length_exponent);
  out.vertex_rounding.assign(p.vertices.size(), stored);
  out.max_rounding = p.vertices.empty() ? 0.0 : stored;
  return out;
}

CoordinatePrecision input_precision(const CreasePattern& p, std::optional<double> stated_tolerance) {
  return stated_tolerance ? stated_precision(p, *stated_tolerance) : coordinate_precision(p);
}

std::string describe_input_precision(const CreasePattern& p, std::optional<double> stated_tolerance) {
  char bound[32];
  if (stated_tolerance) {
    if (*stated_tolerance == 0) return "coordinates taken as exact (--tolerance exact)";
    std::snprintf(bound, sizeof bound, "%.3g", *stated_tolerance);
    return std::string("coordinates within ") + bound + " of the true ones (stated with --tolerance)";
  }
  if (p.position_bounds.covers(p.num_vertices())) {
    std::snprintf(bound, sizeof bound, "%.3g", p.position_bounds.max_half_width * std::ldexp(1.0, p.length_exponent));
    return std::string("vertices within the box of the points drawn for them (half-width <= ") + bound + ")";
  }
  const CoordinatePrecision read = coordinate_precision(p);
  if (!read.rounded) return "full-precision coordinates, taken as exact";
  return describe_precision(read);
}

std::string describe_precision(const CoordinatePrecision& precision) {
  char bound[32];
  std::snprintf(bound, sizeof bound, "%.3g", precision.max_rounding);
  if (precision.stated)
    return precision.rounded ? std::string("coordinates within ") + bound + " (stated with --tolerance)"
                             : std::string("coordinates taken as exact (--tolerance exact)");
  if (precision.single_precision) return std::string("float32 coordinates (rounding <= ") + bound + ")";
  return "coordinates written with " + std::to_string(precision.decimal_places) + " decimals (rounding <= " + bound + ")";
}

}  // namespace rigidfold
