#pragma once
// The symmetry group of a flat crease pattern, computed from its geometry: every rotation
// and reflection of the plane that maps vertices onto vertices and edges onto edges, with
// creases (M, V, U) onto creases, boundary onto boundary and F/J onto F/J (the letters M and
// V themselves are not compared: the group acts on assignments).
//
// Every symmetry of a finite point set fixes its centroid c, and is fixed by the image of one
// vertex p0 farthest from c: candidates are the rotations about c taking p0 to each vertex at
// the same distance and the reflections across the bisecting line through c; each is kept
// when it maps the whole pattern onto itself (vertex positions matched within
// `relative_tolerance` x the pattern's size).
// A reflection of the sheet in the plane keeps mountains mountains (it is a mirror of the
// folded state through a vertical plane), so each element maps an assignment a to
// a'[edge_map[e]] = a[e].
#include <Eigen/Core>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

struct PatternSymmetry {
  Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();  // orthogonal, about `center`
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  bool reflection = false;
  double rotation_angle = 0.0;  // radians, rotations only (in [0, 2 pi))
  std::vector<int> vertex_map;  // vertex v goes to vertex_map[v]
  std::vector<int> edge_map;    // edge e goes to edge_map[e]
};

// The group, identity first. Throws std::invalid_argument when the pattern is not flat
// (a vertex with z != 0).
std::vector<PatternSymmetry> pattern_symmetries(const CreasePattern& pattern, double relative_tolerance = 1e-7);

}  // namespace rigidfold
