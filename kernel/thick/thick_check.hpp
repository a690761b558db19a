#pragma once
// `rigidfold check` and `rigidfold trace` on a thick FOLD: the file that
// `rigidfold thick --out` writes - the thick sheet of thick_sheet_from_hinge_heights at its flat
// state (vertices truncated into holes, hinge edges at their heights, 3D) with the extension keys
//   "rigidfold:thickness":     one number per face (> 0, file units), its panel's slab thickness;
//   "rigidfold:hinge_heights": one entry per edge: the hinge height (file units) of edges
//                              0..H-1 (the flat pattern's edges), null for the cut edges after them.
// is answered with the thick model: the sheet's ClosureSystem with every hole closed in SE(3)
// (one loop per thick vertex), its first-order DOF at the flat state (thick_mobility), and the
// thick motion traced from flat (see Verdict).
// One decision for both commands, here; the app only prints.
//
// Inputs: a pattern as read (complete_and_validate'd) and its topology; ThickCheckRequest.
// Checks on the extension (InputError whose place is the JSON path, e.g.
// "rigidfold:hinge_heights[7]"): both keys present when one is; arrays of the right length;
// thickness finite and > 0; heights finite numbers for a prefix 0..H-1 (H >= 1) and null after;
// each hinge edge's two ends at z = its height (within 1e-9 of the pattern's diagonal: the sheet
// is at its flat state); at least one hole (a thick vertex). Request: drive must be a hinge edge
// (place "drive"), |to| in (0, pi] (place "to"), steps in 1..1000 (place "steps").
//
// Verdict (ThickCheckReport::verdict):
//   "rigid":     DOF 0 at the flat state - the closure map is injective to first order there,
//                so the flat state is an isolated solution (a proof, at the stated rank cut);
//   "mobile":    the drive reached the target, every landed step closing to closure_tolerance
//                (the sheet is a mechanism; where the motion ends with hinges against their
//                letters the reason says that a letter-keeping motion is not decided)
//                (a certificate). From a regular flat state (DOF 1): 1-DOF pseudo-arclength
//                continuation. From a singular one (DOF > 1 to first order, e.g. the flat state of
//                Bricard loops, where first order is inconclusive): projected driving - the drive
//                held at 8 sub-steps per step, the rest Newton-projected from a secant
//                predictor, each M hinge kept <= 0 and V hinge >= 0 (projected Gauss-Newton:
//                the letters pick the branch); a sub-step moving any hinge by > 0.25 rad counts as a jump and ends
//                the trace. Each step's first-order DOF is reported (ThickCheckStep::dof);
//   "undecided": the trace stopped before the target (Newton failed, a jump, a fold limit, a
//                hinge at +-pi, continuation failed; trace_note says which) or the drive does
//                not move to first order - the steps reached are still reported.
// Cost: one rank of the flat Jacobian, one rank per hole, one rank per landed step, and at most
// max_points continuation points (each a dense SVD up to 2000 unknowns) or 8 Newton
// projections per step.
//
// Units: angles in radians (fold angles from the flat state, FOLD sign); lengths in the
// pattern's internal units (to_file_units to print).
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "kernel/analysis/foldability_class.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/thick_mobility.hpp"

namespace rigidfold {

// True when the pattern carries either thick extension key (then thick_check must answer).
bool is_thick_fold(const CreasePattern& pattern);

// The extension checked as thick_check checks it first (throws InputError naming the JSON path,
// e.g. "rigidfold:hinge_heights[3]"); returns the number of hinge edges. Cheap: no solve (the
// FOLD reader's fuzz target runs it on every input that carries the keys).
int thick_extension_hinges(const CreasePattern& pattern);

struct ThickCheckRequest {
  std::optional<int> drive;            // hinge edge; default: the hinge that moves most in the flat state's null space
  std::optional<double> to;            // target drive angle (radians, 0 < |to| <= pi); default 170 deg, towards the drive's letter (V: +, M: -, else +)
  int steps = 17;                      // landed steps at to * k / steps, k = 1..steps
  double closure_tolerance = 1e-10;    // every reported step closes to this (radians)
  int max_points = 2000;               // continuation points at most
  // Places of InputError for the request's own fields (a CLI passes its flag names).
  std::string drive_place = "drive", to_place = "to", steps_place = "steps";
};

struct ThickCheckStep {
  double drive = 0.0;          // driving hinge's fold angle (radians)
  Eigen::VectorXd rho;         // fold angle of every hinge (edges 0..H-1, radians from flat)
  double residual = 0.0;       // ||r||_inf of the sheet's closure there
  int dof = -1;                // first-order DOF there (jacobian_rank, relative cut 1e-9)
};

struct ThickCheckReport {
  int hinges = 0;                      // H: edges carrying a height
  int cut_edges = 0;                   // edges after them (boundaries of the truncated vertices)
  int holes = 0;                       // SE(3) loops (thick vertices)
  double min_thickness = 0.0, max_thickness = 0.0;  // over faces (pattern units)
  ThickMobilityReport mobility;        // at the flat state
  std::string verdict;                 // "rigid", "mobile", "undecided" (as a mechanism)
  // The shared verdict vocabulary (foldability_class.hpp), the headline: rigid is "not foldable
  // (proof)"; mobile is "foldable" only when no lettered hinge ends against its letter, and
  // "undecided" otherwise (a letter-keeping motion is neither found nor ruled out).
  FoldabilityClass verdict_class = FoldabilityClass::kUndecided;
  std::string reason;
  int drive = -1;
  double target = 0.0;                 // radians
  std::vector<ThickCheckStep> steps;   // landed steps reached, in order
  int continuation_points = 0;        // continuation points, or Newton projections (projected driving)
  double max_residual = 0.0;           // over steps
  std::string trace_note;              // where and why the trace ended early (empty if it reached the target)
  // M/V hinges folded against their letter (|rho| > 1e-9 with the wrong sign) at the last step
  // reached (0 if none): the thick model's motion does not use the letters except to pick the
  // branch at a singular flat state, so a traced branch may go against them.
  int letter_disagreements = 0;
};

ThickCheckReport thick_check(const CreasePattern& pattern, const Topology& topology, const ThickCheckRequest& request = {});

// The report as JSON ("model": "thick", lengths in file units, angles in degrees where the key
// ends in _deg) and as text lines, for both commands.
nlohmann::ordered_json thick_check_json(const CreasePattern& pattern, const ThickCheckReport& report, bool with_steps);
std::string thick_check_text(const CreasePattern& pattern, const ThickCheckReport& report, bool with_steps);

}  // namespace rigidfold
