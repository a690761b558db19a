#pragma once
// ORIPA crease patterns (.opx) -> CreasePattern.
//
// An .opx file is what java.beans.XMLEncoder writes for ORIPA's oripa.DataSet. The crease
// lines come in one of two forms, both read here, both met in ORIPA's own files:
//   property form (a "lines" bean property; ORIPA's crane_base_mitani.opx, Java 1.5):
//     <java ...><object class="oripa.DataSet">
//       <void property="lines"><array class="oripa.OriLineProxy" length="N">
//         <void index="i"><object class="oripa.OriLineProxy">
//           <void property="type"><int>2</int></void>
//           <void property="x0"><double>-200.0</double></void>  ... x1, y0, y1
//   field form (the public field DataSet.lines set by reflection; ORIPA's test files of
//   2013-2014 on Java 7, and ORIPA 1.72 on Java 21 in 2024 writes it too):
//     <java ...><object class="oripa.DataSet" id="DataSet0">
//       <void class="oripa.DataSet" method="getField"><string>lines</string>
//         <void method="set"><object idref="DataSet0"/>
//           <array class="oripa.OriLineProxy" length="N"> ... as above
// Properties are named, in any order; XMLEncoder leaves out a property equal to its
// default, so a missing x0, x1, y0, y1 or type is 0. Array entries not written are null and
// hold no line. Other DataSet properties and fields (title, memo, editorName, paperSize ...)
// are skipped; the file format version mainVersion (an <int> property) is read.
//
// Line types (ORIPA's OriLine.Type) depend on the file format version mainVersion, which
// ORIPA writes in every .opx (Version.FILE_MAJOR_VERSION; it is not ORIPA's release number,
// which no .opx states; <java version=...> is Java's):
//   0 auxiliary (a drawing aid, not a crease: ignored with a warning), 1 cut (the paper's
//   outline: B), 2 mountain (M), 3 valley (V), and
//   mainVersion 2 (ORIPA 1.65 and later, April 2023): 4 unassigned (U), 9 cut in the model (C);
//   mainVersion 1, or none:                           4 cut in the model (C).
// ORIPA changed the codes (commit 5639edf2, 2023-04-14: TYPE_UNASSIGNED = 4,
// TYPE_CUT_MODEL 4 -> 9) and raised FILE_MAJOR_VERSION from 1 to 2 nine days later
// (bf0fd592), first released in v1.65; every ORIPA before wrote mainVersion 1 (the original
// ORIPA of 2005-2012 had types 0-3 only). A file without mainVersion was not written by ORIPA
// (XMLEncoder leaves out only a 0): it is read by the rules of format 1, as before. Any other
// code is bad input, and so is a mainVersion above 2 (ORIPA itself refuses a file format newer
// than it knows). XMLEncoder writes mainVersion after the lines, so the types are checked once
// the whole file is read. ORIPA has no fold angles: M and V are read with none
// (edges_foldAngle null).
// Axes: ORIPA draws its coordinates with y pointing down (a Java2D transform
// scale(s, s) without a flip, oripa.util.gui.AffineCamera), like SVG, so FOLD y = -ORIPA y
// and the pattern seen from +z looks as ORIPA shows it.
//
// Arrangement: the lines go through the SVG reader's import (svg_reader.hpp) as one
// <line> each, coordinates exact (shortest round-trip decimals): split where they cross or
// touch, points closer than merge_tolerance x the pattern size merged, collinear degree-2
// vertices of one letter removed, dangling pieces and faces outside the boundary removed
// with a warning, faces derived and validated. A piece drawn by two lines is one edge, by
// the SVG reader's rule ("Lines drawn twice" in svg_reader.hpp), with a warning naming both
// lines: with two letters the line later in the file wins, as in ORIPA's editor, except that
// a crease never replaces a cut line (the outline, B) or a model cut (C); e.g.
//   "CP.opx: lines[4] (line 46) and lines[5] (line 55) draw the same crease from (-200, -200)
//    to (200, 200) as mountain and valley: kept valley (the later line, as ORIPA's editor does)".
// "Later" is the order of the file, which is the array's order in every file ORIPA writes.
// With SvgReadOptions::strict_lines such a piece is bad input naming both lines (the first
// such stretch only). Messages and warnings name the ORIPA line as "lines[i] (line L)", i its
// array index and L its line in the .opx; coordinates in messages are ORIPA's (y down).
//
// Bad input: InputError naming the file and the place, e.g.
//   "CP.opx: lines[3] (line 40): type: unknown line type 7 (0 aux, 1 cut, 2 mountain, 3 valley, 4 cut)".
// XML: parsed by Expat with the SVG reader's refusals: a document type with an internal
// subset and any entity reference other than XML's five are refused. Limits
// (input_limits.hpp): the file size, and the SVG reader's element depth, element count
// and segment count (kMaxSvgDepth, kMaxSvgElements, kMaxSvgSegments).
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/svg_reader.hpp"

namespace rigidfold {

struct OpxImportSummary {
  int lines = 0;               // OriLineProxy objects read
  int lines_by_type[10] = {};  // by ORIPA type code 0..9 (5..8 unused)
  int file_version = 0;        // mainVersion as the file states it (0: not stated)
  bool field_form = false;     // the lines came as a reflective field set (getField), not a property
  SvgImportSummary arrangement;  // what the arrangement did (segments, crossings, merges ...)
};

// Parses .opx text held in memory; `source` names it in messages and warnings.
CreasePattern parse_opx(const std::string& text, const std::string& source, const SvgReadOptions& options = {},
                        OpxImportSummary* summary = nullptr);
// Reads a file within the input limits (read_input_file) and parses it.
CreasePattern read_opx(const std::string& path, const SvgReadOptions& options = {}, OpxImportSummary* summary = nullptr);

bool is_opx_path(const std::string& path);

// The last step the ORIPA readers share (.opx here, .cp in cp_reader.hpp), so that both
// arrange their lines identically: each line becomes one SVG <line> (ORIPA's y points down,
// as SVG's; M and V without fold angle) and the text goes through parse_svg; messages and
// warnings name a line by its `name` instead of the SVG element. `lines` holds crease lines
// only (B, M, V, U or C; no auxiliary lines), at most kMaxSvgSegments of them.
struct OripaCreaseLine {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  Assignment assignment = Assignment::Boundary;
  std::string name;  // "lines[3] (line 40)" (.opx), "line 12" (.cp)
};
CreasePattern arrange_oripa_lines(const std::vector<OripaCreaseLine>& lines, const std::string& source, const SvgReadOptions& options,
                                  SvgImportSummary* summary);

}  // namespace rigidfold
