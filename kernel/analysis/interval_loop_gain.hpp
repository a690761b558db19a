#pragma once
// A loop-gain proof that holds for every pattern within a file's rounding (so that the
// classic square twist drawn with 3 decimals is "not foldable", not "undecided").
//
// The multiplier model finds a cycle of degree-4 vertices whose loop gain misses 1 on one
// flat-foldable witness of the file (flat_foldable_witness.hpp). This repeats that argument
// with interval arithmetic over the boxes each vertex may lie in, using the first-order modes
// of developable degree-4 vertices (degree4_first_order_modes.hpp), which need no Kawasaki.
//
// The argument. Take any analytic folding motion from flat of a pattern whose vertices lie
// in the boxes, which keeps the letters on every crease that folds, and a vertex v of the
// cycle one of whose creases moves. At the lowest order in which a crease at v moves, the
// rates lie on one of v's two mode lines. A mode is ruled out when two of its rates have
// proven signs that disagree with their letters (M < 0, V > 0) in either direction; the
// letters must rule out exactly one mode at each cycle vertex, and on the other the rates of
// the two cycle creases at v must be proven nonzero. Then both cycle creases at v move at
// that order; they are shared with the neighbours on the cycle, so every cycle vertex moves
// at the same order, and the product of the rate ratios c_out / c_in around the cycle is 1.
// If the enclosure of that product excludes 1, no such motion exists: every crease at the
// cycle's vertices stays flat. The file's own numbers lie in the boxes, so this is a proof
// for them too.
//
// Inputs: the pattern and its topology (fans in CCW order); per vertex a box [lo, hi] in x
// and y (length unit; it must hold the vertex, e.g. CreasePattern::position_bounds or the
// coordinates +- their rounding); the cycle as the multiplier model reports it
// (cycle_creases[i] joins cycle_vertices[i] and cycle_vertices[i + 1], cyclically).
// Output: proven, with the enclosure of the loop gain; otherwise why not (never an error).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "kernel/numeric/outward_interval.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {

struct IntervalLoopGainProof {
  bool proven = false;
  std::string why_not;
  OutwardInterval gain = OutwardInterval::whole();  // over every pattern within the boxes
  double largest_box_half_width = 0.0;               // of the cycle's vertices and their neighbours
};

IntervalLoopGainProof interval_loop_gain_proof(const CreasePattern& pattern, const Topology& topology,
                                               const std::vector<Eigen::Vector2d>& box_lo,
                                               const std::vector<Eigen::Vector2d>& box_hi,
                                               const std::vector<int>& cycle_vertices,
                                               const std::vector<int>& cycle_creases);

}  // namespace rigidfold

namespace rigidfold {

// The same proof tried on the cycle around each face whose corners are all interior degree-4
// vertices (the central square of a square twist), for patterns with no flat-foldable
// witness: the first-order modes need no Kawasaki, so the exact numbers (zero-width boxes)
// and patterns that are not flat-foldable within their rounding are covered too. Every face
// is tried; the first proven cycle is reported, and `locked_vertices` collects the corners
// of every proven cycle: no crease at them folds. `every_crease_locked`: every hinge crease
// (two faces across it) has an end among them, so no rigid motion from flat that keeps the
// letters folds any crease at all (strict or weak); otherwise other creases may still fold.
// faces_tried counts the faces whose cycles were tried.
struct FaceCycleProof {
  bool proven = false;
  int face = -1;
  std::vector<int> cycle_vertices, cycle_creases;
  IntervalLoopGainProof proof;
  int faces_tried = 0;
  int faces_proven = 0;
  std::vector<int> locked_vertices;  // increasing
  bool every_crease_locked = false;
};
// True when every hinge crease (two faces across it) has an end at a vertex marked in
// `locked` (one entry per vertex): then no crease can fold.
bool every_hinge_has_a_locked_end(const CreasePattern& pattern, const Topology& topology,
                                  const std::vector<char>& locked);

FaceCycleProof face_cycle_loop_gain_proof(const CreasePattern& pattern, const Topology& topology,
                                          const std::vector<Eigen::Vector2d>& box_lo,
                                          const std::vector<Eigen::Vector2d>& box_hi);

}  // namespace rigidfold
