#pragma once
// Printable solids of SORCE panels: each panel as closed, outward-oriented
// polygon shells — its slab cut back from every fold that carries a cam, and one cam per
// such fold: the fold's profile (sorce_profile.hpp) extruded along the crease — for binary
// STL (polygons_stl in kernel/geometry/folded_output.hpp).
//
// Frame of a cam (the fold's normal plane, digest section 1): a point (x, y) of the profile
// at distance w along the crease is origin + x * x_axis + y * e_z + w * fold_direction, in
// the flat pattern's coordinates with the panel's mid-plane at z = 0 (its t = 0 pose; place
// the shells at t by the panel's pose, offset included).
//
// Cam cross-section (left panel; the right one mirrored, x -> -x): the profile s(0) .. s(1)
// closed around its excursions - with sigma = sgn(y_e), y_e = s(1).y, from s(1) to x_base at
// y_e (or first up to `margin` beyond the profile where it rises beyond y_e on sigma's side),
// down to y_lo = -sigma max(h/2, the profile's reach on the other side + margin), and back to
// (s(0).x, y_lo) - where x_base lies `margin` behind the profile's farthest point into the
// panel (never in front of the fold line). The
// slab is the panel polygon clipped at x_base + overlap (toward the fold): it reaches
// `overlap` into the cam, so the shells overlap and their union (what a slicer prints) is one
// solid. Each cam is cut `vertex_gap` short of both ends of its crease, so the cams of
// neighbouring folds do not meet at a vertex. A profile shorter than 1e-9 h (z = 0 on both
// sides: a plain revolute) gets no cam; the slab is still cut back by `margin`.
// Clearance cuts (a mate's cam that protrudes beyond its own slab faces sweeps through this
// slab as the fold turns): each Clearance gives, in a fold's frame, the region the mate's cam
// section sweeps over the path in this panel's coordinates (sorce_pattern_solids.hpp builds
// it, margin included) and its extent along the fold. The slab is then split, per clearance:
//   - the back: the slab on the panel's side of u_cut + overlap h, u_cut = `overlap` h
//     beyond the region's deepest point into the slab (u the distance from the fold line
//     into the panel, mirrored as above);
//   - the band between u_cut and the slab's edge at the fold: over the clearance's extent
//     (widened by overlap h each way), the rectangle [u_cut, edge] x [-h/2, h/2] less the
//     region (Boost.Geometry difference), extruded along the fold, one prism per piece left,
//     where the band is full depth; where it is not (a panel corner) the band is removed whole;
//     before and after that extent the band uncut (reaching overlap h into the cut part).
// The pieces overlap (never share an edge), each is closed and outward, so the mesh stays a
// closed manifold and their union is the printed slab. Clearances are applied one after the
// other to the back; a later band is not cut by an earlier one's region (the FCL check,
// sorce_cam_interference.hpp, tells whether the cut parts still meet). A region that does
// not reach the slab is no cut (listed in clearances_unneeded).
//
// Units: the pattern's length units; thickness h and gaps in the same.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "design/sorce/sorce_profile.hpp"

namespace rigidfold::sorce {

using Polygon3 = std::vector<Eigen::Vector3d>;

struct CamSide {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();          // on the crease line, z = 0
  Eigen::Vector3d fold_direction = Eigen::Vector3d::UnitY();  // unit, along the crease, z = 0
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();          // unit, in plane, from the left panel into the right
  double w0 = 0.0, w1 = 1.0;  // the crease's extent along fold_direction from origin, w1 > w0
  bool left = true;           // this panel is the fold's left panel (uses s_left) or its right one (s_right)
  std::vector<Vec2> profile;  // this panel's profile points, t = 0 .. 1 (sample_profiles)
};

struct Clearance {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();           // as CamSide: on the crease line, z = 0
  Eigen::Vector3d fold_direction = Eigen::Vector3d::UnitY();  // unit, along the crease, z = 0
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();          // unit, in plane, from the fold's left panel into its right
  double w0 = 0.0, w1 = 1.0;  // the cut's extent along fold_direction from origin, w1 > w0
  // The removed region: simple polygons (no holes, either orientation) of points (x, y),
  // x along x_axis, y along +z, in this panel's flat coordinates (mid-plane y = 0).
  std::vector<std::vector<Vec2>> region;
};

struct PanelSolidInput {
  Polygon3 polygon;  // the flat panel, z = 0, counter-clockwise seen from +z, convex
  double thickness = 0.0;
  std::vector<CamSide> cams;
  std::vector<Clearance> clearances;
};

struct SolidOptions {
  double margin = 0.1;       // x_base behind the profile, as a fraction of the thickness (> overlap)
  double overlap = 0.05;     // slab reaching into the cam, fraction of the thickness (> 0)
  double vertex_gap = -1.0;  // length cut off each end of a cam; < 0: the thickness
};

struct PanelSolid {
  std::vector<Polygon3> polygons;  // every shell's polygons, outward (counter-clockwise about the outward normal)
  std::vector<int> shell_of_polygon;  // 0 the slab (its back when cut), k the k-th cam built, then clearance pieces
  // Volume of each shell (slab first) from its 2D cross-section's area: independent of the
  // polygon assembly, so a mesh volume can be checked against it.
  std::vector<double> shell_volumes;
  std::vector<int> cam_of_shell;  // index into PanelSolidInput::cams per cam shell (shell k -> cams[cam_of_shell[k-1]])
  std::vector<int> cams_skipped;  // cams with no solid: a plain revolute or a crease shorter than 2 gaps
  // Per cam shell (same order as cam_of_shell): its section in the fold frame (x along
  // x_axis, y along +z; closed, counter-clockwise or not) and its extent [a, b] along
  // fold_direction from origin - what a mate's clearance is swept from.
  std::vector<std::vector<Vec2>> cam_sections;
  std::vector<std::array<double, 2>> cam_extents;
  // Shells after the cams (1 + cams .. end): pieces of the slab left by clearance cuts.
  std::vector<int> clearances_unneeded;  // clearances whose region misses the slab
  int clearance_pieces = 0;              // band prisms built over the clearances' extents
};

// Throws InputError: "polygon" (< 3 points, not planar at z = 0, not convex and counter-
// clockwise), "thickness" (<= 0), "options" (margin <= overlap or overlap <= 0),
// "cams[k]" (a frame that is not orthonormal in the plane, w1 <= w0, fewer than 2 profile
// points, or a cross-section that crosses itself - the profile doubles back over its own
// closing lines), "cams[k]: slab" when the cut-backs leave no slab, "clearances[k]" (a frame
// that is not orthonormal, w1 <= w0, a region that is not a valid polygon, that cuts the
// slab through or leaves a piece with a hole).
PanelSolid panel_solid(const PanelSolidInput& input, const SolidOptions& options = {});

// The polygons moved by a rigid motion (a panel's pose at some t).
std::vector<Polygon3> transformed(const std::vector<Polygon3>& polygons, const Eigen::Isometry3d& pose);

}  // namespace rigidfold::sorce
