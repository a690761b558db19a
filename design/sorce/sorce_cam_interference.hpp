#pragma once
// Cam interference of a pattern's SORCE solids along the folding path (slab and
// cam non-interference over sampled t, by FCL; the slab-only check is
// PatternChecks::interference in sorce_pattern.hpp).
//
// Every cam shell of every panel (sorce_pattern_solids.hpp), placed by its panel's pose
// P_f(t) (panel_poses), is tested against every shell of every OTHER panel - slabs and cams,
// the mate's slab included - at `samples` evenly spaced t in [0, 1]. Excluded:
//   - shells of one panel (its slab and cams overlap on purpose: one printed part);
//   - slab against slab (PatternChecks::interference does that with its own cut-backs);
//   - a cam against its rolling partner, the mate's cam on the SAME crease: they touch along
//     the contact line by construction (that contact is the joint), so the pair is skipped by
//     identity, not by a tolerance.
// Touching is not interference: every shell is tested shrunk toward its panel's mid-plane
// (flat coordinates' z scaled by 1 - 2e-9: a slab face at h/2 moves in by 1e-9 h), so layers
// stacked face to face at t = 1 do not count. Narrow phase: FCL mesh-mesh
// (surfaces crossing; a shell wholly inside another at a sample is not seen); broad phase:
// FCL's dynamic AABB tree.
//
// Inputs: the pattern, its joints, their solids (flat coordinates), samples >= 2.
// Output: every colliding pair at every sample (t ascending), and the counts tested.
// Units: t dimensionless.
#include <vector>

#include "design/sorce/sorce_pattern.hpp"
#include "design/sorce/sorce_pattern_solids.hpp"

namespace rigidfold::sorce {

struct CamCollision {
  double t = 0.0;
  int face_a = -1, face_b = -1;  // face_a < face_b
  int edge_a = -1, edge_b = -1;  // the crease of each shell's cam; -1: that shell is the panel's slab
};

struct CamInterference {
  std::vector<double> times;               // the sampled t
  std::vector<CamCollision> collisions;    // t ascending; empty: no cam interferes
  long long pairs_tested = 0;              // narrow-phase tests over all samples
  int partner_pairs_skipped = 0;           // rolling-partner pairs per sample (the joints)
};

// Throws InputError("samples") if samples < 2.
CamInterference cam_interference(const CreasePattern& pattern, const PatternSorce& sorce, const PatternSolids& solids,
                                 int samples);

}  // namespace rigidfold::sorce
