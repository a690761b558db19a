#pragma once
// Planar arrangement of labelled line segments: the plane straight-line graph a drawing of
// creases stands for. Segments are split where they cross or touch, endpoints closer than a
// tolerance become one vertex, and an edge drawn twice becomes one edge.
//
// Inputs:  segments in the plane (any length unit) with an integer label each (the caller's
//          meaning: an assignment and fold angle) and the index of the drawing element it
//          came from; `tolerance` (same length unit, > 0): points closer than this are one
//          vertex, and a point closer than this to a segment splits it there.
// Output:  vertices, edges (each with a label and source, see "Edges drawn twice"), and what
//          was done: crossings split, points merged (with the largest distance a point
//          moved), duplicate edges, conflicts (one edge drawn with two labels), and degree-2
//          vertices removed (two collinear edges of one label joined into one, as Origami
//          Simulator's importer does).
// Edges drawn twice: a piece of the plane drawn by two segments is one edge. With one label
//          it keeps the first segment's source (a duplicate); with two labels (a conflict) it
//          takes the label of higher ArrangementOptions::label_priority and, on a tie, the
//          later segment's (segments count in input order), with that segment's source, so
//          a third segment over the same piece meets the label kept so far. Both kinds are
//          listed, one record per stretch of consecutive pieces two segments share.
// Limits:  `max_candidate_pairs` bounds the pairs of nearby segments tested (a pile of
//          overlapping segments is quadratic); past it, build_planar_arrangement throws
//          std::length_error, which the caller reports as bad input.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace rigidfold {

struct LabelledSegment {
  Eigen::Vector2d a, b;
  // How far each end may lie from the point it stands for, per axis (the rounding of the
  // numbers it was written with; 0: exact). Only carried into PlanarArrangement's boxes.
  Eigen::Vector2d a_rounding = Eigen::Vector2d::Zero(), b_rounding = Eigen::Vector2d::Zero();
  int label = 0;
  int source = 0;  // caller's index of the element that drew it (for messages)
};

// A stretch of consecutive edges drawn by two segments: `a` drew it first (or its label
// had been kept there so far), `b` later.
struct LabelConflict {
  int source_a = 0, source_b = 0;  // the two drawing elements
  int label_a = 0, label_b = 0;
  int label_kept = 0;              // the edge's label after both (label_a == label_b for a duplicate)
  Eigen::Vector2d from, to;        // the shared stretch, along segment b
  int pieces = 1;                  // edges in it (more where other lines cross it)
};

struct PlanarArrangement {
  std::vector<Eigen::Vector2d> vertices;
  std::vector<std::array<int, 2>> edges;
  std::vector<int> edge_label;
  std::vector<int> edge_source;
  int crossings = 0;             // points where two segments cross inside both
  int touches = 0;               // segment ends lying on another segment (T-junctions, overlaps)
  int merged_points = 0;         // points merged into another (distinct coordinates only), and
                                 // line ends near (not on) another line that now bends through them
  double max_merge_distance = 0;  // largest distance a point or line moved
  int zero_length_segments = 0;  // dropped: shorter than the tolerance
  int duplicate_edges = 0;       // drawn more than once with the same label
  int collinear_vertices_removed = 0;
  std::vector<LabelConflict> conflicts;   // drawn more than once with different labels
  std::vector<LabelConflict> duplicates;  // drawn more than once with the same label
  // Per vertex, the box its true position lies in: the bounding box of the points merged into
  // it, each grown by its rounding. A crossing (no drawn point) gets twice the first-order move
  // of the crossing when each line's ends move within their rounding: (d_i + d_j) / sin(angle),
  // d the larger rounding of a line's ends; where that is not small against the two lines'
  // lengths (> 1e-3 of the shorter), the box is unbounded (infinite).
  std::vector<Eigen::Vector2d> vertex_lo, vertex_hi;
};

struct ArrangementOptions {
  double tolerance = 0;                          // absolute, > 0
  bool remove_collinear_degree2 = true;
  std::int64_t max_candidate_pairs = 50000000;  // see header comment
  // Per label (labels outside it: 0): of two labels drawn on one piece, the higher is kept,
  // on a tie the later segment's ("Edges drawn twice").
  std::vector<int> label_priority;
};

PlanarArrangement build_planar_arrangement(const std::vector<LabelledSegment>& segments, const ArrangementOptions& options);

}  // namespace rigidfold
