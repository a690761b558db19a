#pragma once
// Every folding branch of a 1-DOF-per-branch pattern, from the flat state through its
// bifurcations (docs/DESIGN.md, "Bifurcation").
//
// Method (points and branches form a graph):
//   1. The flat state x = 0 is the first point. Its tangent cone (tangent_cone.hpp: kernel
//      of J filtered by the second-order conditions) gives the tangent lines; each line is
//      left on both sides (leave_singular_point) and traced by 1-DOF pseudo-arclength
//      continuation (continue_one_dof).
//   2. Along a branch, at every accepted point, the bordered determinant
//      det[U_prev^T J(x); t^T] is compared with the previous point's; a sign change is a
//      bifurcation, located by locate_singular_point (a march to
//      `locate_tolerance` in the path parameter, then Newton on the extended system, with an
//      error bound) and added as a point (or matched with a known one). Its
//      tangent cone gives new departures: every line, both sides, except directions already
//      used by a branch at that point (the way we came in, and branches traced before).
//   3. A branch stops at: a bifurcation (kBifurcation); a crease reaching +-fold_limit()
//      (kFoldLimit: local facet interference if the others are not at 0 or +-pi, the fully
//      folded state if they all are). The exact point where that crease is at +-pi is then
//      solved for (solve_fold_limit_end) and added as a point of kind kInterference or
//      kFullyFolded (it replaces the branch's last point, which passed the limit); departures
//      are taken from a fully folded point too, but only those
//      that fold back (no crease beyond pi). Other stops: kKnownPoint, kContinuationFailed
//      ("step too small", "not 1 DOF"), kMaxPoints, kDepartureFailed.
//   4. Along each branch (PathWatch, path_watch.hpp, first segment skipped: it leaves a
//      singular point): sign switches of creases, with the branch's driving crease value at
//      the crossing; whether the pattern's M/V letters hold over the whole branch (zero
//      counts as either sign); global facet interference (facet_interference.hpp).
// The exploration is breadth-first and bounded (max_branches).
//
// Units: radians inside; per-edge fold angles with the FOLD sign (valley > 0).
// Limits: dense linear algebra at every point (SVD of J): meant for patterns up to
//   max_unknowns free creases (a few hundred); multi-DOF branches are reported, not traced;
//   sheets with holes are rejected (ClosureSystem throws).
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "kernel/analysis/progress.hpp"
#include "kernel/analysis/tolerances.hpp"
#include "kernel/analysis/traced_branch.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/tangent_cone.hpp"

namespace rigidfold {

struct BranchExplorerOptions {
  double departure_step = 2e-3;       // distance from a point to the first branch point (radians)
  // fold_limit() ends a branch, sign_threshold (|rho| at most this has no sign), rank_cut
  // (DOF of a branch not traced) and cone_rank_cut (tangent cones) come from here.
  Tolerances tolerances = kDefaultTolerances;
  double locate_tolerance = 1e-10;    // stop of the march that starts the bifurcation solve (radians)
  double same_point = 1e-6;           // |x - y|_inf below this: the same point
  double same_direction = 0.995;      // cosine above this: the same departure direction
  int max_branches = 64;
  int max_points_per_branch = 3000;
  // Work budget: each traced point and each branch point's tangent cone costs a dense
  // factorisation of the closure Jacobian, counted as rows x unknowns^2; the exploration stops
  // (branches end with kMaxPoints, BranchExploration::budget_exhausted) when the sum passes
  // this. Deterministic, unlike a time limit. The bundled and corpus patterns the explorer
  // finishes on spend <= 4e6 (square twist Type 2M: 1206 points); Origami Simulator's
  // triangulated hypar (280 creases, 2e7 a point) would trace 1000+ points in 37 s, and stops
  // after 8 (1.5 s with its flat tangent cone; 2-core VM).
  double max_dense_work = 1.5e8;
  int max_unknowns = 400;             // larger patterns: not applicable (dense SVDs)
  bool check_global_interference = true;  // faces placed and tested (facet_interference.hpp) at every point
  // Corrector stop 5e-13 (inf-norm) so that every vertex's |log R_v| (a 2-norm, up to sqrt(3)
  // times larger) stays <= 1e-12 rad, the quality bar.
  ContinuationOptions continuation = [] {
    ContinuationOptions c;
    c.tolerance = 5e-13;
    return c;
  }();
  TangentConeOptions cone;           // its rank_tolerance is replaced by tolerances.cone_rank_cut
  ProgressSink progress;             // each point of each branch
};

struct BranchPoint {
  PointKind kind = PointKind::kFlat;
  Eigen::VectorXd angles;             // per-edge fold angles (radians)
  int parameter_edge = -1;            // the edge whose fold angle is reported as the path parameter:
                                      // the arriving branch's driving crease, or the crease held at +-pi
  double parameter = 0.0;             // its fold angle there (radians)
  double location_error_bound = 0.0;  // bifurcation: verified bound on |x - x*|_2 over the unknowns
                                      // (radians; so on every fold angle), bifurcation.hpp
  double residual = 0.0;              // ||r||_inf there
  double sigma_second_smallest = 0.0; // independent check of a bifurcation: ~0 (kernel dimension >= 2)
  double sigma_max = 0.0;
  int kernel_dimension = 0;           // first-order DOF there
  int tangent_lines = 0;              // second-order cone lines there
  int stop_crease = -1;               // "interference" / "fully folded": the crease held at +-pi
};

struct BranchExploration {
  bool applicable = false;
  std::string why_not;                // when not applicable
  int num_unknowns = 0;
  std::vector<BranchPoint> points;    // points[0] is the flat state
  std::vector<TracedBranch> branches;  // from_point / to_point index `points`
  double seconds = 0.0;
  bool budget_exhausted = false;      // stopped by max_dense_work (departures left untraced)
  double dense_work = 0.0;            // spent, in max_dense_work's units
};

// Inputs: a validated flat pattern and its topology.
BranchExploration explore_branches(const CreasePattern& pattern, const Topology& topology,
                                   const BranchExplorerOptions& options = {});

}  // namespace rigidfold
