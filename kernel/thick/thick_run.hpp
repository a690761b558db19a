#pragma once
// The `rigidfold thick` command's one kernel call: every check on the
// user's input and on the answers, so that the command line only parses, calls this and
// prints.
//
// Inputs: a pattern as read from its file (complete_and_validate'd, faces present) and its
// topology; ThickRunRequest below.
// Checks, in order, each an InputError naming its place:
//   "pattern":   no interior vertex (nothing for thickness to change); a vertex off z = 0
//                (require_flat_pattern: a folded form needs its flat development first);
//   "thickness": not finite, <= 0, or above the pattern's diagonal (printed in file units);
//   "hinges":    as thick_report (valley without letters, Bennett heights that do not exist);
//   "at":        slabs_at outside the traced thick motion (thick_state_at).
// Then: zero_thickness_samples (17 steps, up to 90 deg, `reverse` as asked), thick_report
// (mobility, trace, extension, slab interference, stacking order), and where slabs_at is
// given the slabs placed there (thick_state_at, place_thick_sheet, slab_polygons) with the
// placement's cracks <= 1e-9 of the pattern's size, else NoAnswerError.
// Units: thickness in the FILE's length units (CreasePattern::length_exponent converts);
// everything returned in the pattern's internal units (to_file_units for printing); angles in
// radians.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_report.hpp"

namespace rigidfold {

struct ThickRunRequest {
  double thickness = 0.0;             // file units, 0 < T <= the pattern's diagonal
  ThickHinges hinges = ThickHinges::kBennett;
  bool reverse = false;               // zero-thickness motion the other way from flat
  std::optional<double> slabs_at;     // driving crease's fold angle (radians) for the slabs
};

struct ThickSlabsAt {
  ThickTraceStep state;               // closes to 1e-10 (checked by thick_state_at)
  FoldedGeometry placed;              // relative_mismatch() <= 1e-9 (checked)
  std::vector<std::vector<Eigen::Vector3d>> polygons;  // slab_polygons, pattern units
};

struct ThickRun {
  ThickReportRequest request;         // as given to thick_report (thickness in pattern units, samples)
  ThickReport report;
  std::optional<ThickSlabsAt> at;
};

ThickRun run_thick(const CreasePattern& flat, const Topology& topology, const ThickRunRequest& request);

}  // namespace rigidfold
