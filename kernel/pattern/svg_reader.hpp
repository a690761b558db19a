#pragma once
// SVG crease patterns (Origami Simulator's convention) -> CreasePattern.
//
// Colours (stroke, in any CSS form: #rgb, #rrggbb, #rgba, #rrggbbaa, rgb()/rgba() with
// numbers or percentages, CSS names, currentColor; from the stroke= attribute or
// style="stroke:...", inherited from enclosing <g>/<svg>):
//   black #000000 B (boundary)      red #ff0000 M (mountain)    blue #0000ff V (valley)
//   yellow #ffff00 F (facet: flat)  magenta #ff00ff U (undriven hinge)
//   green #00ff00, and the CSS name green (#008000) C (cut)
// as in Origami Simulator's importer (js/pattern.js). An element drawn in any other colour
// (cyan, grey guides ...) is ignored and listed in the warnings, as Origami Simulator ignores
// it; an element with no stroke is not drawn and is skipped. Dash patterns carry no meaning
// (Origami Simulator clears stroke-dasharray): a dashed line is read by its colour alone.
// Fold angle: Origami Simulator reads a mountain's target angle as -opacity x 180 deg and a
// valley's as +opacity x 180 deg; here the opacity is the product of opacity (element and
// enclosing groups), stroke-opacity and the colour's alpha, and it becomes edges_foldAngle
// (F: 0; B, C, U: none; a fully transparent M/V: none).
//
// Geometry: <line>, <polyline>, <polygon>, <rect> (no rounded corners) and <path> with
// M L H V Z in absolute and relative form (implicit repeats included). Curves (C S Q T A)
// in a crease colour are refused, not flattened: crease patterns are straight lines.
// transform= (matrix, translate, scale, rotate with or without centre, skewX, skewY; lists;
// nested groups) is applied; viewBox and the width/height of <svg> are not (they scale
// the whole drawing uniformly, which no verdict depends on). Lengths in px or absolute units
// (mm, cm, in, pt, pc; converted to px); % and font units are refused. The y axis is
// flipped (FOLD y = -SVG y) so the pattern seen from +z looks as drawn.
// Contents of <defs>, <clipPath>, <mask>, <symbol>, <marker>, <pattern>, <metadata>, and
// elements of other namespaces (sodipodi:, inkscape:) are skipped, as is display:none.
// <style> sheets and <use> are not applied (warned).
//
// Arrangement (planar_arrangement.hpp): lines are split where they cross or touch, points
// closer than merge_tolerance x the pattern size (the diagonal of the drawn lines' bounding
// box) become one vertex, a line drawn twice becomes one edge (drawn twice in two colours is
// bad input naming both elements), a vertex joining two collinear edges of one colour is
// removed, and dangling pieces (an end on no other line: overshoots, a crease stopping inside
// the paper) are removed with a warning, since they divide no face and cannot fold; before
// that, a line stopping short of a vertex by at most SvgReadOptions::loose_end_snap is joined
// to it, with a warning (loose_end_snap.hpp). Faces
// are derived from the plane embedding (validate_pattern.hpp); where the black lines close
// into loops, faces outside them (closed by lines drawn past the boundary) are removed too.
//
// Bad input: InputError naming the file and the element, e.g.
//   "CP.svg: <path> #12 (line 40): d: curve command 'C' is not a straight crease".
// XML: parsed by Expat; a document type with an internal subset (where entities are declared:
// "billion laughs") and any entity reference other than XML's five are refused. Limits:
// input_limits.hpp (file size, element nesting depth, elements, segments).
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

struct SvgReadOptions {
  // Points closer than this fraction of the pattern size are one vertex. Files drawn by hand
  // or exported with 3 decimals miss their meeting points by more than their rounding: in
  // Origami Simulator's own SVGs, lines meant to meet at one vertex cross up to 0.05 px apart
  // (huffmanWaterbomb.svg, traditionalCrane.svg; 1e-5 of their size leaves slivers and a
  // mountain drawn over a valley), while their shortest creases are > 10 px (> 3e-3 of
  // their size). 1e-4 imports them all.
  double merge_tolerance = 1e-4;
  // A line end on no other line, whose dangling piece is longer than this, moves to the
  // nearest vertex (else line) within this distance (loose_end_snap.hpp), in SVG user units:
  // Origami Simulator's vertex tolerance (vertTol = 3), at most 1e-2 of the pattern size.
  // 0: no snapping (such pieces are removed as dangling).
  double loose_end_snap = 3.0;
};

struct SvgImportSummary {
  int elements = 0;                // XML elements in the file
  int drawn_elements = 0;          // elements drawn in a crease colour
  int ignored_elements = 0;        // drawn in another colour (listed in the pattern's warnings)
  int segments = 0;                // straight segments read from the drawn elements
  int segments_by_letter[7] = {};  // indexed by Assignment (B M V F U C J)
  double pattern_size = 0;         // bounding-box diagonal of the segments, SVG user units (px)
  double merge_tolerance = 0;      // absolute, SVG user units
  double merge_tolerance_relative = 0;
  int crossings = 0;               // new vertices where two lines cross
  int touches = 0;                 // line ends met on another line (T-junctions, overlaps)
  int merged_points = 0;           // distinct points merged into another vertex
  double max_merge_distance = 0;   // largest move of a point onto its vertex, user units
  int duplicate_edges = 0;
  int collinear_vertices_removed = 0;
  int zero_length_segments = 0;
  double loose_end_snap = 0;       // the snap distance used, user units
  int loose_ends_snapped = 0;      // line ends moved onto a vertex or line (loose_end_snap.hpp)
  int loose_ends_onto_lines = 0;   // of which onto a line
  double max_snap_distance = 0;    // largest such move, user units
  int dangling_edges_removed = 0;  // pieces with an end on no other line (see above)
  int faces_outside_boundary_removed = 0;  // closed by lines drawn past the black boundary
  double shortest_edge = 0;        // after the import, user units (warned when < 10 x merge_tolerance)
};

// Parses SVG text held in memory; `source` names it in messages (and warnings).
CreasePattern parse_svg(const std::string& text, const std::string& source, const SvgReadOptions& options = {},
                        SvgImportSummary* summary = nullptr);
// Reads a file within the input limits (read_input_file) and parses it.
CreasePattern read_svg(const std::string& path, const SvgReadOptions& options = {}, SvgImportSummary* summary = nullptr);

}  // namespace rigidfold
