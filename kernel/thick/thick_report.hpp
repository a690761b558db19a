#pragma once
// The thick-panel front door: a flat crease pattern, one panel thickness
// and a hinge placement in, a checked report out - the thick sheet, its mobility at the flat
// state, and (when it moves) a short trace from flat compared with the zero-thickness motion.
//
// Inputs (ThickReportRequest):
//   - a flat pattern (complete_and_validate'd, faces present) and its topology;
//   - thickness t > 0 (pattern units, the CreasePattern's internal units); every panel is the
//     slab [0, t] at the flat state;
//   - the hinge placement (ThickHinges):
//       kTop, kBottom, kMid: every hinge on the top face (z = t), the bottom face (z = 0) or
//         the mid-plane (z = t/2). All hinges then lie in one plane, so the hinge axes of a
//         vertex meet and the kinematics is the zero-thickness one (the slabs' volume is
//         what differs: see the STL);
//       kValley: each hinge on the face its crease folds towards - top for V, bottom for M
//         (every crease at an interior vertex must be M or V). Opposite links of a
//         degree-4 vertex then differ (t, 0, 0, t): not a Bennett, so no vertex follows the
//         zero-thickness motion and a Miura-ori is rigid (DOF 0 at a regular flat state),
//         though each vertex alone keeps first-order DOF 1 at its singular flat state;
//       kBennett: the heights of bennett_heights.hpp (Bennett staircases, thickness scale t),
//         which keep the zero-thickness motion; needs zero-thickness folded states. Each is
//         tried, the most folded first, until the per-vertex staircases agree on every shared
//         crease (where two start creases close at a state, bennett_hinge_heights' pick
//         depends on the state); the heights are then checked against every state.
//   - zero-thickness fold states to compare with (per flat edge, radians, FOLD sign), all on
//     one branch driven by crease `drive`, in order of increasing |drive angle|; the thick
//     trace is taken at their driving angles. zero_thickness_samples() makes them with
//     trace_motion. May be empty (then no trace and no off-motion test; kBennett refuses).
//
// Output (ThickReport), every number checked before it is put in:
//   - edge_heights: the hinge height of every flat edge (pattern units); the sheet
//     (thick_sheet_from_hinge_heights, truncation 0.1);
//   - mobility at the flat state (thick_mobility.hpp): DOF with its rank cut and smallest kept
//     singular value, locked vertices, off-motion vertices with their residuals; the flat
//     state closes exactly (residual 0 <= closure_tolerance, checked by thick_mobility);
//   - when DOF >= 1 and states were given: the thick sheet traced from flat by Newton
//     projection on its ClosureSystem with the driving crease held at each state's driving
//     angle (predictor: the previous thick state plus the zero-thickness increment; halved
//     steps where Newton fails). Each step kept has closure residual <= closure_tolerance
//     (1e-10), re-evaluated after Newton; the first step that cannot be reached ends the
//     trace (trace_note says where and why). Per step the largest |rho_thick - rho_zero|
//     (radians, over every flat edge) and the first-order DOF there;
//   - past the trace, the extension (see ThickReport); the slabs, their interference along
//     flat + trace + extension, the stacking order at the end of that path.
//
// Units: lengths in pattern units, angles in radians.
// Throws InputError: place "pattern" (a vertex off z = 0: not a flat pattern), "thickness"
// (not finite or <= 0), "hinges" (valley placement on a
// crease without M/V, Bennett without a folded zero-thickness state, Bennett heights that do
// not exist for the pattern - the kernel's message names the vertex or the crease).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/hinge_heights.hpp"
#include "kernel/thick/panel_slab.hpp"
#include "kernel/thick/slab_interference.hpp"
#include "kernel/thick/stacking_order.hpp"
#include "kernel/thick/thick_mobility.hpp"

namespace rigidfold {

enum class ThickHinges { kTop, kBottom, kMid, kValley, kBennett };
const char* to_string(ThickHinges hinges);  // "top", "bottom", "mid", "valley", "bennett"

struct ZeroThicknessSamples {
  int drive = -1;                      // driving crease (flat edge index)
  std::vector<double> drive_angles;    // radians, |.| increasing, none 0
  std::vector<Eigen::VectorXd> states; // per flat edge, radians; states[k][drive] == drive_angles[k]
  double max_residual = 0.0;           // largest closure residual of the kept states (radians)
  std::string note;                    // why there are none (empty when there are)
  // The same branch past max_drive, to the end of the zero-thickness path (+-pi where it folds
  // flat), same spacing and checks: thick_report tests them on the thick sheet as they are.
  std::vector<double> further_drive_angles;
  std::vector<Eigen::VectorXd> further_states;
};

// The first branch of trace_motion (default drive and direction - its letter's way; the
// model check picks), `steps` equal steps up to 170 deg, kept while |drive| <= max_drive
// (radians). further_*: the same drive traced again to +-180 deg at the same spacing, its
// states past the last sample, kept only when that trace passes through every sample. reverse: the same drive traced the other way from flat (to -170 deg of the
// letter's way: every crease against its letter on a multiplier family), for designs that
// exist only that way (the Type 3 square twist's Bennett heights). Only states whose
// closure residual is <= 1e-10 are kept.
ZeroThicknessSamples zero_thickness_samples(const CreasePattern& flat, const Topology& topology, int steps = 17,
                                            double max_drive = 1.5707963267948966, bool reverse = false);

struct ThickReportRequest {
  double thickness = 0.0;  // > 0, pattern units
  ThickHinges hinges = ThickHinges::kBennett;
  ZeroThicknessSamples zero;           // may be empty
  double closure_tolerance = 1e-10;    // every reported state closes to this (radians)
  bool check_geometry = true;          // slab interference along the path and stacking at its end
  double interference_margin = 0.0;    // pattern units; 0: 1e-4 x the thinnest slab (slab_interference.hpp)
};

struct ThickTraceStep {
  double drive = 0.0;          // driving crease's fold angle (radians)
  Eigen::VectorXd rho;         // thick fold angles per flat edge (radians)
  double residual = 0.0;       // closure residual ||r||_inf of the sheet there
  double deviation = 0.0;      // max over flat edges of |rho - rho_zero| (radians, wrapped)
  int worst_edge = -1;         // where the deviation is largest
  int dof = -1;                // first-order DOF of the sheet there
};

struct ThickReport {
  double thickness = 0.0;
  ThickHinges hinges = ThickHinges::kBennett;
  std::vector<double> edge_heights;    // per flat edge (pattern units)
  ThickHeightSheet sheet;
  ThickMobilityReport mobility;        // at the flat state
  int drive = -1;
  std::vector<ThickTraceStep> trace;   // empty when DOF 0 or no zero-thickness states
  double max_deviation = 0.0;          // over trace (radians)
  double max_trace_residual = 0.0;     // over trace (radians)
  std::string trace_note;              // why there is no trace or where it ends early

  // Past the trace (only when it reached every sample on the zero-thickness motion,
  // max_deviation <= closure_tolerance): the zero-thickness states past max_drive at which the
  // thick sheet closes as it is (residual <= closure_tolerance, checked here), in order, up to
  // the first that does not - the thick motion continued where it is the zero-thickness one.
  // deviation 0 by construction; dof -1 (not evaluated).
  std::vector<ThickTraceStep> extension;

  // Geometry (request.check_geometry):
  std::vector<PanelSlab> slabs;        // per flat face (thick_slabs.hpp's panel_slabs)
  // Slab interference at the flat state (drive 0), every trace step and every extension
  // state, in that order (slab_interference.hpp).
  SlabInterference interference;
  // The end of the path: the last extension state, else the last trace step, else flat.
  ThickTraceStep end;
  bool end_is_extension = false;
  StackingOrder stacking;              // at `end` (stacking_order.hpp)
};

// The sheet is built from the pattern's xy (hinge heights become z), so a folded form would be
// read as its projection: every vertex must lie on z = 0 (within 1e-12 of the pattern's
// diagonal). Throws InputError(place "pattern") naming the first vertex off it.
void require_flat_pattern(const CreasePattern& flat);

ThickReport thick_report(const CreasePattern& flat, const Topology& topology, const ThickReportRequest& request);

// The thick state with the driving crease at `drive` (radians), on the traced thick motion:
// Newton projection (drive held) from the linear interpolation of the two trace steps (or
// flat and the first step) that bracket it. drive must lie between 0 and the last traced
// driving angle, same sign. The returned step has passed residual <= closure_tolerance.
// Throws InputError(place "at") for a drive outside the traced range or no trace;
// NoAnswerError when Newton does not reach it within the tolerance.
ThickTraceStep thick_state_at(const ThickReport& report, double drive, double closure_tolerance = 1e-10);

}  // namespace rigidfold
