#pragma once
// Writing a folded state: as a FOLD frame appended to the crease pattern, as OBJ, and as binary STL.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "kernel/geometry/face_placement.hpp"
#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// The pattern (key frame, unchanged) plus one file_frames entry
// {frame_classes: ["foldedForm"], frame_parent: 0, frame_inherit: true,
//  vertices_coords: folded 3D, edges_foldAngle: degrees}. fold_angles in radians.
CreasePattern with_folded_frame(const CreasePattern& pattern, const FoldedGeometry& folded,
                                const Eigen::VectorXd& fold_angles, const std::string& title);

// Wavefront OBJ text of the folded faces (1-based indices, one polygon per face).
std::string folded_obj(const CreasePattern& pattern, const FoldedGeometry& folded);

// Binary STL of the folded faces, as bytes: an 80-byte header naming rigidfold, the
// triangle count (uint32), then per triangle the unit normal and three vertices (float32 x 3
// each, little-endian, the file's length units) and a zero attribute (uint16).
// Each face is triangulated in its own reference plane by ear clipping (faces may be
// non-convex; a vertex on a straight side of its face is skipped, leaving the triangle side
// through it), and each triangle is placed by its face's rigid motion, so the triangles of a
// face are congruent to it and a closure mismatch shows as cracks between faces, not as
// stretched faces. Triangles wind counter-clockwise about their normal, the face's folded
// normal (the side a flat pattern's +z turns to). Throws std::invalid_argument when a face
// cannot be triangulated (a face that crosses itself) or there are 2^32 triangles or more.
std::string folded_stl(const CreasePattern& pattern, const FoldedGeometry& folded);

// Binary STL (same layout as folded_stl) of planar 3D polygons given by their points
// (length units of a pattern with that length_exponent; written in file units), each
// triangulated by triangulate_face and wound counter-clockwise about its Newell normal, which
// is the facet normal written. For solids built of polygons (thick panels as slabs,
// kernel/thick/thick_slabs.hpp). Throws std::invalid_argument naming the polygon when one
// cannot be triangulated.
std::string polygons_stl(const std::vector<std::vector<Eigen::Vector3d>>& polygons, int length_exponent,
                         const std::string& title);

// Ear-clipping triangulation of one face in its reference plane: triangles as vertex
// indices of the pattern, each counter-clockwise about the face's Newell normal.
std::vector<std::array<int, 3>> triangulate_face(const CreasePattern& pattern, const std::vector<int>& face);

}  // namespace rigidfold
