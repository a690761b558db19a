#pragma once
// CreasePattern: the in-memory crease graph of one FOLD frame.
//
// Units: lengths in the file's units, fold angles in RADIANS (FOLD stores degrees;
// the FOLD reader/writer converts). Sign convention (FOLD edges_foldAngle):
//   rho = 0 flat, rho > 0 valley, rho < 0 mountain, rho in [-pi, pi].
// Faces are vertex cycles ordered counter-clockwise seen from the side the face
// normal points to (+z for a 2D pattern).
#include <Eigen/Core>
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "kernel/pattern/assignment.hpp"

namespace rigidfold {

struct CreasePattern {
  std::vector<Eigen::Vector3d> vertices;      // reference coordinates (z = 0 for 2D input), in units of 2^length_exponent
  // The file's coordinates are ldexp(vertices, length_exponent). complete_and_validate sets
  // it when the pattern's extent lies outside [2^-20, 2^20] (a pattern of side 1e-300 or
  // 1e300), so that the kernel works on coordinates of size ~1 (rigid foldability does not
  // depend on the scale, and lengths squared neither underflow nor overflow). Scaling by a
  // power of two is exact: writers (fold_to_json, with_folded_frame, folded_obj) give back
  // the file's coordinates. 0 for every pattern within that band.
  int length_exponent = 0;
  bool coords_2d = true;                      // true when the file gave 2D coordinates
  std::vector<std::array<int, 2>> edges;      // vertex index pairs
  std::vector<Assignment> assignments;        // one per edge
  std::vector<std::optional<double>> fold_angles;  // radians; nullopt where the file gave null or nothing
  std::vector<std::vector<int>> faces;        // CCW vertex cycles
  bool faces_derived = false;                 // true when faces came from the planar embedding
  // Every key of the frame that rigidfold does not model (file_*, frame_*, faceOrders,
  // vendor keys like "cpedit:page", file_frames ...), kept verbatim for the round trip.
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();
  bool fold_angles_in_file = false;           // the file had edges_foldAngle (written back even if all null)
  std::vector<std::string> warnings;          // non-fatal remarks from reading/validation, with their place
  // How precisely the file places each vertex, where the reader knows it (the SVG reader:
  // svg_reader.hpp, "Precision"): the box, in stored units, that the true position of vertex v
  // lies in, position_bounds.lo[v] <= vertices[v].head<2>() <= position_bounds.hi[v]. Empty
  // when unknown (a FOLD file: coordinate_precision.hpp reads the digits of the coordinates
  // themselves). Kept only while it has one box per vertex; a pass that renumbers vertices
  // without it leaves the sizes unequal, and users then ignore it.
  struct PositionBounds {
    std::vector<Eigen::Vector2d> lo, hi;
    int decimal_places = 0;      // D: most decimals of any coordinate number in the file
    int significant_digits = 0;  // S: most significant digits of any coordinate number
    double max_half_width = 0;   // largest (hi - lo) / 2 over vertices and axes (stored units)
    bool covers(int num_vertices) const {
      return static_cast<int>(lo.size()) == num_vertices && static_cast<int>(hi.size()) == num_vertices;
    }
  };
  PositionBounds position_bounds;

  int num_vertices() const { return static_cast<int>(vertices.size()); }
  int num_edges() const { return static_cast<int>(edges.size()); }
  int num_faces() const { return static_cast<int>(faces.size()); }
};

}  // namespace rigidfold
