#pragma once
// Slab-slab interference of a thick sheet at a list of fold states: every
// panel's slab (panel_slab.hpp) placed by the rigid motion of its face of the thick sheet,
// every pair of slabs tested with FCL (broad phase: dynamic AABB tree; narrow phase: exact
// triangle-triangle tests of the two closed slab meshes, plus a point-in-slab test for a slab
// wholly inside another, which meshes that do not cross would miss).
//
// Contact is not interference. Panels sharing a hinge touch along the hinge line (at the
// flat state along their whole common side wall), panels round a vertex touch at its corner,
// and panels folded flat touch face to face. So every slab is shrunk by `margin` before the
// test: its polygon inset by margin on every side (in its plane) and its top and bottom moved
// in by margin. A shrunk slab lies inside the original at distance >= margin from its
// boundary, so slabs that only touch are never reported, whatever the fold angle, while two
// slabs that interpenetrate by more than about 2 margin are. No other exclusion: panels that
// share a hinge are tested like every other pair (a mountain fold of slabs hinged on their
// top face makes them overlap next to the hinge, and that is reported).
//
// Inputs: the flat pattern (faces = panels) and its topology; the thick sheet
// (hinge_heights.hpp) whose faces carry the panels' motions; one slab per flat face; the
// states (per flat edge fold angles, radians, FOLD sign) with their driving angles; margin
// (pattern units, > 0, below a quarter of the thinnest slab).
// Output: per state its colliding panel pairs (flat faces a < b, sorted, with the hinge edge
// they share or -1) and the placement's closure mismatch; the total count and the first
// state with a collision.
// Throws std::invalid_argument for sizes that do not match or a margin out of range;
// NoAnswerError when a state's placement leaves cracks larger than margin / 10 (the slabs'
// poses would not be trustworthy to the margin).
// Units: lengths in pattern units, angles in radians.
#include <Eigen/Core>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/panel_slab.hpp"

namespace rigidfold {

struct SlabCollision {
  int face_a = -1, face_b = -1;  // flat faces, a < b
  int shared_edge = -1;          // hinge edge between them, -1 when they share none
};

struct SlabInterferenceState {
  double drive = 0.0;                    // driving crease's fold angle (radians)
  std::vector<SlabCollision> collisions; // sorted by (a, b)
  double placement_mismatch = 0.0;       // FoldedGeometry::max_mismatch (pattern units)
};

struct SlabInterference {
  double margin = 0.0;                        // pattern units
  std::vector<SlabInterferenceState> states;  // same order as the input states
  long long collision_count = 0;              // (state, pair) collisions over every state
  int first_state = -1;                       // first state with a collision, -1 if none
  bool passed() const { return collision_count == 0; }
};

SlabInterference slab_interference(const CreasePattern& flat, const Topology& topology, const ThickHeightSheet& sheet,
                                   const std::vector<PanelSlab>& slabs, const std::vector<double>& drives,
                                   const std::vector<Eigen::VectorXd>& states, double margin);

}  // namespace rigidfold
