#pragma once
// ORIPA crease patterns (.opx) -> CreasePattern.
//
// An .opx file is what ORIPA's java.beans.XMLEncoder writes for an oripa.DataSet:
//   <java ...><object class="oripa.DataSet">
//     <void property="lines"><array class="oripa.OriLineProxy" length="N">
//       <void index="i"><object class="oripa.OriLineProxy">
//         <void property="type"><int>2</int></void>
//         <void property="x0"><double>-200.0</double></void>  ... x1, y0, y1
//   ...
// Properties are named, in any order; XMLEncoder leaves out a property equal to its
// default, so a missing x0, x1, y0, y1 or type is 0. Array entries not written are null and
// hold no line. Other DataSet properties (title, memo, versions ...) are skipped.
// Line types (ORIPA's OriLine.Type): 0 auxiliary (a drawing aid, not a crease: ignored with
// a warning), 1 cut (the paper's outline: B), 2 mountain (M), 3 valley (V), 4 cut in the
// model (C); any other code is bad input. ORIPA has no fold angles: M and V are read with
// none (edges_foldAngle null).
// Axes: ORIPA draws its coordinates with y pointing down (a Java2D transform
// scale(s, s) without a flip, oripa.util.gui.AffineCamera), like SVG, so FOLD y = -ORIPA y
// and the pattern seen from +z looks as ORIPA shows it.
//
// Arrangement: the lines go through the SVG reader's import (svg_reader.hpp) as one
// <line> each, coordinates exact (shortest round-trip decimals): split where they cross or
// touch, points closer than merge_tolerance x the pattern size merged, collinear degree-2
// vertices of one letter removed, dangling pieces and faces outside the boundary removed
// with a warning, faces derived and validated. Messages and warnings name the ORIPA line
// as "lines[i] (line L)", i its array index and L its line in the .opx.
//
// Bad input: InputError naming the file and the place, e.g.
//   "CP.opx: lines[3] (line 40): type: unknown line type 7 (0 aux, 1 cut, 2 mountain, 3 valley, 4 cut)".
// XML: parsed by Expat with the SVG reader's refusals: a document type with an internal
// subset and any entity reference other than XML's five are refused. Limits
// (input_limits.hpp): the file size, and the SVG reader's element depth, element count
// and segment count (kMaxSvgDepth, kMaxSvgElements, kMaxSvgSegments).
#include <string>

#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/svg_reader.hpp"

namespace rigidfold {

struct OpxImportSummary {
  int lines = 0;              // OriLineProxy objects read
  int lines_by_type[5] = {};  // by ORIPA type code 0..4
  SvgImportSummary arrangement;  // what the arrangement did (segments, crossings, merges ...)
};

// Parses .opx text held in memory; `source` names it in messages and warnings.
CreasePattern parse_opx(const std::string& text, const std::string& source, const SvgReadOptions& options = {},
                        OpxImportSummary* summary = nullptr);
// Reads a file within the input limits (read_input_file) and parses it.
CreasePattern read_opx(const std::string& path, const SvgReadOptions& options = {}, OpxImportSummary* summary = nullptr);

bool is_opx_path(const std::string& path);

}  // namespace rigidfold
