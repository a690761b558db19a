#pragma once
// read_pattern: the one loader of crease-pattern files for the commands that take a pattern
// (info, check, trace, ...). Four formats: FOLD (fold_io.hpp), SVG in Origami Simulator's
// colours (svg_reader.hpp, default merge tolerance), ORIPA .opx (opx_reader.hpp) and .cp
// (cp_reader.hpp), the last two through the SVG reader's arrangement.
//
// The format is chosen by the content, so that a file with a missing or wrong extension
// reads (detect_pattern_format; a UTF-8 byte order mark and leading white space skipped):
//   '{' or '['                          FOLD (JSON; a top-level array is then refused as FOLD)
//   XML whose root element is <java>    ORIPA .opx (java.beans.XMLEncoder)
//   XML whose root element is <svg>     SVG (with or without a namespace prefix)
//   a first line "integer x1 y1 x2 y2"  .cp
// (XML: the root element after any <?xml ...?>, comments and <!DOCTYPE ...>.) Where the
// content names a format its extension (case-insensitive .fold, .svg, .opx, .cp) contradicts,
// the content wins and the pattern's warnings say so. Where the content is none of these, a
// file named .svg, .opx or .cp goes to that reader, which names the fault in its own terms
// (an XML error's line and column, the .cp line); any other file - .fold included, since
// every FOLD file starts with '{' - is refused as
//   "FILE: not a FOLD, SVG, ORIPA .opx or .cp file (it begins "...")"
// and an empty file as FOLD's "file is empty".
//   Output: the validated CreasePattern (faces derived when the file has none); its warnings
//     include the line readers' (lines drawn twice and merged, svg_reader.hpp "Lines drawn
//     twice"; elements ignored; points merged ...).
//   Throws: InputError naming the file and the place in it.
// The line readers (SVG, .opx, .cp) take SvgReadOptions (merge tolerance, loose-end snap,
// strict_lines); read_pattern(path) uses their defaults, the overloads below take them.
#include <string>
#include <string_view>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/svg_reader.hpp"

namespace rigidfold {

enum class PatternFormat { Unknown, Fold, Svg, Opx, Cp };

bool is_svg_path(const std::string& path);
// By the extension alone (case-insensitive): .fold, .svg, .opx, .cp; Unknown for any other.
PatternFormat pattern_format_of_path(const std::string& path);
// By the content alone (see above); Unknown for an empty file or anything else.
PatternFormat detect_pattern_format(const std::string& text);
// "FOLD", "SVG", "ORIPA .opx", ".cp", "unknown".
std::string_view pattern_format_name(PatternFormat format);

// The format parse_pattern reads `text` as (by its content, else by the extension of
// `source`, see above); throws the InputError refusing it when there is none.
PatternFormat pattern_format_to_read(const std::string& text, const std::string& source);

// Parses text held in memory, choosing the format as read_pattern does; `source` names it
// (and its extension counts as a file's would).
CreasePattern parse_pattern(const std::string& text, const std::string& source);
// The same with the line readers' options; for SVG, .opx and .cp, `summary` (when given) gets
// what the arrangement did, as their readers report it (for .opx and .cp: the arrangement of
// their summaries; elements are the file's, drawn elements its crease lines); for FOLD it
// is left as it was. `format` (when given) gets the format read.
CreasePattern parse_pattern(const std::string& text, const std::string& source, const SvgReadOptions& options,
                            SvgImportSummary* summary = nullptr, PatternFormat* format = nullptr);
// Reads a file within the input limits (read_input_file) and parses it.
CreasePattern read_pattern(const std::string& path);
CreasePattern read_pattern(const std::string& path, const SvgReadOptions& options, SvgImportSummary* summary = nullptr,
                           PatternFormat* format = nullptr);

}  // namespace rigidfold
