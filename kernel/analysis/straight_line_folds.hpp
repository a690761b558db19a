#pragma once
// Straight crease lines: the structural part of a verdict (evidence for every no;
// strict and weak foldability).
//
// A STRAIGHT LINE is a chain of hinge creases that continues through each interior vertex it
// meets along an opposite crease (the sectors on either side of the line sum to pi there).
// Two facts about them are exact, not numerical:
//
//  1. A line that runs from a boundary vertex to a boundary vertex through interior vertices
//     only is a cross-cut of its (disk) component: it splits the sheet into two pieces, and
//     turning one piece about the line is a rigid folding motion with every other crease
//     flat, from flat to +-180 deg. If the letters allow it (all creases of the line V and U,
//     or all M and U) it is a certificate of WEAK foldability: some lettered creases stay
//     flat. The certificate is checked, not assumed: the closure residual of every interior
//     vertex is evaluated along the motion and must stay within
//     tolerances.certificate_residual (it is exactly 0 for an exactly straight line; the
//     collinearity test below admits rounding, the residual check bounds its effect).
//  2. At an interior vertex of degree 4 where two straight lines cross (sectors
//     a, pi - a, a, pi - a), every rigid motion from flat folds one line with the other flat
//     until a crease reaches +-180 deg (the flat-foldable degree-4 vertex with fold-angle
//     multipliers 0 and infinity). So no motion from flat folds all four creases: STRICT
//     foldability (every lettered crease folds) is impossible when the four are lettered
//     M/V - a proof, reported as the strict obstruction.
//
// Units: radians. Cost O(creases x line length).
#include <Eigen/Core>
#include <vector>

#include "kernel/analysis/tolerances.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// A boundary-to-boundary straight line that folds alone.
struct StraightLineFold {
  std::vector<int> creases;   // edges of the line, from one boundary vertex to the other
  std::vector<int> vertices;  // its vertices in order (first and last on the boundary)
  int sign = 0;               // +1: folds as a valley, -1: as a mountain, 0: either (letters ignored or all U)
  double max_residual = 0.0;  // largest vertex closure residual along the checked motion (radians)
  // Per-edge fold angles at the checked samples of the motion: the line at
  // sign' x (fold_limit x k / samples), k = 1..samples, sign' = sign or +1 (radians).
  std::vector<Eigen::VectorXd> path;
};

struct StraightLineAnalysis {
  // Lines that fold alone with their letters kept (or letters ignored) and a residual within
  // tolerances.certificate_residual, longest first (at most max_reported).
  std::vector<StraightLineFold> folds;
  int lines_found = 0;             // boundary-to-boundary lines, before letters and residual
  // Interior degree-4 vertices where two straight lines of foldable creases cross.
  std::vector<int> crossing_vertices;
  // Those of them whose four creases are lettered M/V (with letters used; all of them when
  // letters are ignored): no strict motion.
  std::vector<int> strict_obstruction_vertices;
};

struct StraightLineOptions {
  bool use_assignment = true;
  Tolerances tolerances = kDefaultTolerances;  // flat_kawasaki: collinearity; certificate_residual; fold_limit()
  int samples = 16;       // points of the motion checked per line
  int max_reported = 8;   // lines kept in folds
};

StraightLineAnalysis straight_line_folds(const CreasePattern& pattern, const Topology& topology,
                                         const StraightLineOptions& options = {});

}  // namespace rigidfold
