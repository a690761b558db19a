#pragma once
// DXF (AutoCAD R12) drawing of SORCE profile pairs, for CAD: per fold, the left and right
// profiles as 2D polylines in their panels' own t = 0 coordinates (the fold's normal plane,
// sorce_profile.hpp: zero-thickness fold at the origin, left panel along -x, right along +x,
// y the facet normal), and each panel's slab faces y = +-h/2 as lines on its own side.
// Every fold keeps its true coordinates (no layout shift, unlike the SVG): folds are told
// apart by layer, "<NAME>_LEFT", "<NAME>_RIGHT", "<NAME>_SLAB" (colours 5 blue, 1 red, 8
// grey), so a maker switches one fold on and extrudes its profiles as drawn.
// Units: the caller's length unit; samples evenly spaced in t, both ends included.
#include <string>
#include <vector>

#include "design/sorce/sorce_profile.hpp"

namespace rigidfold::sorce {

// NamedFold::name is the layer prefix: letters, digits, '_' or '-' only (DXF layer names).
// Throws InputError("samples") if samples < 2, InputError("folds[k].name") for an empty name
// or one with other characters; passes on profile errors (gamma' = 0 somewhere).
std::string fold_profiles_dxf(const std::vector<NamedFold>& folds, int samples = 201);

}  // namespace rigidfold::sorce
