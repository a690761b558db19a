#pragma once
// The tolerances of a foldability verdict and of a traced motion, in one place. Every solver
// option that decides a verdict takes its default from here, check_foldability passes the
// caller's values down, and the report (and its JSON) states the values it used.
//
// Units: radians for angles and closure residuals (||r||_inf of the per-vertex log R_v);
// placement mismatch relative to the pattern's size; rank cut relative to the largest
// singular value (dense) or column norm (SPQR).
#include <numbers>

namespace rigidfold {

struct Tolerances {
  // A point is on the configuration manifold when ||r||_inf <= residual (Newton stop).
  double residual = 1e-12;
  // A traced branch certifies a fold when its largest residual is at most this.
  double certificate_residual = 1e-10;
  // First-order DOF: singular values below rank_cut x the largest are dropped.
  double rank_cut = 1e-9;
  // The same at a located singular point (tangent cones): larger, because a bifurcation is
  // located only to ~1e-10 and the singular value that vanishes there is that small, not 0.
  double cone_rank_cut = 1e-8;
  // |rho| at most this counts as flat: no sign, so never against its letter.
  double sign_threshold = 1e-10;
  // A crease past pi - fold_limit_margin ends a traced branch (local facet interference);
  // the end itself is then solved with that crease held at +-pi (fold_limit_end.hpp).
  double fold_limit_margin = 1e-3;
  // |rho| >= pi - at_fold_limit counts as a crease AT 180 deg (trace events, the end solve's
  // acceptance).
  double at_fold_limit = 1e-9;
  // Face placement of a certificate: relative closure mismatch at most this.
  double placement_mismatch = 1e-10;
  // A least closure residual below this is no evidence that a pattern cannot fold: a search
  // that ends there stopped near its own floor (the general verdict answers "undecided").
  double evidence_floor = 1e-9;
  // Multiplier model: Kawasaki test of applicability (rad) and relative loop-gain defect
  // taken as 1.
  double flat_kawasaki = 1e-9;
  double loop_gain = 1e-9;

  // |rho| at which a traced branch stops (pi - fold_limit_margin).
  constexpr double fold_limit() const { return std::numbers::pi - fold_limit_margin; }
};

// The defaults every option struct starts from.
inline constexpr Tolerances kDefaultTolerances{};

}  // namespace rigidfold
