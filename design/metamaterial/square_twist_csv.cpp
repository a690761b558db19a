#include "design/metamaterial/square_twist_csv.hpp"

#include <cstdio>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace rigidfold::metamaterial {

void write_square_twist_csv(std::ostream& out, const SquareTwistUnitParams& params, int samples) {
  if (samples < 1) throw std::invalid_argument("square twist CSV: samples must be >= 1");
  out << kSquareTwistCsvHeader << '\n';
  char line[512];
  for (int k = 1; k <= samples; ++k) {
    const double theta = std::numbers::pi * k / (samples + 1);
    const SquareTwistUnitState u = square_twist_unit(params, theta);
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", u.theta, u.phi, u.L, u.S, u.H,
                  u.nu_SL, u.nu_HL);
    out << line;
  }
}

void write_square_twist_csv(const std::string& path, const SquareTwistUnitParams& params, int samples) {
  std::ofstream file(path);
  if (!file) throw std::runtime_error("square twist CSV: cannot open '" + path + "' for writing");
  write_square_twist_csv(file, params, samples);
  file.flush();
  if (!file) throw std::runtime_error("square twist CSV: writing '" + path + "' failed");
}

}  // namespace rigidfold::metamaterial
