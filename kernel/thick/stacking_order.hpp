#pragma once
// Stacking order of a thick sheet's panels at one fold state, meant for the fully folded end
// of its path: which panel lies on which side of which.
//
// Two views, both from the slabs (panel_slab.hpp) placed by their faces of the thick sheet:
//   - per crease: for hinge e between panels a and b, the side of a's plane on which b's
//     slab centre lies (its top side: along a's folded +z) and the other way round. A
//     valley folded far brings the panels' top faces together, so each lies on the other's
//     top side; a mountain, each on the other's bottom side. `agrees_with_letter` compares
//     that with the crease's M/V letter: at +-pi the kinematics alone cannot say which
//     (a rotation by +pi and by -pi is the same rotation), the slabs' heights do - hinges on
//     the top face put every folded panel on top, through its neighbour for a mountain;
//     A centre within 1e-9 of the pattern's diagonal of the other's plane is level (side 0:
//     neither; e.g. every crease at the flat state), which agrees with no letter;
//   - when every panel is parallel to panel 0 (within 1e-6 rad) and one at least is turned
//     over (its normal against panel 0's: folded flat, not merely flat), the layers
//     along panel 0's top normal n: each slab's interval [low, high] along n, the panels
//     sorted bottom to top by their centres, and every pair whose footprints overlap seen
//     along n (intersection area > 1e-9 of the pattern's diagonal squared) with its gap
//     (upper.low - lower.high; < 0: the slabs interpenetrate there). A panel's layer is the
//     length of the longest chain of overlapping panels below it, so panels side by side
//     share a layer.
//
// Inputs: the flat pattern and topology, the thick sheet (hinge_heights.hpp), one slab per
// flat face, fold angles per flat edge (radians, FOLD sign) at which the sheet closes (the
// caller checks its closure).
// Output: StackingOrder below. Lengths in pattern units, angles in radians.
// Throws std::invalid_argument for sizes that do not match.
#include <Eigen/Core>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/panel_slab.hpp"

namespace rigidfold {

struct CreaseStacking {
  int edge = -1;
  int face_a = -1, face_b = -1;   // topology.edge_faces[edge]
  int b_side_of_a = 0;            // +1: b's centre on a's top side, -1: bottom side, 0: level
  int a_side_of_b = 0;
  bool has_letter = false;        // M or V
  bool agrees_with_letter = false;  // V: both +1; M: both -1
};

struct StackedPanel {
  int face = -1;
  double low = 0.0, high = 0.0;  // slab interval along the stack normal (pattern units)
  int layer = 0;                 // 0 at the bottom
};

struct StackedPair {
  int lower = -1, upper = -1;    // flat faces, by centre height
  double gap = 0.0;              // upper.low - lower.high (pattern units)
  double overlap_area = 0.0;     // of the footprints seen along the normal (pattern units^2)
};

struct StackingOrder {
  std::vector<CreaseStacking> creases;  // every hinge, by edge index
  int letter_disagreements = 0;         // lettered creases whose panels lie against their letter
  double max_tilt = 0.0;                // largest angle between a panel's normal and +-n (radians)
  bool flat_folded = false;             // max_tilt <= 1e-6 and a panel turned over
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // panel 0's folded top normal
  // Filled only when flat_folded:
  std::vector<StackedPanel> panels;     // bottom to top
  std::vector<StackedPair> overlaps;    // sorted by (lower, upper) height order
  int layers = 0;                       // 1 + the highest layer
  double min_gap = 0.0;                 // over overlaps (0 when none)
};

StackingOrder stacking_order(const CreasePattern& flat, const Topology& topology, const ThickHeightSheet& sheet,
                             const std::vector<PanelSlab>& slabs, const Eigen::VectorXd& fold_angles);

}  // namespace rigidfold
