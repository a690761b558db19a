#pragma once
// A split crease as the user writes it, `rigidfold sorce --split EDGE:SPEC` (seed 002
// section 10): EDGE the crease's edge index, SPEC the scalar split offset d(t) (the pattern's
// length units), applied along the crease's half-angle direction, d_e(t) = d(t) u(gamma_e/2)
// (eqs 58, 59; PatternSorceRequest::splits):
//   linear:D      d(t) = D t
//   quadratic:D   d(t) = D t^2   (the seed's eq 61 on the bird's-foot vertex: 0.4 t^2)
// D a finite number with |D| <= 1e6 (decimal or exponent form). Both vanish at t = 0 (the
// panels coplanar when flat). Split both collinear creases through a vertex with one spec to
// get the seed's collinear split (sorce_vertex.hpp).
// Throws InputError(place = the whole text, message saying what is wrong); the caller adds
// the flag's name.
#include <string>

#include "design/sorce/sorce_pattern.hpp"

namespace rigidfold::sorce {

PatternSorceRequest::Split parse_split_spec(const std::string& text);

}  // namespace rigidfold::sorce
