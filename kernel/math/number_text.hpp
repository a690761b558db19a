#pragma once
// Numbers as text in messages and outputs: a fold angle in degrees or any magnitude for people
// (6 significant digits) and a double that reads back bit for bit (17 significant digits).
#include <cstdio>
#include <string>

#include "kernel/math/angle_units.hpp"

namespace rigidfold {

// radians -> "12.3457" (degrees, %.6g).
inline std::string degrees_text(double radians) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", to_degrees(radians));
  return buf;
}

// x -> "%.6g": a tolerance or a magnitude in a message ("1e-09", not std::to_string's "0.000000").
inline std::string short_text(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// x -> "%.17g": the shortest format that round-trips every double.
inline std::string round_trip_text(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

}  // namespace rigidfold
