#pragma once
// The z component of the cross product of two plane vectors (twice the signed area of the
// triangle they span; > 0 when b turns counter-clockwise from a).
#include <Eigen/Core>

namespace rigidfold {

inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace rigidfold
