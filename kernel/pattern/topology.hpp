#pragma once
// Topology of a crease pattern: the star of creases around each vertex in counter-clockwise
// order with its sector angles, connected components, boundary loops, Euler characteristic.
//
// Faces are joined across "hinge" edges: edges with two faces whose assignment is not B or
// C (FOLD: a cut edge C acts as two boundary edges). Around a vertex the faces form fans;
// a vertex with one closed fan is interior (it carries a loop-closure constraint), any
// other vertex is on the boundary (or where several flaps touch).
//
// Sector angles (radians) are corner angles of the faces in their reference coordinates,
// 2D or 3D, measured about each face's own normal, so non-developable vertices are legal
// and reflex corners (> pi) are right.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

// One fan of faces around a vertex, counter-clockwise about the face normals.
struct Fan {
  bool closed = false;        // the faces go all the way round
  std::vector<int> edges;     // edges in CCW order; closed: n edges, open: n+1 (first/last are boundary)
  std::vector<double> sectors;  // sectors[i] (radians) lies between edges[i] and edges[i+1] (cyclic if closed)
  std::vector<int> faces;     // faces[i] is the face of sectors[i]
};

struct VertexStar {
  std::vector<Fan> fans;  // empty for an isolated vertex
  bool interior() const { return fans.size() == 1 && fans[0].closed; }
  double sector_sum() const;  // radians, over all fans
};

struct Component {
  int vertices = 0, edges = 0, faces = 0;
  int euler_characteristic = 0;  // V - E + F of the surface (cut edges counted on both sides)
  int boundary_loops = 0;
  int genus = 0;                 // from chi = 2 - 2g - b (orientable surface)
  int holes = 0;                 // boundary loops beyond the outer one (a tube has 1)
};

struct Topology {
  std::vector<VertexStar> stars;             // one per vertex
  std::vector<std::array<int, 2>> edge_faces;  // [face on the left of v0->v1, face on the right]; -1 if none
  std::vector<bool> edge_is_hinge;           // two faces joined across this edge
  std::vector<Eigen::Vector3d> face_normals;  // unit normals of the reference faces (Newell)
  std::vector<double> face_areas;
  std::vector<int> face_component;           // component of each face
  std::vector<Component> components;
  std::vector<std::vector<int>> boundary_loops;  // vertex cycles, each with the sheet on its left
  std::vector<int> interior_vertices;        // vertices with one closed fan
};

// Builds the topology. Requires faces (see complete_and_validate). Throws InputError on a
// non-manifold edge (three or more faces) or two faces traversing an edge the same way.
Topology build_topology(const CreasePattern& pattern, const std::string& source = "pattern");

// Corner angle at vertex `at` of the triangle (prev, at, next) measured counter-clockwise
// about `normal` from the direction of `next` to the direction of `prev`, in (0, 2pi).
double corner_angle(const Eigen::Vector3d& prev, const Eigen::Vector3d& at, const Eigen::Vector3d& next,
                    const Eigen::Vector3d& normal);

// Newell normal (not normalised; its norm is twice the polygon's area).
Eigen::Vector3d newell_normal(const CreasePattern& pattern, const std::vector<int>& face);

}  // namespace rigidfold
