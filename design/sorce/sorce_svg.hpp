#pragma once
// SVG drawing of SORCE profile pairs: polylines in panel-local
// coordinates, for checking by eye and for handing to CAD.
//
// One fold: the left profile s_l(t) (class "left") and the right profile s_r(t) (class
// "right"), each in its own panel's t = 0 coordinates (the fold's normal plane: the
// zero-thickness fold at the origin, the left panel along -x, the right along +x, y up), so
// both start at the same point (s0, 0). The slab faces y = +-h/2 of each panel are drawn as
// dashed lines (classes "left-slab", "right-slab") on its own side of the fold. Points are
// printed in model units (the caller's length unit) with 12 significant digits; the picture
// flips y once, in a transform on the enclosing group, so polyline coordinates are the
// model's. Samples are evenly spaced in t, both ends included (evaluated exactly).
#include <string>
#include <vector>

#include "design/sorce/sorce_vertex.hpp"

namespace rigidfold::sorce {

struct SvgOptions {
  int samples = 201;           // points per profile, >= 2
  double pixels_per_unit = 100;  // width/height attributes; the viewBox stays in model units
  double width_px = 0;           // > 0: pixels_per_unit chosen so that the drawing is this wide
  double stroke = 0.01;        // line width, model units
};

// A group <g class="fold"> with the fold's profile pair and slab faces (no <svg> wrapper),
// its own y flip, translated by (dx, dy) in model units. Throws InputError("samples") if
// samples < 2.
std::string fold_profiles_svg_group(const FoldMotion& motion, const SvgOptions& options, double dx = 0.0,
                                    double dy = 0.0);

// A whole SVG document with the folds side by side in the order given, each labelled by its
// name (XML-escaped). Throws InputError("folds") when there is none.
std::string folds_profiles_svg(const std::vector<NamedFold>& folds, const SvgOptions& options = {});

// The four folds of a vertex (fold 1 leftmost), labelled "fold j".
std::string vertex_profiles_svg(const SorceVertex& vertex, const SvgOptions& options = {});

}  // namespace rigidfold::sorce
