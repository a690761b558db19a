#pragma once
// The precision a file's coordinates were written with, read off the numbers themselves
// (the tolerance comes from the input): a pattern exported with 6 decimals carries sector
// angles known to ~1e-6 and cannot be judged in exact arithmetic.
//
// Method: each coordinate c is given the fewest decimal places d (0..17; none: the file is
// not read as rounded) for which c lies
// within two units in its last place of the double nearest to round(c 10^d) / 10^d (two ulps:
// the coordinate may have gone through a translation or a sign change after it was written,
// as an SVG's are), and its significant digits s = d + floor(log10|c|) + 1.
// A writer rounds either to a fixed number of decimals D (the largest d in the file) or to
// a fixed number of significant digits S (the largest s); the rounding of coordinate c is
// then at most half a unit in its last place under either reading, and the bound taken is
// the larger of the two:
//     u(c) = max(0.5 10^-D, 0.5 10^(floor(log10|c|) - S + 1), 2^-52 |c|) + 2^-51 |c|
// (the last term: the two ulps). A coordinate written with fewer places than
// its neighbours (0.25 among 0.466968) is an exact value or rounded the same way; both
// readings cover it.
//
// Single precision: a file whose every coordinate is exactly a float32 value, and not all
// short decimals, was written from float32 numbers (Origami Simulator's exports: 0.7071067690849304
// for sqrt(1/2)). Their rounding is half a float32 ulp of the value; the writer computed them
// in float32 too (a flat sheet rotated into 3D carries 1e-22 in place of 0), so the bound
// taken is half an ulp at the sheet's scale, u = 2^-24 max|c| over the file, for every
// coordinate (plus the two double ulps).
//
// Stated precision (`--tolerance U`): the user says how far each coordinate may lie from the
// true one, U in the file's length unit, overriding what the digits say; U = 0 ("exact")
// judges the numbers as they are, with no "within the input's precision" verdicts.
//
// Units: the pattern's length unit (coordinates as stored in CreasePattern::vertices).
#include <optional>
#include <string>
#include <vector>

#include "kernel/pattern/crease_pattern.hpp"

namespace rigidfold {

struct CoordinatePrecision {
  int decimal_places = 0;        // D: the most decimals any coordinate needs
  int significant_digits = 0;    // S: the most significant digits any coordinate needs
  double max_rounding = 0.0;     // max over coordinates of u(c)
  std::vector<double> vertex_rounding;  // per vertex: max u(c) over its three coordinates
  // True when every coordinate needs at most 15 significant digits: the file was rounded
  // (a full double needs 16-17 digits for most values).
  bool rounded = false;
  bool single_precision = false;  // every coordinate is a float32 value (see above); rounded too
  bool stated = false;            // the bound was given by the user (stated_precision), not read
};

// One phrase for reports: "coordinates written with 6 decimals (rounding <= 5e-07)" or
// "float32 coordinates (rounding <= 4.2e-08)".
std::string describe_precision(const CoordinatePrecision& precision);

CoordinatePrecision coordinate_precision(const CreasePattern& pattern);

// The user's bound: every coordinate within `tolerance` (the file's length unit, >= 0) of the
// true one; rounded = tolerance > 0.
CoordinatePrecision stated_precision(const CreasePattern& pattern, double tolerance);

// The precision every verdict uses: stated_precision when a tolerance is given, otherwise
// coordinate_precision (read off the digits).
CoordinatePrecision input_precision(const CreasePattern& pattern, std::optional<double> stated_tolerance);

// One phrase for the precision a verdict used, whatever its source: the stated bound, an
// SVG's drawn points (CreasePattern::position_bounds), the digits, or exact data.
std::string describe_input_precision(const CreasePattern& pattern, std::optional<double> stated_tolerance);

}  // namespace rigidfold
