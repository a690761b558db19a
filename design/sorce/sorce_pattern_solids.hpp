#pragma once
// Printable solids of a whole pattern's SORCE panels: every face of a
// PatternSorce built by panel_solid (sorce_solids.hpp) in its flat t = 0 pose - its slab cut
// back from each folding crease and one cam per such crease, the crease's sampled profile
// (sample_profiles) extruded along it.
//
// Inputs: the flat pattern and its joints (sorce_pattern.hpp), `samples` points per profile
// (>= 2). Output: per face its PanelSolid, and per face and cam input the crease (edge index)
// the cam belongs to, so that checks can tell a cam's rolling partner (the other face's cam on
// the same crease). Units: the pattern's.
// Clearance cuts (ClearanceOptions::cut): for each folding crease and each of its two faces,
// the region the mate's cam section sweeps in this face's fold-frame coordinates - the mate's
// section posed by the crease's planar relative motion (eq 55: right -> left
//   q = R(gamma) (p + (0, z_r)) + d - (0, z_l), and its inverse) at `samples` evenly spaced t,
// their union (Boost.Geometry), grown by `margin` (round joins) - removed from this face's slab
// over the mate cam's extent along the crease plus the margin (panel_solid's Clearance).
// The margin must cover the motion between sweep samples: sweep_step reports the largest
// move of a section point from one sample to the next (length), beside the margin used.
// Throws InputError("faces[f]: ...") when a panel cannot be built (not convex, a cam section
// that crosses itself; panel_solid's places after the face).
#include <vector>

#include "design/sorce/sorce_pattern.hpp"
#include "design/sorce/sorce_solids.hpp"

namespace rigidfold::sorce {

struct ClearanceOptions {
  bool cut = false;      // off: panels as panel_solid builds them without clearances
  double margin = 0.05;  // grown around the swept region, as a fraction of the cut face's thickness (> 0)
  int samples = 41;      // sweep samples in t (>= 2), each interval refined as below
};

struct ClearanceCut {
  int face = -1, edge = -1;  // the face cut, the crease whose mate cam sweeps it
  double margin = 0.0;       // length
  double sweep_step = 0.0;   // largest move of a mate section point between sweep samples (length)
  double region_area = 0.0;  // area of the grown swept region (length^2), before meeting the slab
  bool cut = false;          // false: the region misses the slab (nothing removed)
};

struct PatternSolids {
  std::vector<PanelSolid> panels;           // per face, flat coordinates (mid-plane z = 0)
  std::vector<std::vector<int>> cam_edge;   // cam_edge[f][k]: crease of PanelSolidInput::cams[k] of face f
  std::vector<ClearanceCut> clearances;     // one per folding crease side whose mate has a cam
};

PatternSolids pattern_solids(const CreasePattern& pattern, const PatternSorce& sorce, int samples,
                             const SolidOptions& options = {}, const ClearanceOptions& clearance = {});

}  // namespace rigidfold::sorce
