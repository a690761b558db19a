#pragma once
// add_creases: where to add creases so that a pattern folds rigidly with its letters (seed 001
// §5 leaves it to future study; docs/cli/repair.md, "--add-creases").
//
// Candidates: the diagonals of the pattern's faces (every pair of corners of a face that are
// not neighbours on it), each with the letter M or V. The search goes by count, smallest
// first: every single candidate, then (if none folds) every pair of candidates in different
// faces, up to max_added creases; it stops at the first count where some addition folds, so
// every answer has the fewest creases found to suffice. Each addition is a new pattern (the
// face split in two along the crease) judged from scratch by check_foldability with its
// letters: an answer is one whose check says "foldable", with its certificate and DOF.
// Ranked: most DOF first, then candidate order.
//
// A search that finds nothing says "undecided" (nothing up to max_added creases, or the
// budget ran out), not "no": a crease between new points, or more creases, might still do.
// Cost: 2 D checks for the singles (D diagonals), 2 D (D - 1) for the pairs.
#include <string>
#include <vector>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct CreaseAdditionOptions {
  int max_added = 2;          // largest number of creases added together (1 or 2)
  long max_checks = 5000;     // then the search stops and says so
  int max_results = 10;       // answers kept
  // For every check (letters used). The branch explorer is off by default: on the candidates
  // it costs ~70x the check (4.5 s against 0.06 s on a square twist with its diagonal, ASan
  // build) and does not change a "foldable" the search certifies; a candidate that only the
  // explorer would certify is missed (set check.explore_branches to include them).
  FoldabilityOptions check = [] {
    FoldabilityOptions o;
    o.explore_branches = false;
    return o;
  }();

  // False, with the reason, when max_added is not 1 or 2, or max_checks or max_results < 1.
  bool IsValid(std::string* error) const;
};

struct AddedCrease {
  int v0 = -1, v1 = -1;       // the crease joins these vertices of the input
  int face = -1;              // across this face of the input
  Assignment letter = Assignment::Mountain;
};

struct CreaseAddition {
  std::vector<AddedCrease> creases;
  CreasePattern pattern;      // the input with the creases added (edges appended in order)
  FoldabilityReport check;    // its check: foldable
};

struct CreaseAdditionSummary {
  FoldabilityReport before;   // the input's check
  bool already_foldable = false;
  int candidates = 0;         // face diagonals (each tried with M and with V)
  long checks = 0;
  int searched_up_to = 0;     // the largest count searched in full
  bool budget_exhausted = false;
  std::vector<CreaseAddition> found;  // ranked; empty when nothing was found
  std::string message;        // one line for the user
  double seconds = 0.0;
};

// Throws InputError for invalid options. A candidate whose pattern is invalid (a diagonal
// of a non-convex face that leaves it) is skipped.
CreaseAdditionSummary add_creases(const CreasePattern& pattern, const Topology& topology,
                                  const CreaseAdditionOptions& options = {});

}  // namespace rigidfold
