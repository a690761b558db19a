#pragma once
// CreasePattern -> SVG crease pattern in Origami Simulator's convention: the inverse of
// svg_reader.hpp, so that read_svg(write_svg_string(P)) is P again (up to vertex, edge and
// face order; see "Not preserved").
//
// Output: SVG 1.1 text, one <line> per edge, in the file's length units (the pattern's
// length_exponent undone), user units = FOLD units, y flipped (SVG y = -FOLD y, as the
// reader flips it back). Coordinates are written as the shortest decimal that reads back to
// the same double (std::to_chars), so they round-trip bit for bit.
//   Colour per letter (stroke): B #000000, M #ff0000, V #0000ff, F #ffff00, U #ff00ff,
//   C #00ff00.
//   Fold angle: M and V carry stroke-opacity = |edges_foldAngle| / 180 deg (the reader reads
//   opacity x 180 deg, signed by the letter); the opacity written is the double whose
//   product with pi, as the reader forms it, is nearest to |rho|: the angle reads back bit
//   for bit where such a product exists and within 1 ulp otherwise (products of consecutive
//   opacities lie ~1.6 ulp of the angle apart, so not every double is one). An M or V with
//   no fold angle gets stroke-opacity 0, which the reader reads as no angle (it is then
//   invisible in a viewer).
//   viewBox: the bounding box of the lines grown by a margin of 2% of its diagonal; stroke
//   width 1/400 of that diagonal (non-scaling: no width/height attributes are written).
// 3D coordinates: the flat crease pattern is written (flat_development.hpp); a tube, a sheet
// with holes, several pieces, a folded form that is not developable or whose development
// overlaps itself has none and is refused.
//
// Not preserved (the SVG convention cannot say it):
//   - vertex, edge and face order, and faces given in the file (the reader derives faces
//     from the drawing; a consistent counter-clockwise FOLD gives the same face cycles);
//   - fold angles of B, C and U edges (read back as none), of F edges (read back as 0), and
//     an M or V whose fold angle is exactly 0 (read back as none);
//   - what the reader's planar arrangement changes: a degree-2 vertex between two collinear
//     edges of one letter and fold angle is removed (the two edges become one), points
//     closer than its merge tolerance (1e-4 of the pattern size) become one vertex, edges
//     that cross without a vertex are split, dangling edges and isolated vertices are dropped;
//   - the FOLD file's other keys (file_*, frame_*, file_frames, vendor keys).
// Refused (InputError naming `source` and the edge): a J (join) edge, which has no colour in
// the convention; an M with a positive or a V with a negative fold angle, which an opacity
// cannot say; plus the refusals of flat_development.
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// Stroke colour of a letter in Origami Simulator's convention ("#rrggbb"); empty for J.
std::string svg_stroke_colour(Assignment a);

// The SVG text of the pattern's flat crease pattern. `source` names it in messages.
std::string write_svg_string(const CreasePattern& pattern, const std::string& source);

}  // namespace rigidfold
