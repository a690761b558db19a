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
// box) become one vertex, a line drawn twice becomes one edge (by the rule below), a vertex
// joining two collinear edges of one colour is removed, and dangling pieces (an end on no other line: overshoots, a crease stopping inside
// the paper) are removed with a warning, since they divide no face and cannot fold; before
// that, a line stopping short of a vertex by at most SvgReadOptions::loose_end_snap is joined
// to it, with a warning (loose_end_snap.hpp). Faces
// are derived from the plane embedding (validate_pattern.hpp); where the black lines close
// into loops, faces outside them (closed by lines drawn past the boundary) are removed too.
//
// Lines drawn twice: a piece of line drawn by two elements becomes one edge, and a warning
// names both elements, the piece, the letters and what was kept (one per pair of elements;
// at most ten, then a count; SvgImportSummary::merged_lines lists them all, and
// `import --json` prints that list as "merged_lines").
// Lines that overlap only in part were split where one ends on the other, so the rule below
// holds piece by piece: a valley drawn over half of a mountain takes that half only.
//   - Same letter and fold angle: one edge (also counted in duplicate_edges).
//   - Two letters, or one letter with two fold angles (opacities): the element drawn later
//     in the file wins, with its letter and fold angle (within one element: its later
//     segment). This is what ORIPA's editor does when a line is drawn over another (it
//     "reduces overlaps by overwriting types": oripa.domain.cptool.LineTypeOverwriter gives
//     the overlap the added line's type), so the file reads as ORIPA would show its lines
//     drawn in the order of the file. A third line over the same piece meets the letter
//     kept so far, and is warned about with the line that drew it.
//   - Except: a boundary (B) or cut (C) line is not overwritten by a crease (M, V, F, U),
//     whichever was drawn later (between B and C the later wins). Here this reader departs
//     from ORIPA's editor, on purpose: B and C say where the paper is (its outline, a slit),
//     a crease letter how to fold paper lying on both sides of a line. A crease traced
//     over the outline (a crease drawn along an edge, the square's sides retraced in a
//     crease colour, a "select all, change type" slip) can fold nothing there,
//     having paper on one side only; letting it win would turn the paper's edge into a crease
//     with one face, which validation can only treat as boundary again ("edge has one face
//     but is assigned M") while the written FOLD would carry the crease letter on the
//     outline. A user who draws over the outline expects the outline to stay. The same holds
//     inside the paper: a crease over a slit leaves the slit (a crease cannot join cut paper).
// SvgReadOptions::strict_lines refuses instead, as before this rule: a piece drawn with two
// letters or two fold angles is bad input naming both elements and the first such stretch
// of line (consecutive pieces the two draw together), e.g.
//   "CP.svg: <line> #1 (line 3) and <line> #2 (line 4): draw the same crease from (0, 5) to
//    (10, 5) as mountain and valley"
// (a piece drawn twice with one letter and fold angle is still one edge, with its warning).
//
// Bad input: InputError naming the file and the element, e.g.
//   "CP.svg: <path> #12 (line 40): d: curve command 'C' is not a straight crease".
// XML: parsed by Expat; a document type with an internal subset (where entities are declared:
// "billion laughs") and any entity reference other than XML's five are refused. Limits:
// input_limits.hpp (file size, element nesting depth, elements, segments).
#include <optional>
#include <string>
#include <string_view>
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
  // Refuse a piece drawn with two letters or fold angles instead of keeping one of them
  // ("Lines drawn twice" above).
  bool strict_lines = false;
};

// Two lines (elements) drawing the same piece of line, merged into one edge ("Lines drawn
// twice" above): one record per pair of lines and letters.
struct MergedLines {
  enum class Rule {
    Duplicate,  // same letter and fold angle: one edge
    Later,      // two letters or fold angles: the later line's kept
    Outline,    // a crease drawn later over a B or C line: the B or C line kept
  };
  std::string first, second;  // the lines as messages name them, in the order drawn ("<line> #2 (line 5)")
  Assignment first_letter = Assignment::Boundary, second_letter = Assignment::Boundary, kept_letter = Assignment::Boundary;
  std::optional<double> first_fold_angle, second_fold_angle, kept_fold_angle;  // radians
  Rule rule = Rule::Duplicate;
  double from[2] = {0, 0}, to[2] = {0, 0};  // the first stretch they share, SVG user units (y down)
  int stretches = 0;  // separate stretches they share (a polyline over a polyline: several)
  int pieces = 0;     // edges in them (lines crossing a stretch split it into several)
};
std::string_view merged_lines_rule_name(MergedLines::Rule rule);  // "same", "later", "outline"

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
  int duplicate_edges = 0;         // pieces drawn twice with one letter and fold angle
  int overwritten_edges = 0;       // pieces drawn with two letters or fold angles, one kept
  std::vector<MergedLines> merged_lines;  // each pair of lines drawing a piece twice
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
