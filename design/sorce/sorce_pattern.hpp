#pragma once
// SORCE joints for a whole crease pattern (seed 002, digest sections 1, 4).
//
// Input: a flat crease pattern (FOLD, faces counter-clockwise seen from +z), a folding path
// traced by the kernel's general solver (kernel/analysis/trace_motion.hpp) and splined per
// crease (sorce_path_spline.hpp: t = drive / final drive), panel thicknesses and per-face
// offsets z_f(t) along each face's own normal (+z at t = 0).
//
// Per hinge crease e (two faces), its fold frame in reference coordinates: origin v0,
//   z = (v1 - v0)/|v1 - v0| (the fold line), y = +z of the pattern (both faces' normal at t = 0),
//   x = y cross z, pointing into the face on the LEFT of v0 -> v1.
// That face is the SORCE right panel (it turns by +gamma toward +y: a FOLD valley, rho > 0,
// lifts the face on the left of v0 -> v1), the face on the right of v0 -> v1 the SORCE left
// panel, and gamma_e(t) = rho_e(t) (the spline), z_left/z_right the two faces' offsets (each
// face's local normal is the frame's y at t = 0, so no sign changes).
//
// End offsets z_f(1): given, or derived by the stacking rule of the digest (section 1, sign
// law): for every folding crease, with sigma_e = sign(gamma_e(1)),
//   sigma_e * (-(z_left(1) + z_right(1))) >= (h_left + h_right) / 2,
// and z_left(1) = z_right(1) for a hinge that does not fold on the path (it stays flat);
// among these, the offsets of least sum of squares (a small convex QP: NLopt SLSQP, then the
// active constraints solved exactly by a minimum-norm least-squares step, so that the stacking
// holds to round-off). On the seed's degree-4 vertex this gives eq 4 (-3h/2, h/2, h/2, -3h/2).
// Only creases are constrained: faces that overlap at t = 1 without sharing a crease are not
// ordered (see the interference check). If the path does not end flat-folded (|gamma(1)| < pi),
// the same rule defines the end values and the joints work over the traced range only.
// Offsets in t: linear z_f(t) = z_f(1) t, or z_f(1) (t + sum_j b_j B_j(t)) with the seed's
// bases (eq 37, sorce_function.hpp) when coefficients are given.
//
// Poses: P_f(t) = M_f(t) Trans(z_f(t) n_f), M_f the zero-thickness placement (place_faces) of
// the spline's fold angles at t.
//
// Units: lengths the pattern's units, angles radians, t dimensionless.
#include <Eigen/Geometry>
#include <optional>
#include <utility>
#include <vector>

#include "design/sorce/sorce_fold_report.hpp"
#include "design/sorce/sorce_path_spline.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold::sorce {

struct PatternSorceRequest {
  // The path: this branch if given (traced on this pattern), else trace_motion(pattern, trace)
  // with trace.force_general set (the general solver), its branch 0. For a flat-folded end set
  // trace.to = +-pi (the trace's default is 170 deg); the solver then stops a few 1e-6 rad short
  // of pi on patterns whose creases all reach pi together (Miura), exactly at pi on one vertex.
  std::optional<MotionBranch> branch;
  TraceRequest trace;
  // The path's parameter t (sorce_path_spline.hpp). The offsets z_f(t) are functions of it, so
  // it decides which offsets the linear and basis families (and the optimiser) can reach. For
  // optimising vertex A's offsets kHalfTangent is the better one (it is the seed's eq 35: the
  // seed's eq 39 coefficients give its FOM 55.3 there, 419 on kDrive; COBYLA from them reaches
  // 21.0 against 79.5 on kDrive and nothing feasible on kArcLength;
  // tests/sorce/sorce_path_parameter_test.cpp). The default stays kDrive: kHalfTangent is not
  // defined on every path (a crease that turns back or ends flat), and the existing designs' and
  // tests' offsets (linear z = z(1) t included) are functions of the drive parameter: another
  // default would silently change every joint already designed.
  PathParameter path_parameter = PathParameter::kDrive;
  double thickness = 0.0;               // every panel (> 0) unless face_thickness is given
  std::vector<double> face_thickness;   // empty, or one per face (> 0)
  std::vector<double> end_offsets;      // empty (derived, see above), or z_f(1) per face
  std::vector<std::vector<double>> offset_coefficients;  // empty (linear), or b per face (<= 3 each)
  // Hinge creases forced to circular CORE joints (seed section 3, eq 2): both faces of each get
  // z = -(h/2) tan(gamma_e(t)/4), overriding end_offsets and coefficients there, so the crease's
  // profiles are arcs of radius h/2. A face on two listed creases needs their gamma equal along
  // the path (1e-9 rad at the check samples) and both faces of a crease the same thickness.
  std::vector<int> circular_edges;
  // Split creases (seed section 10): crease `edge`'s right panel is shifted, in the crease's
  // normal plane, by d_e(t) = d(t) u(gamma_e(t)/2) (left panel's frame; eqs 58, 59, 68: along
  // the fold's half-angle direction), d(0) = 0, so its profiles are eqs 56/57. Two collinear
  // creases through a vertex split with one d are the seed's collinear split (sorce_vertex.hpp,
  // collinear_split). The poses then follow the joints from face 0 (its place_faces pose) across
  // a spanning tree of the hinges, so the consistency check (a) measures the closure of the
  // other hinges and the vertex closure (b) includes the split offsets. The derived end offsets
  // (stacking rule) do not see d; the fold reports' stacking does (end_separation adds d_y(1)).
  struct Split {
    int edge = -1;
    ScalarFunction d;  // length, d(0) = 0
  };
  std::vector<Split> splits;
  std::vector<double> pose_times;       // t of the pose table; empty: 0, 0.1, .., 1
  int check_samples = 21;               // evenly spaced t for pitch, spline closure gap, interference (>= 2)
  bool check_interference = true;
  ReportOptions report;
};

struct CreaseJoint {
  int edge = -1;
  int left_face = -1, right_face = -1;  // SORCE left / right panel (right: left of v0 -> v1)
  Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();  // fold frame (above), reference coordinates
  FoldMotion motion;
  FoldReport report;
  // false: |rho| <= 1e-9 all along the path (no joint, no report; its faces get equal offsets).
  // A crease that folds but ends at exactly 0 is treated the same way by the stacking rule.
  bool folds = true;
  // Verification figures of this crease (see PatternChecks).
  double consistency = 0.0, pitch = 0.0, contact = 0.0;
  // Forward rolling (sorce_rolling.hpp) at the check samples: the profiles rolled on each other
  // by matched arc length give back gamma (radians) and the right panel's translation (length);
  // not run (NaN) where the report finds a cusp or a t with gamma' = 0; a pivot at t = 1 is left
  // out of the comparison (its tangent is a limit the spline path blurs; sorce_pattern.cpp).
  double rolled_gamma = 0.0, rolled_translation = 0.0;
};

struct FaceOffset {
  ScalarFunction z;         // z_f(t) along the face's own normal
  double end_value = 0.0;   // z_f(1)
  double thickness = 0.0;
};

struct SlabInterference {
  double t = 0.0;
  std::vector<std::pair<int, int>> face_pairs;  // a < b
};

// Verification (relative figures: translations divided by the pattern's bounding-box diagonal).
struct PatternChecks {
  // (a) max over creases and the path's knots of |P_left^-1 P_right - F T_e F^-1| (4x4 entries),
  // T_e = Trans(-z_l y) Rz(gamma) Trans(z_r y) the planar motion mapped into 3D. At the knots the
  // spline equals the solver's samples, so this is the solver's closure (place_faces mismatch).
  double consistency = 0.0;
  // Screw pitch |omega . v| / |omega|^2 of each crease's 3D relative motion over the check samples
  // (relative to the pattern size; 0 for a motion in the fold's normal plane).
  double pitch = 0.0;
  // (b) max over interior vertices of |prod T - I| around the vertex: at the knots, and midway
  // between consecutive knots (the spline's own closure gap, O(spline error)).
  double closure_knots = 0.0, closure_samples = 0.0;
  // (c) max distance (length units) between the two faces' 3D images of s_l(t), s_r(t), at the knots.
  double contact = 0.0;
  // Largest rolling/contact residual of the folds' reports (length units).
  double rolling = 0.0, contact_planar = 0.0;
  // Forward rolling over the creases where it runs, and the folding creases where it does not.
  double rolled_gamma = 0.0, rolled_translation = 0.0;
  std::vector<int> not_rolled;
  // (d) every folding crease ends at |gamma(1)| = pi (1e-12) and, if so, whether all stack.
  bool flat_folded_end = false;
  bool all_stack = false;
  // Whether or not the path ends flat: end_gap = max over folding creases of pi - |gamma_e(1)|
  // (radians; the general solver stops a flat fold a little short of pi), and the stacking
  // margin of the end offsets, min over folding creases of
  //   sign(gamma_e(1)) (-(z_l(1) + z_r(1))) - (h_l + h_r)/2   (>= 0: every crease stacks at pi).
  double end_gap = 0.0;
  double stacking_margin = 0.0;
  // (e) slab pairs that intersect at the check samples (empty when not checked). Each slab is
  // the face extruded to +-h/2 about its offset mid-plane, cut back from each hinge edge by
  // that joint's cam extent (max lateral |s_x| of its profiles plus (h_l + h_r)/2), so the
  // rolling contact and the cams' own sweep are not counted; slabs touching face to face
  // (stacked layers) are shrunk by 1e-9 h in thickness so that contact is not interference.
  // Non-convex faces are skipped (listed).
  std::vector<SlabInterference> interference;
  std::vector<int> skipped_faces;
};

struct PatternSorce {
  PathSpline path;
  std::vector<CreaseJoint> creases;  // hinge creases, by edge index
  std::vector<FaceOffset> faces;     // per face
  std::vector<double> pose_times;
  std::vector<std::vector<Eigen::Isometry3d>> poses;  // poses[i][f] = P_f(pose_times[i])
  PatternChecks checks;
};

// Throws InputError: "pattern" (not flat, or without hinges), "thickness", "face_thickness[f]",
// "end_offsets[f]", "offset_coefficients[f]", "circular_edges[k]", "splits[k]" (not a hinge crease, given twice,
// no d, d(0) != 0), "pose_times[i]", "check_samples", "branch" (path
// not traced / too short), and the trace's own places ("drive", "to").
PatternSorce pattern_sorce(const CreasePattern& pattern, const PatternSorceRequest& request);

// Every face's pose P_f(t) = M_f(t) Trans(z_f(t) n_f) on the pattern's path at any t in [0, 1]
// (the pose table's formula; t outside is clamped by the spline). `topology` of `pattern`.
std::vector<Eigen::Isometry3d> panel_poses(const CreasePattern& pattern, const Topology& topology, const PatternSorce& sorce,
                                           double t);

// The derived end offsets alone (rule above): sigma per edge (sign of gamma_e(1), 0: does not
// fold), per-face thickness. Throws InputError("end_offsets") if the QP is infeasible.
std::vector<double> stacking_end_offsets(const CreasePattern& pattern, const Topology& topology,
                                         const std::vector<int>& fold_sign, const std::vector<double>& thickness);

}  // namespace rigidfold::sorce
