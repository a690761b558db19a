#include "design/sorce/sorce_solids.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <string>

#include <boost/geometry.hpp>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {
namespace {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint>;

double signed_area(const std::vector<Vec2>& p) {
  double a = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec2& u = p[k];
    const Vec2& v = p[(k + 1) % p.size()];
    a += u.x() * v.y() - u.y() * v.x();
  }
  return a / 2;
}

// A prism: the 2D section (in the basis u, v at `origin`) swept along e = u x v from a to b.
// Appends its polygons, outward, to `out` tagged with `shell`.
void add_prism(PanelSolid& out, int shell, const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
               const Eigen::Vector3d& v, std::vector<Vec2> section, double a, double b) {
  if (signed_area(section) < 0.0) std::reverse(section.begin(), section.end());  // counter-clockwise about e
  const Eigen::Vector3d e = u.cross(v);
  auto at = [&](const Vec2& p, double w) -> Eigen::Vector3d { return origin + p.x() * u + p.y() * v + w * e; };
  Polygon3 top, bottom;
  for (const Vec2& p : section) top.push_back(at(p, b));
  for (auto it = section.rbegin(); it != section.rend(); ++it) bottom.push_back(at(*it, a));
  out.polygons.push_back(std::move(top));
  out.polygons.push_back(std::move(bottom));
  out.shell_of_polygon.insert(out.shell_of_polygon.end(), 2, shell);
  for (std::size_t k = 0; k < section.size(); ++k) {
    const Vec2& p = section[k];
    const Vec2& q = section[(k + 1) % section.size()];
    out.polygons.push_back({at(p, a), at(q, a), at(q, b), at(p, b)});  // (q - p) x e points out of a CCW section
    out.shell_of_polygon.push_back(shell);
  }
  out.shell_volumes.push_back(std::abs(signed_area(section)) * (b - a));
}

// Keeps the part of a convex polygon where n . p >= c (Sutherland-Hodgman, one plane).
std::vector<Vec2> clip(const std::vector<Vec2>& poly, const Vec2& n, double c) {
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec2& p = poly[k];
    const Vec2& q = poly[(k + 1) % poly.size()];
    const double fp = n.dot(p) - c, fq = n.dot(q) - c;
    if (fp >= 0.0) out.push_back(p);
    if ((fp >= 0.0) != (fq >= 0.0)) out.push_back(p + (q - p) * (fp / (fp - fq)));
  }
  return out;
}

// A cam's or a clearance's fold frame: origin finite, fold direction and x axis orthonormal in
// the plane z = 0 (to 1e-9).
void check_fold_frame(const Eigen::Vector3d& origin, const Eigen::Vector3d& fold_direction, const Eigen::Vector3d& x_axis,
                      const std::string& place) {
  const double frame_error = std::max({std::abs(fold_direction.norm() - 1.0), std::abs(x_axis.norm() - 1.0),
                                       std::abs(fold_direction.dot(x_axis)), std::abs(fold_direction.z()),
                                       std::abs(x_axis.z())});
  if (!(frame_error <= 1e-9) || !origin.allFinite()) throw InputError(place, "the fold frame must be orthonormal in the plane z = 0");
}

bool simple_section(const std::vector<Vec2>& section) {
  BgPolygon poly;
  for (const Vec2& p : section) bg::append(poly.outer(), BgPoint(p.x(), p.y()));
  bg::correct(poly);  // closes the ring and orients it as Boost.Geometry expects
  return bg::is_valid(poly);
}

using BgMulti = bg::model::multi_polygon<BgPolygon>;

// The u-range [lo, hi] along `w_dir` of a convex polygon's points with `n` . p in [c, c + width].
std::array<double, 2> w_range(const std::vector<Vec2>& poly, const Vec2& n, double c, double width, const Vec2& w_dir) {
  const std::vector<Vec2> strip = clip(clip(poly, n, c), -n, -(c + width));
  std::array<double, 2> r{1e300, -1e300};
  for (const Vec2& p : strip) r = {std::min(r[0], w_dir.dot(p)), std::max(r[1], w_dir.dot(p))};
  return r;
}

}  // namespace

PanelSolid panel_solid(const PanelSolidInput& input, const SolidOptions& options) {
  const double h = input.thickness;
  if (!(h > 0.0) || !std::isfinite(h)) throw InputError("thickness", "must be a positive number");
  if (!(options.overlap > 0.0) || !(options.margin > options.overlap) || !std::isfinite(options.margin))
    throw InputError("options", "need 0 < overlap < margin (fractions of the thickness)");
  const std::size_t n = input.polygon.size();
  if (n < 3) throw InputError("polygon", "a panel needs at least 3 points");
  std::vector<Vec2> flat;
  double scale = 0.0;
  for (const Eigen::Vector3d& p : input.polygon) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d& p = input.polygon[k];
    if (!p.allFinite() || std::abs(p.z()) > 1e-12 * std::max(scale, 1.0))
      throw InputError("polygon[" + std::to_string(k) + "]", "panel points must be finite and flat (z = 0)");
    flat.push_back(p.head<2>());
  }
  for (std::size_t k = 0; k < n; ++k) {  // convex, counter-clockwise: every turn is to the left
    const Vec2 a = flat[(k + 1) % n] - flat[k], b = flat[(k + 2) % n] - flat[(k + 1) % n];
    if (!(a.x() * b.y() - a.y() * b.x() > 0.0))
      throw InputError("polygon[" + std::to_string((k + 1) % n) + "]", "the panel must be convex and counter-clockwise seen from +z");
  }
  const double gap = options.vertex_gap < 0.0 ? h : options.vertex_gap;
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();

  PanelSolid out;
  std::vector<Vec2> slab = flat;
  struct CamShell {
    int index;
    std::vector<Vec2> section;
    double a, b;
  };
  std::vector<CamShell> cams;
  for (std::size_t k = 0; k < input.cams.size(); ++k) {
    const CamSide& c = input.cams[k];
    const std::string place = "cams[" + std::to_string(k) + "]";
    check_fold_frame(c.origin, c.fold_direction, c.x_axis, place);
    if (!(c.w1 > c.w0)) throw InputError(place, "the crease extent needs w1 > w0");
    if (c.profile.size() < 2) throw InputError(place, "a profile needs at least 2 points");
    // The right panel mirrored (x -> -x) so that both panels lie at x < 0 of the fold line.
    const double mirror = c.left ? 1.0 : -1.0;
    std::vector<Vec2> profile;
    double x_min = 0.0, extent = 0.0;
    for (const Vec2& p : c.profile) {
      if (!p.allFinite()) throw InputError(place, "profile points must be finite");
      profile.emplace_back(mirror * p.x(), p.y());
      x_min = std::min(x_min, profile.back().x());
      extent = std::max(extent, (p - c.profile.front()).norm());
    }
    const double x_base = x_min - options.margin * h;
    // The slab keeps mirror * (p - origin) . x_axis <= x_cut: x_base + overlap h under a cam,
    // x_base (the margin behind the fold line) at a plain revolute.
    const Vec2 inward = -mirror * c.x_axis.head<2>();
    const bool revolute = extent <= 1e-9 * h;
    slab = clip(slab, inward, inward.dot(c.origin.head<2>()) - (revolute ? x_base : x_base + options.overlap * h));
    if (slab.size() < 3 || !(std::abs(signed_area(slab)) > 0.0)) throw InputError(place + ": slab", "the cut-backs leave no slab");
    const double a = c.w0 + gap, b = c.w1 - gap;
    if (revolute || !(b > a)) {
      out.cams_skipped.push_back(static_cast<int>(k));
      continue;
    }
    // Closed around the profile's excursions: on the side opposite its end at the slab face or
    // `margin` beyond the profile, whichever is farther; on its end's side at the end's height,
    // or `margin` above the profile where it rises beyond its end.
    const double y_end = profile.back().y(), sigma = y_end < 0.0 ? -1.0 : 1.0;
    double below = 0.0, above = sigma * y_end;
    for (const Vec2& p : profile) below = std::max(below, -sigma * p.y()), above = std::max(above, sigma * p.y());
    const double y_lo = -sigma * std::max(h / 2, below > 0.0 ? below + options.margin * h : 0.0);
    std::vector<Vec2> section{Vec2(x_base, y_lo), Vec2(profile.front().x(), y_lo)};
    section.insert(section.end(), profile.begin(), profile.end());
    if (above > sigma * y_end) {
      const double y_top = sigma * (above + options.margin * h);
      section.emplace_back(profile.back().x(), y_top);
      section.emplace_back(x_base, y_top);
    } else {
      section.emplace_back(x_base, y_end);
    }
    if (!simple_section(section))
      throw InputError(place, "the cam's cross-section crosses itself (the profile crosses itself or the lines that close it)");
    for (Vec2& p : section) p.x() *= mirror;  // back to the fold frame
    cams.push_back({static_cast<int>(k), std::move(section), a, b});
  }
  // Clearance cuts (header): the back of the slab stays in `slab`, the band's pieces wait.
  struct Piece {
    Eigen::Vector3d origin, u, v;
    std::vector<Vec2> section;
    double a, b;
  };
  std::vector<Piece> pieces;
  const double ov = options.overlap * h;
  for (std::size_t k = 0; k < input.clearances.size(); ++k) {
    const Clearance& c = input.clearances[k];
    const std::string place = "clearances[" + std::to_string(k) + "]";
    check_fold_frame(c.origin, c.fold_direction, c.x_axis, place);
    if (!(c.w1 > c.w0)) throw InputError(place, "the extent needs w1 > w0");
    const Vec2 o = c.origin.head<2>(), ux = c.x_axis.head<2>(), uw = c.fold_direction.head<2>();
    // u: distance from the fold line into this panel (the panel's side from its slab's centroid).
    Vec2 centroid = Vec2::Zero();
    for (const Vec2& p : slab) centroid += p / static_cast<double>(slab.size());
    const double mirror = (centroid - o).dot(ux) < 0.0 ? 1.0 : -1.0;
    const Vec2 into = -mirror * ux;  // u = into . (p - o)
    double u_edge = 1e300, u_far = -1e300;
    for (const Vec2& p : slab) u_edge = std::min(u_edge, into.dot(p - o)), u_far = std::max(u_far, into.dot(p - o));
    BgMulti region;
    for (const std::vector<Vec2>& ring : c.region) {
      BgPolygon poly;
      for (const Vec2& p : ring) {
        if (!p.allFinite()) throw InputError(place, "region points must be finite");
        bg::append(poly.outer(), BgPoint(-mirror * p.x(), p.y()));  // (u, y)
      }
      bg::correct(poly);
      if (!bg::is_valid(poly)) throw InputError(place, "a region polygon is not simple");
      BgMulti merged;
      bg::union_(region, poly, merged);
      region = std::move(merged);
    }
    BgPolygon depth_box;  // the slab's section from its fold edge to its far side
    for (const Vec2& p : {Vec2(u_edge, -h / 2), Vec2(u_far, -h / 2), Vec2(u_far, h / 2), Vec2(u_edge, h / 2)})
      bg::append(depth_box.outer(), BgPoint(p.x(), p.y()));
    bg::correct(depth_box);
    BgMulti inside;
    bg::intersection(region, depth_box, inside);
    if (!(bg::area(inside) > 1e-12 * h * h)) {
      out.clearances_unneeded.push_back(static_cast<int>(k));
      continue;
    }
    double deepest = u_edge;
    for (const BgPolygon& poly : inside)
      for (const BgPoint& p : poly.outer()) deepest = std::max(deepest, p.x());
    const double u_cut = deepest + ov;
    if (!(u_cut + ov < u_far)) throw InputError(place, "the clearance cuts the slab through");
    // The band's extent along the fold where it is full depth (convex slab: both ends' ranges).
    const std::array<double, 2> near_end = w_range(slab, into, into.dot(o) + u_edge, 1e-9 * h, uw);
    const std::array<double, 2> far_end = w_range(slab, into, into.dot(o) + u_cut - 1e-9 * h, 1e-9 * h, uw);
    const double full_lo = std::max(near_end[0], far_end[0]) - uw.dot(o), full_hi = std::min(near_end[1], far_end[1]) - uw.dot(o);
    // Kept ov/2 inside the full-depth range: a middle piece ending exactly there would share
    // its corner edge with the uncut end piece (an edge used twice: not a manifold).
    // Where the band is not full depth within the clearance's extent (near a corner of the
    // panel), it is removed whole: the uncut end pieces stop at the extent, the middle pieces
    // start where the band is full depth.
    const double lo_cut = c.w0 - ov, hi_cut = c.w1 + ov;
    const double m_lo = std::max(lo_cut, full_lo + ov / 2), m_hi = std::min(hi_cut, full_hi - ov / 2);
    const std::vector<Vec2> band = clip(slab, -into, -(into.dot(o) + u_cut));
    slab = clip(slab, into, into.dot(o) + deepest);  // the back, reaching `overlap` into the band
    const Eigen::Vector3d e = c.x_axis.cross(ez);
    const double sense = e.dot(c.fold_direction) > 0.0 ? 1.0 : -1.0;
    for (const auto& [n, off] : {std::pair{Vec2(-uw), -(uw.dot(o) + lo_cut + ov)}, std::pair{Vec2(uw), uw.dot(o) + hi_cut - ov}}) {
      const std::vector<Vec2> end = clip(band, n, off);
      if (end.size() >= 3 && std::abs(signed_area(end)) > 1e-12 * h * h)
        pieces.push_back({Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), end, -h / 2, h / 2});
    }
    BgPolygon rect;
    for (const Vec2& p : {Vec2(u_edge, -h / 2), Vec2(u_cut, -h / 2), Vec2(u_cut, h / 2), Vec2(u_edge, h / 2)})
      bg::append(rect.outer(), BgPoint(p.x(), p.y()));
    bg::correct(rect);
    BgMulti left;
    bg::difference(rect, region, left);
    double a = sense * m_lo, b = sense * m_hi;
    if (a > b) std::swap(a, b);
    if (!(m_hi > m_lo)) left.clear();  // no full-depth band within the extent: all of it removed
    for (const BgPolygon& poly : left) {
      if (!poly.inners().empty()) throw InputError(place, "the cut leaves a slab piece with a hole");
      std::vector<Vec2> section;
      for (std::size_t i = 0; i + 1 < poly.outer().size(); ++i)  // the ring repeats its first point
        section.emplace_back(-mirror * poly.outer()[i].x(), poly.outer()[i].y());
      if (section.size() < 3 || !(std::abs(signed_area(section)) > 1e-12 * h * h)) continue;
      pieces.push_back({c.origin, c.x_axis, ez, std::move(section), a, b});
      ++out.clearance_pieces;
    }
    if (slab.size() < 3) throw InputError(place, "the clearance cuts the slab through");
  }
  add_prism(out, 0, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), slab, -h / 2, h / 2);
  for (std::size_t s = 0; s < cams.size(); ++s) {
    const CamSide& c = input.cams[cams[s].index];
    const Eigen::Vector3d e = c.x_axis.cross(ez);  // the prism's sweep direction
    const double sense = e.dot(c.fold_direction) > 0.0 ? 1.0 : -1.0;
    double a = sense * cams[s].a, b = sense * cams[s].b;
    if (a > b) std::swap(a, b);
    add_prism(out, static_cast<int>(s) + 1, c.origin, c.x_axis, ez, cams[s].section, a, b);
    out.cam_of_shell.push_back(cams[s].index);
    out.cam_sections.push_back(cams[s].section);
    out.cam_extents.push_back({cams[s].a, cams[s].b});
  }
  for (std::size_t k = 0; k < pieces.size(); ++k)
    add_prism(out, static_cast<int>(cams.size() + 1 + k), pieces[k].origin, pieces[k].u, pieces[k].v, pieces[k].section,
              pieces[k].a, pieces[k].b);
  return out;
}

std::vector<Polygon3> transformed(const std::vector<Polygon3>& polygons, const Eigen::Isometry3d& pose) {
  std::vector<Polygon3> out;
  out.reserve(polygons.size());
  for (const Polygon3& p : polygons) {
    Polygon3 q;
    q.reserve(p.size());
    for (const Eigen::Vector3d& x : p) q.push_back(pose * x);
    out.push_back(std::move(q));
  }
  return out;
}

}  // namespace rigidfold::sorce
