#include "kernel/analysis/rounding_residual_bound.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "kernel/math/so3.hpp"
#include "kernel/pattern/vertex_boxes.hpp"

namespace rigidfold {

std::vector<std::vector<double>> sector_rounding_bounds(const CreasePattern& p, const Topology& t,
                                                        const CoordinatePrecision& precision) {
  std::vector<std::vector<double>> out;
  for (int v : t.interior_vertices) {
    const Fan& fan = t.stars[v].fans[0];
    const int n = static_cast<int>(fan.edges.size());
    // An edge's direction turns by at most asin(d / L) when its ends move by d <= L in all
    // (each end by at most sqrt(3) u: u per coordinate).
    auto reach = [&](int e) {
      const int other = p.edges[e][0] == v ? p.edges[e][1] : p.edges[e][0];
      const double len = (p.vertices[other] - p.vertices[v]).norm();
      const double moved =
          2.0 * std::sqrt(3.0) * std::max(precision.vertex_rounding[v], precision.vertex_rounding[other]);
      return len > 0 ? std::asin(std::min(1.0, moved / len)) : 1.0;
    };
    std::vector<double> bound(n);
    for (int i = 0; i < n; ++i) bound[i] = reach(fan.edges[i]) + reach(fan.edges[(i + 1) % n]);
    out.push_back(std::move(bound));
  }
  return out;
}

namespace {

// The precision the bound uses: the verdicts' (input_precision: stated, or read off the
// digits), except for an SVG's drawn points, whose vertices are computed (means of the drawn
// ends, crossings) and carry no digits of their own: there each vertex may lie anywhere in its
// box (vertex_boxes.hpp), i.e. up to its largest distance to the box's sides per coordinate.
CoordinatePrecision residual_precision(const CreasePattern& p, std::optional<double> stated_tolerance) {
  if (stated_tolerance || !p.position_bounds.covers(p.num_vertices())) return input_precision(p, stated_tolerance);
  const VertexBoxes boxes = vertex_boxes(p, stated_tolerance);
  CoordinatePrecision c;
  c.rounded = true;
  c.vertex_rounding.assign(p.num_vertices(), 0.0);
  for (int i = 0; i < p.num_vertices(); ++i) {
    for (int k = 0; k < 2; ++k) {
      const double x = p.vertices[i][k];
      c.vertex_rounding[i] = std::max({c.vertex_rounding[i], x - boxes.lo[i][k], boxes.hi[i][k] - x});
    }
    c.max_rounding = std::max(c.max_rounding, c.vertex_rounding[i]);
  }
  return c;
}

}  // namespace

RoundingResidualCheck rounding_explains_residual(const CreasePattern& p, const Topology& t, const Eigen::VectorXd& rho,
                                                 std::optional<double> stated_tolerance) {
  RoundingResidualCheck out;
  const CoordinatePrecision precision = residual_precision(p, stated_tolerance);
  const std::vector<std::vector<double>> bounds = sector_rounding_bounds(p, t, precision);
  for (std::size_t k = 0; k < t.interior_vertices.size(); ++k) {
    const int v = t.interior_vertices[k];
    const Fan& fan = t.stars[v].fans[0];
    const int n = static_cast<int>(fan.edges.size());
    Eigen::Matrix3d P = Eigen::Matrix3d::Identity();
    double lever = 0.0, total = 0.0;
    for (int i = 0; i < n; ++i) {
      P = P * rot_x(rho[fan.edges[i]]);
      lever += bounds[k][i] * (P.col(2) - Eigen::Vector3d::UnitZ()).norm();
      total += bounds[k][i];
      P = P * rot_z(fan.sectors[i]);
    }
    const Eigen::Vector3d r = so3_log(P);
    const double jl = Eigen::JacobiSVD<Eigen::Matrix3d>(so3_left_jacobian_inverse(r)).singularValues()[0];
    const double bound = jl * lever + total * total;
    const double ratio = bound > 0 ? r.norm() / bound : (r.norm() > 0 ? std::numeric_limits<double>::infinity() : 0.0);
    if (ratio > out.worst_ratio) {
      out.worst_ratio = ratio;
      out.worst_vertex = v;
    }
  }
  out.explained = out.worst_ratio <= 1.0;
  return out;
}

}  // namespace rigidfold
