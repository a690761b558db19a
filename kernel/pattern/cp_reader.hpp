#pragma once
// .cp crease patterns (ORIPA, Oriedita, Orihime, Rabbit Ear ...) -> CreasePattern.
//
// A .cp file is text, one line segment a line:
//   type x1 y1 x2 y2
// fields separated by spaces or tabs, lines by LF, CRLF or CR; blank lines are skipped, and
// so is a UTF-8 byte order mark. The numbers are Java's Double.toString ("200.0", "-0.0",
// "2.4492935982947067E-14"): any decimal or exponent form, optionally signed; NaN and
// infinities are bad input. A line with other than five fields is bad input (ORIPA would
// read the tokens out of step, Oriedita would skip the line).
// Types, as the tools that write .cp read them:
//   1 cut (the paper's outline: B), 2 mountain (M), 3 valley (V),
//   0 and 4: auxiliary lines (no creases): ignored, with a warning.
// ORIPA's LoaderCP (oripa/oripa, persistence/doc/loader/LoaderCP.java) keeps 1, 2 and 3 and
// reads every other code as an auxiliary line; its ExporterCP writes no auxiliary lines and
// refuses a pattern with unassigned creases, so ORIPA never writes 4 (its "unassigned" in
// .opx format 2) into a .cp. Oriedita's .cp (oriedita/fold, fold.io.CreasePatternReader and
// CreasePatternWriter) writes 4 for its auxiliary lines (FOLD "F", cyan in Oriedita) and
// reads every code but 1-3 as one. Any other code is bad input here.
// Units and axes: ORIPA's (the same numbers as in the .opx of the same pattern): y points
// down, so FOLD y = -y. No fold angles: M and V are read with none.
//
// Arrangement: exactly the .opx reader's (opx_reader.hpp, arrange_oripa_lines): the SVG
// reader's planar arrangement, merging, clean-up and validation, and its rule for a piece
// drawn by two lines ("Lines drawn twice" in svg_reader.hpp: the later line in the file wins,
// except that a crease does not replace a cut line (1); warned, or refused with
// SvgReadOptions::strict_lines); messages and warnings name a segment as "line L", L its
// line in the file, and give coordinates as the file does.
//
// Bad input: InputError naming the file and the line, e.g.
//   "CP.cp: line 12: x2: 'abc' is not a finite number".
// Limits (input_limits.hpp): the file size, and at most kMaxSvgSegments lines.
#include <string>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/svg_reader.hpp"

namespace rigidfold {

struct CpImportSummary {
  int lines = 0;              // segment lines read (blank lines not counted)
  int lines_by_type[5] = {};  // by type code 0..4
  SvgImportSummary arrangement;  // what the arrangement did (segments, crossings, merges ...)
};

// Parses .cp text held in memory; `source` names it in messages and warnings.
CreasePattern parse_cp(const std::string& text, const std::string& source, const SvgReadOptions& options = {},
                       CpImportSummary* summary = nullptr);
// Reads a file within the input limits (read_input_file) and parses it.
CreasePattern read_cp(const std::string& path, const SvgReadOptions& options = {}, CpImportSummary* summary = nullptr);

bool is_cp_path(const std::string& path);
// True when the first non-blank line of `text` is a .cp segment: an integer and four numbers
// (read_pattern.hpp chooses the reader by it).
bool looks_like_cp(const std::string& text);

}  // namespace rigidfold
