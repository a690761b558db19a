#include "data/generators/square_twist_tessellation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "data/generators/generator_common.hpp"
#include "data/generators/parallelogram_lattice.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold::generators {
namespace {

using A = Assignment;

A opposite(A a) { return a == A::Mountain ? A::Valley : A::Mountain; }

std::string twist_name(int i, int j, int k) {
  return "twist (" + std::to_string(i) + ", " + std::to_string(j) + ") vertex " + "ABCD"[k];
}

void check_params(const SquareTwistTessellationParams& p) {
  const double t = p.twist;
  require(p.rows >= 1 && p.rows <= 500, "rows", "must be between 1 and 500, got " + std::to_string(p.rows));
  require(p.cols >= 1 && p.cols <= 500, "cols", "must be between 1 and 500, got " + std::to_string(p.cols));
  require(std::isfinite(t) && t > 0 && t < kPi / 2, "twist",
          "the twist angle must lie strictly between 0 and 90 deg, got " + std::to_string(to_degrees(t)) + " deg");
  require(std::isfinite(p.side) && p.side > 0, "side", "the central square's side must be positive");
  const double reach = square_twist_tessellation_min_spacing(p.twist, p.side);
  require(std::isfinite(p.spacing) && p.spacing > reach * (1 + 1e-9), "spacing",
          "twist centres must be more than side * (sin t + cos t) = " + std::to_string(reach) +
              " apart, so that every crease between twists has positive length; got " + std::to_string(p.spacing));
  require(std::isfinite(p.spacing_y) && (p.spacing_y == 0 || p.spacing_y > reach * (1 + 1e-9)), "spacing_y",
          "twist centres along y must be more than side * (sin t + cos t) = " + std::to_string(reach) +
              " apart (or 0: the same as spacing); got " + std::to_string(p.spacing_y));
}

}  // namespace

double square_twist_tessellation_min_spacing(double twist, double side) {
  return side * (std::sin(twist) + std::cos(twist));
}

const char* to_string(SquareTwistTessellationLayout layout) {
  switch (layout) {
    case SquareTwistTessellationLayout::Type4: return "type4";
    case SquareTwistTessellationLayout::Type3Rows: return "type3-rows";
    case SquareTwistTessellationLayout::AllType1: return "type1";
    case SquareTwistTessellationLayout::AllType2: return "type2";
  }
  return "?";
}

SquareTwistTessellationLayout square_twist_tessellation_layout_from_string(const std::string& name) {
  for (auto layout : {SquareTwistTessellationLayout::Type4, SquareTwistTessellationLayout::Type3Rows,
                      SquareTwistTessellationLayout::AllType1, SquareTwistTessellationLayout::AllType2})
    if (name == to_string(layout)) return layout;
  throw InputError("layout", "unknown layout '" + name + "' (expected type4, type3-rows, type1 or type2)");
}

int square_twist_tessellation_dof(SquareTwistTessellationLayout layout) {
  return layout == SquareTwistTessellationLayout::Type4 || layout == SquareTwistTessellationLayout::Type3Rows ? 1 : 0;
}

std::array<Assignment, 4> square_twist_tessellation_twist_sides(SquareTwistTessellationLayout layout, int j) {
  const A M = A::Mountain, V = A::Valley;
  switch (layout) {
    case SquareTwistTessellationLayout::Type4: return {V, M, M, M};
    case SquareTwistTessellationLayout::Type3Rows:
      return j % 2 == 0 ? std::array<A, 4>{V, M, M, V} : std::array<A, 4>{M, V, V, M};
    case SquareTwistTessellationLayout::AllType1: return {M, M, M, M};
    case SquareTwistTessellationLayout::AllType2: return {V, M, V, M};
  }
  return {M, M, M, M};
}

std::vector<std::array<Assignment, 4>> square_twist_tessellation_sides(const SquareTwistTessellationParams& params) {
  check_params(params);
  std::vector<std::array<Assignment, 4>> out;
  for (int j = 0; j < params.rows; ++j)
    for (int i = 0; i < params.cols; ++i) out.push_back(square_twist_tessellation_twist_sides(params.layout, j));
  return out;
}

CreasePattern square_twist_tessellation(const SquareTwistTessellationParams& params,
                                        const std::vector<std::array<Assignment, 4>>& sides) {
  check_params(params);
  const int m = params.cols, n = params.rows;
  require(static_cast<long>(sides.size()) == static_cast<long>(m) * n, "sides",
          "needs one entry (4 side letters) per twist, rows * cols = " + std::to_string(m * n) + ", got " +
              std::to_string(sides.size()));
  for (std::size_t w = 0; w < sides.size(); ++w)
    for (int k = 0; k < 4; ++k)
      require(sides[w][k] == A::Mountain || sides[w][k] == A::Valley, "sides",
              "twist " + std::to_string(w) + " side " + std::to_string(k) + " must be M or V");

  const double t = params.twist, L = params.spacing;
  const double Ly = params.spacing_y > 0 ? params.spacing_y : params.spacing;
  const double r = params.side / std::sqrt(2.0);
  const double phi0 = t - 3 * kPi / 4;  // as square_twist: A's o_b along +x (before mirroring)
  auto mirrored = [](int i, int j) { return (i + j) % 2 == 1; };
  auto twist_index = [m](int i, int j) { return j * m + i; };

  CreasePattern p;
  p.coords_2d = true;
  // Twist vertices. Outer crease directions of vertex k (unmirrored): o_a at (k-1) pi/2,
  // o_b at k pi/2; mirroring negates x.
  std::vector<Eigen::Vector2d> pos;
  std::vector<std::array<Eigen::Vector2d, 2>> dir;  // [o_a, o_b] per twist vertex
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i)
      for (int k = 0; k < 4; ++k) {
        Eigen::Vector2d x = r * unit_vector(phi0 + k * kPi / 2);
        Eigen::Vector2d da = unit_vector((k - 1) * kPi / 2), db = unit_vector(k * kPi / 2);
        // Round the axis directions exactly (cos(pi/2) is 6e-17, not 0).
        da = da.array().round().matrix();
        db = db.array().round().matrix();
        if (mirrored(i, j)) {
          x.x() = -x.x();
          da.x() = -da.x();
          db.x() = -db.x();
        }
        pos.push_back(x + Eigen::Vector2d(i * L, j * Ly));
        dir.push_back({da, db});
      }
  for (const auto& x : pos) p.vertices.emplace_back(x.x(), x.y(), 0.0);

  auto add_edge = [&](int a, int b, A assignment) {
    p.edges.push_back({a, b});
    p.assignments.push_back(assignment);
    return p.num_edges() - 1;
  };
  // Letters of a twist vertex's outer creases (square_twist_assignment's rule; mirroring keeps
  // which creases bound the sector t, so the rule is the same).
  auto outer_letter = [&](int v, int slot) {
    const auto& s = sides[v / 4];
    const int k = v % 4;
    const A previous = s[(k + 3) % 4], twist_side = s[k];
    if (slot == 0) return previous;
    return previous == twist_side ? opposite(previous) : previous;
  };

  // Sides.
  for (int w = 0; w < m * n; ++w)
    for (int k = 0; k < 4; ++k) add_edge(4 * w + k, 4 * w + (k + 1) % 4, sides[w][k]);

  // Outer creases: to the twist vertex of the neighbour in that direction whose outer crease
  // points back along the same line, or to the sheet's boundary (the rectangle of the twists'
  // L x Ly cells). Boundary points are numbered after all creases exist.
  const double x_lo = -L / 2, x_hi = (m - 0.5) * L, y_lo = -Ly / 2, y_hi = (n - 0.5) * Ly;
  struct BoundaryPoint {
    double walk;  // arc length along the boundary, counter-clockwise from the lower-left corner
    Eigen::Vector2d x;
    int edge;     // crease ending here (-1 for a corner)
  };
  std::vector<BoundaryPoint> boundary;
  const double W = x_hi - x_lo, H = y_hi - y_lo;
  auto walk_of = [&](const Eigen::Vector2d& x, const Eigen::Vector2d& d) {
    if (d.y() < 0) return x.x() - x_lo;               // bottom side
    if (d.x() > 0) return W + (x.y() - y_lo);         // right side
    if (d.y() > 0) return W + H + (x_hi - x.x());     // top side
    return 2 * W + H + (y_hi - x.y());                // left side
  };
  std::vector<int> crease_of(8 * m * n, -1);  // 2 v + slot -> edge (slot 0 = o_a, 1 = o_b)
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i)
      for (int k = 0; k < 4; ++k)
        for (int slot = 0; slot < 2; ++slot) {
          const int v = 4 * twist_index(i, j) + k;
          if (crease_of[2 * v + slot] >= 0) continue;
          const Eigen::Vector2d d = dir[v][slot];
          const int ni = i + static_cast<int>(d.x()), nj = j + static_cast<int>(d.y());
          const A letter = outer_letter(v, slot);
          if (ni >= 0 && ni < m && nj >= 0 && nj < n) {
            // Partner: among the neighbour's vertices with a crease along -d, the one on our line.
            int best = -1, best_slot = -1;
            double best_off = 0;
            for (int kk = 0; kk < 4; ++kk)
              for (int ss = 0; ss < 2; ++ss) {
                const int u = 4 * twist_index(ni, nj) + kk;
                if ((dir[u][ss] + d).norm() > 1e-12) continue;
                const Eigen::Vector2d off = pos[u] - pos[v];
                const double perp = std::fabs(off.x() * d.y() - off.y() * d.x());
                if (best < 0 || perp < best_off) best = u, best_slot = ss, best_off = perp;
              }
            if (outer_letter(best, best_slot) != letter)
              throw InputError("sides", "the crease joining " + twist_name(i, j, k) + " and " +
                                            twist_name(ni, nj, best % 4) + " gets " + assignment_letter(letter) +
                                            " from the first twist's sides and " +
                                            assignment_letter(outer_letter(best, best_slot)) +
                                            " from the second's (the letters are not flat-foldable)");
            const int e = add_edge(v, best, letter);
            crease_of[2 * v + slot] = e;
            crease_of[2 * best + best_slot] = e;
          } else {
            Eigen::Vector2d end = pos[v];
            if (d.x() > 0) end.x() = x_hi;
            if (d.x() < 0) end.x() = x_lo;
            if (d.y() > 0) end.y() = y_hi;
            if (d.y() < 0) end.y() = y_lo;
            const int e = add_edge(v, -1, letter);
            crease_of[2 * v + slot] = e;
            boundary.push_back({walk_of(end, d), end, e});
          }
        }
  // Corners sit at walk 0, W, W + H, 2W + H.
  boundary.push_back({0.0, {x_lo, y_lo}, -1});
  boundary.push_back({W, {x_hi, y_lo}, -1});
  boundary.push_back({W + H, {x_hi, y_hi}, -1});
  boundary.push_back({2 * W + H, {x_lo, y_hi}, -1});
  std::sort(boundary.begin(), boundary.end(),
            [](const BoundaryPoint& a, const BoundaryPoint& b) { return a.walk < b.walk; });
  const int first_boundary = p.num_vertices();
  for (const auto& b : boundary) {
    const int id = p.num_vertices();
    p.vertices.emplace_back(b.x.x(), b.x.y(), 0.0);
    if (b.edge >= 0) p.edges[b.edge][1] = id;
  }
  const int nb = static_cast<int>(boundary.size());
  for (int q = 0; q < nb; ++q) add_edge(first_boundary + q, first_boundary + (q + 1) % nb, A::Boundary);

  std::string letters;
  for (const auto& s : sides)
    for (A a : s) letters.push_back(assignment_letter(a));
  nlohmann::ordered_json g;
  g["kind"] = "square-twist-tessellation";
  g["rows"] = n;
  g["cols"] = m;
  g["twist_deg"] = deg_rounded(t);
  g["side"] = params.side;
  g["spacing"] = params.spacing;
  if (params.spacing_y > 0) g["spacing_y"] = params.spacing_y;
  g["sides"] = letters;
  g["sides_order"] = "per twist row by row (twist (i, j) = j * cols + i): AB BC CD DA";
  char title[160];
  std::snprintf(title, sizeof title, "Square-twist tessellation %dx%d, twist %g deg", n, m, to_degrees(t));
  return finish_pattern(std::move(p), title, "explicit side letters (see rigidfold:generator.sides)", g);
}

CreasePattern square_twist_tessellation(const SquareTwistTessellationParams& params) {
  CreasePattern p = square_twist_tessellation(params, square_twist_tessellation_sides(params));
  static const char* frames[] = {
      "every twist Type 4 (sides V M M M), neighbours mirrored; rigidly foldable, 1 DOF",
      "every twist Type 3, rows alternate sides V M M V / M V V M; rigidly foldable, 1 DOF",
      "every twist Type 1 (sides M M M M); not rigidly foldable",
      "every twist Type 2 (sides V M V M); not rigidly foldable"};
  p.extra["frame_title"] = frames[static_cast<int>(params.layout)];
  // The layout names the letters; drop the per-twist list (rows * cols * 4 letters).
  p.extra["rigidfold:generator"].erase("sides");
  p.extra["rigidfold:generator"].erase("sides_order");
  p.extra["rigidfold:generator"]["layout"] = to_string(params.layout);
  return p;
}

}  // namespace rigidfold::generators
