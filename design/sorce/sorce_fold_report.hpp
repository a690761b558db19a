#pragma once
// Per-fold diagnostics of a SORCE profile pair (seed 002 section 6, digest section 4):
// s0, end points, arc lengths, convexities and their concave spans, cusps, ill-behaved t,
// end-point pivots, protrusion beyond the slab faces, and the built-in rolling/contact
// residuals; and the figure of merit over a set of folds (eqs 34, 38).
//
// Sampling: `samples` evenly spaced t in [0, 1] (both ends included, evaluated exactly: the
// profile forms carry analytic derivatives). Extremes and sign changes found between samples
// are refined: maxima/minima by Brent, convexity and gamma' roots by TOMS 748. Features
// narrower than the sample spacing can be missed; the tests size `samples` for their cases.
// Units: lengths the caller's unit, convexity 1/length, t dimensionless.
#include <vector>

#include "design/sorce/sorce_profile.hpp"

namespace rigidfold::sorce {

struct ReportOptions {
  int samples = 2001;  // >= 3
  // A cusp or pivot is where the profile speed |s'(t)| falls to speed_tolerance times its
  // largest sampled value (relative; |s_l'| = |s_r'| by rolling).
  double speed_tolerance = 1e-6;
  // A local minimum of |s'| is also a cusp when the profile's radius of curvature there is
  // at most cusp_radius times the largest |s'| (a length: |s'| is the contact point's speed
  // per unit t, t in [0, 1]): a hairpin of negligible radius, e.g. a cusp the data blur
  // into a tiny turn (eq 60, fold 3: radius ~1e-8 against a profile of length 0.15).
  double cusp_radius = 1e-4;
};

struct Span {
  double begin = 0.0, end = 0.0;  // t
};

struct FoldReport {
  double s0 = 0.0;  // eq 20
  FoldEndPoints ends;
  // Arc lengths over t in [0, 1] (adaptive Gauss-Kronrod, relative error 1e-12); equal when
  // the pair rolls without slip (NaN when the fold is ill-behaved somewhere).
  double arc_length_left = 0.0, arc_length_right = 0.0;
  // Extremes of the convexities over the samples (+-infinity at pivots and cusps).
  double min_convexity_left = 0.0, max_convexity_left = 0.0;
  double min_convexity_right = 0.0, max_convexity_right = 0.0;
  std::vector<Span> concave_left, concave_right;  // where c < 0
  // Interior cusps: t of a local minimum of |s'| at or below the speed tolerance or with a
  // radius of curvature at or below the cusp radius (ReportOptions).
  std::vector<double> cusps;
  double min_turn_radius = 0.0;  // smallest radius of curvature at interior |s'| minima (inf: none)
  std::vector<double> ill_behaved;  // gamma'(t) = 0 while some offset derivative is not
  std::vector<double> stationary;   // gamma'(t) = 0 with every offset derivative 0 (a limit may exist)
  bool pivot_at_start = false, pivot_at_end = false;  // |s'| -> 0 at t = 0 / t = 1
  double min_speed = 0.0, max_speed = 0.0;            // |s'(t)| over the samples
  // Largest distance of a profile beyond its own panel's slab faces (0: inside; only when the
  // motion's thickness is > 0). A positive value means the mate needs a clearance hole.
  double protrusion_left = 0.0, protrusion_right = 0.0;
  double max_rolling_residual = 0.0, max_contact_residual = 0.0;  // over the samples
  // Stacking at t = 1 (only when gamma(1) = +-pi): the right panel's mid-plane height in the
  // left panel's own coordinates, -(z_l(1) + z_r(1)) + d_y(1) (digest section 1, sign law).
  // `stacks`: on the fold's side (> 0 valley, < 0 mountain) and at least (h_l + h_r)/2 away
  // (within 1e-12), so the two slabs lie flat on each other or with layers between.
  double end_separation = 0.0;
  bool stacks = false;
};

// Throws InputError("samples") if samples < 3; passes on profile/end-point errors.
FoldReport fold_report(const FoldMotion& motion, const ReportOptions& options = {});

// eq 38 (eq 34 with epsilon = 0): max over folds and t of {c_l, c_r} divided by
// max(epsilon, min over folds and t of {c_l, c_r}); +infinity when a convexity diverges or
// the denominator is 0. epsilon >= 0.
double figure_of_merit(const std::vector<FoldReport>& folds, double epsilon);

}  // namespace rigidfold::sorce
