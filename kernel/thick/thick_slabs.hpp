#pragma once
// Thick panels as solid geometry: each panel of a thick sheet
// (thick_report.hpp) as a closed slab - its flat polygon at the slab's bottom and top
// heights plus one side wall per polygon side - placed at a fold state by the rigid motion
// of its face of the thick sheet (place_faces on the sheet), for writing as STL
// (polygons_stl in kernel/geometry/folded_output.hpp).
//
// Slab of a panel (flat face) f, at the flat state, [bottom_f, top_f] in z:
//   - hinges top, bottom, mid, valley: [0, t] for every panel (the sheet is the slab 0..t);
//   - bennett: [min, max] of the heights of the hinges on the panel's sides (each Bennett
//     link joins hinges on opposite faces of its panel), or [min, min + t] where they are all
//     equal.
// Polygons: the top face counter-clockwise seen from outside (+z at flat), the bottom face
// reversed, each side wall (a_bottom, b_bottom, b_top, a_top) for side a -> b of the
// counter-clockwise flat polygon: every polygon winds counter-clockwise about its outward
// normal, so the slab is a closed, outward-oriented surface.
//
// Units: pattern units (the CreasePattern's internal units); fold angles in radians.
#include <Eigen/Core>
#include <vector>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/crease_pattern.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/thick/panel_slab.hpp"
#include "kernel/thick/thick_report.hpp"

namespace rigidfold {

// One slab per flat face (see above).
std::vector<PanelSlab> panel_slabs(const CreasePattern& flat, const Topology& topology, const ThickReport& report);

// The sheet's faces placed at fold angles (per flat edge, radians, from flat) by place_faces
// on the thick sheet; `placed.max_mismatch` is the closure mismatch of that placement.
FoldedGeometry place_thick_sheet(const ThickReport& report, const Eigen::VectorXd& fold_angles);

// Every panel's slab polygons (2 + sides per panel), placed by `placed` (from
// place_thick_sheet). Points in pattern units.
std::vector<std::vector<Eigen::Vector3d>> slab_polygons(const CreasePattern& flat, const ThickReport& report,
                                                        const std::vector<PanelSlab>& slabs, const FoldedGeometry& placed);

}  // namespace rigidfold
