#pragma once
// Angle units. The kernel works in radians; degrees appear only at the edges (CLI flags, JSON
// keys ending in _deg, FOLD files). Convert with these, never with a local constant: a local
// `kDeg` meant 180/pi in some files and pi/180 in others.
#include <numbers>

namespace rigidfold {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

// Radians -> degrees.
constexpr double to_degrees(double radians) { return radians * kDegreesPerRadian; }
// Degrees -> radians.
constexpr double to_radians(double degrees) { return degrees * kRadiansPerDegree; }

}  // namespace rigidfold
