#pragma once
// CreasePattern -> ASCII DXF (AutoCAD R12, AC1009) crease pattern, for laser cutters and
// CAD programs.
//
// Output: a DXF with a HEADER ($ACADVER AC1009), a LAYER table of six layers, one per
// letter, named by the letter, with AutoCAD Colour Index colours
//   B 7 (white/black)   M 1 (red)   V 5 (blue)   F 2 (yellow)   U 6 (magenta)   C 3 (green)
// and one LINE entity per edge on its letter's layer (colour BYLAYER), z = 0.
// Coordinates in the file's length units (the pattern's length_exponent undone), DXF axes
// = FOLD axes (y up, no flip), written as the shortest decimal that reads back to the same
// double. Lines end with "\n" (DXF readers accept it as well as "\r\n").
// 3D coordinates: the flat crease pattern (flat_development.hpp), refused where none exists.
// Not preserved: fold angles (an R12 LINE has no place for them), faces (implied by the
// lines), vertex and edge order, the FOLD file's other keys.
// Refused (InputError naming `source` and the edge): a J (join) edge, which has no layer in
// the letter table; plus the refusals of flat_development.
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// AutoCAD Colour Index of a letter's layer (7, 1, 5, 2, 6, 3 for B M V F U C); 0 for J.
int dxf_layer_colour(Assignment a);

// The DXF text of the pattern's flat crease pattern. `source` names it in messages.
std::string write_dxf_string(const CreasePattern& pattern, const std::string& source);

}  // namespace rigidfold
