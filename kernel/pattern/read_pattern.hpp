#pragma once
// read_pattern: the one loader of crease-pattern files for the commands that take a pattern
// (info, check, trace, ...). By extension, case-insensitive: ".svg" is read as an SVG crease
// pattern in Origami Simulator's colours (svg_reader.hpp, default merge tolerance), ".opx" as
// an ORIPA file (opx_reader.hpp, the same arrangement), anything else as FOLD (fold_io.hpp).
//   Output: the validated CreasePattern (faces derived when the file has none).
//   Throws: InputError naming the file and the place in it.
#include <string>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

bool is_svg_path(const std::string& path);
CreasePattern read_pattern(const std::string& path);

}  // namespace rigidfold
