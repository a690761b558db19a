#pragma once
// CSV table of the square-twist unit along its motion (seed 003 Fig. 3-19 data): one row per
// sample of theta, columns
//   theta,phi,L,S,H,nu_SL,nu_HL
// theta, phi in radians (fold-angle magnitudes, square_twist_unit.hpp), L, S, H in the unit of
// params.a, the Poisson's ratios dimensionless; numbers with 17 significant digits, so that
// reading them back gives the same doubles. The samples are `samples` equally spaced theta in
// the open interval (0, pi) (k pi / (samples + 1), k = 1..samples): the ratios are 0/0 at the
// ends. Throws std::invalid_argument for samples < 1 or bad params (square_twist_unit), and
// std::runtime_error when the file cannot be written.
#include <ostream>
#include <string>

#include "design/metamaterial/square_twist_unit.hpp"

namespace rigidfold::metamaterial {

inline constexpr const char* kSquareTwistCsvHeader = "theta,phi,L,S,H,nu_SL,nu_HL";

void write_square_twist_csv(std::ostream& out, const SquareTwistUnitParams& params, int samples);
void write_square_twist_csv(const std::string& path, const SquareTwistUnitParams& params, int samples);

}  // namespace rigidfold::metamaterial
