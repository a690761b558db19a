#pragma once
// Mountain-valley assignment enumeration (seed 003 §3.2-3.3): every
// assignment of a flat crease pattern's creases that folds each interior vertex flat
// (kernel/pattern/vertex_letter_rules.hpp: Maekawa and big-little-big via the crimp
// reduction; Kawasaki is the geometry's), grouped into classes under the pattern's symmetry
// group (kernel/pattern/pattern_symmetry.hpp, computed from the coordinates) and the global
// M <-> V flip, each class with its rigid-foldability verdict and DOF from the kernel's front
// door (check_foldability with the class's letters: multiplier propagation, exact, for
// flat-foldable degree-4 patterns; the general model otherwise).
//
// Creases are the edges whose letter is M, V or U; F, J, B and C edges keep theirs. The
// search is a backtracking over the interior vertices in breadth-first order (each vertex's
// flat-folding letter sets filtered by the creases already set), then over the creases that
// touch no interior vertex. Each assignment found is kept as a class representative iff it is
// the lexicographically smallest of its orbit (letters in crease order, M < V), so every class
// is met exactly once and the orbit sizes sum to the count (checked).
// Units: radians (sector tolerance).
#include <string>
#include <vector>

#include "kernel/analysis/foldability_report.hpp"
#include "kernel/analysis/progress.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct AssignmentEnumerationOptions {
  double sector_tolerance = 1e-9;   // Kawasaki and equal-sector test (radians)
  long max_assignments = 50'000'000;  // stop the search after this many (then `complete` is false)
  long max_search_steps = 500'000'000;  // vertex visits of the backtracking at most (dead ends too)
  long max_verdicts = 100'000;      // classes given a verdict at most (the rest counted only)
  int max_listed = 1000;            // classes kept with their letters in `classes`
  bool symmetry = true;             // false: classes under the global flip only
  // One subtree of the search (assignment_search_branches lists them): at the k-th vertex of the
  // search order, only its branch[k]-th flat-folding letter set. Empty: the whole search. The
  // subtrees of one depth split the search without overlap, in its order: their classes, joined
  // in branch order, are the whole search's (each class lies in the subtree of its representative).
  std::vector<int> branch;
  ProgressSink progress;
};

struct AssignmentClass {
  std::string letters;   // one letter per crease (crease order: AssignmentEnumeration::creases)
  int orbit_size = 0;    // assignments in the class
  bool verdict_run = false;
  FoldabilityClass verdict = FoldabilityClass::kUndecided;
  bool is_proof = false;
  int dof = 0;
  std::string reason;    // the verdict's one line
};

struct AssignmentEnumeration {
  std::vector<int> creases;        // edge of each crease position
  int symmetry_order = 1;          // geometric symmetries (identity included)
  int symmetry_rotations = 1;      // of which rotations (identity included)
  long assignments = 0;            // flat-folding assignments found
  long class_count = 0;            // classes (under symmetry and flip)
  long verdicts = 0;               // classes given a verdict
  long foldable_classes = 0;       // of those, foldable (certified)
  long not_foldable_classes = 0;   // of those, not foldable (proof or evidence)
  long undecided_classes = 0;
  bool complete = true;            // false when max_assignments or max_search_steps stopped the search
  long search_steps = 0;           // vertex visits of the backtracking
  std::vector<AssignmentClass> classes;  // the first max_listed classes, in search order
  // Set when no assignment can fold flat because of the geometry: the first interior vertex
  // with odd degree or off Kawasaki (then assignments = 0).
  int blocking_vertex = -1;
  std::string blocking_reason;
  double seconds = 0.0;
};

// Throws InputError naming `source` (the file) and the vertex when the pattern is not flat
// (vertices_coords[v] with z != 0) or a vertex has more than kMaxLetterDegree creases.
AssignmentEnumeration enumerate_assignments(const CreasePattern& pattern, const Topology& topology,
                                            const AssignmentEnumerationOptions& options = {},
                                            const std::string& source = "PATTERN");

// The subtrees of the search at `depth` vertices (fewer when the search has fewer vertices), in
// search order, each a value for AssignmentEnumerationOptions::branch; only the subtrees with a
// letter set at each of their vertices that fits the letters set before it. Empty when a vertex
// blocks every assignment (AssignmentEnumeration::blocking_vertex). Throws as enumerate_assignments.
std::vector<std::vector<int>> assignment_search_branches(const CreasePattern& pattern, const Topology& topology, int depth,
                                                         const AssignmentEnumerationOptions& options = {},
                                                         const std::string& source = "PATTERN");

}  // namespace rigidfold
