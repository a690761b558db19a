#pragma once
// Validators for numeric command-line flags (CLI11). A number that enters through a flag is
// checked where it enters: NaN and +-inf are refused (CLI11's PositiveNumber lets "nan"
// through, since every comparison with NaN is false), and a documented range is a closed
// range [lo, hi]. CLI11 names the flag in the error ("--tolerance-deg: ..."), and run_cli
// turns it into exit status 2.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::cli {

// The flag's text as a finite double; an error text otherwise (empty on success).
inline std::string finite_number_error(const std::string& text, double& value) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtod(begin, &end);
  if (end == begin || *end != '\0') return "'" + text + "' is not a number";
  if (!std::isfinite(value) || (errno == ERANGE && std::fabs(value) > 1.0))
    return "'" + text + "' is not a finite number";
  return {};
}

// Any finite number.
inline CLI::Validator finite_number() {
  return CLI::Validator(
      [](std::string& text) {
        double v;
        return finite_number_error(text, v);
      },
      "FINITE", "finite");
}

// A finite number in the closed range [lo, hi]; unit names it in the message ("degrees").
inline CLI::Validator finite_in(double lo, double hi, const std::string& unit = "") {
  char range[96];
  std::snprintf(range, sizeof range, "[%.17g, %.17g]%s%s", lo, hi, unit.empty() ? "" : " ", unit.c_str());
  const std::string r = range;
  return CLI::Validator(
      [lo, hi, r](std::string& text) {
        double v;
        std::string err = finite_number_error(text, v);
        if (err.empty() && !(v >= lo && v <= hi)) err = text + " is outside " + r;
        return err;
      },
      "in " + r, "finite_in");
}

// --tolerance auto|exact|U (check, trace): how far each coordinate may lie from the true one,
// in the file's length unit. nullopt for auto (read off the input), 0 for exact; anything
// else that is not a finite number >= 0 is an InputError naming `flag`.
inline std::optional<double> coordinate_tolerance_flag(const std::string& flag, const std::string& text) {
  if (text == "auto") return std::nullopt;
  if (text == "exact") return 0.0;
  double u = -1;
  if (!finite_number_error(text, u).empty() || u < 0)
    throw InputError(flag, "'" + text + "' is not auto, exact or a finite number >= 0");
  return u;
}

}  // namespace rigidfold::cli

namespace rigidfold::cli {

// Adds finite_number() to every floating-point option (CLI11 type name "FLOAT") of app and
// of its subcommands, recursively: no double flag of any command accepts NaN or +-inf,
// including flags added later. Call once, after every command is registered.
inline void require_finite_numbers(CLI::App& app) {
  for (CLI::Option* opt : app.get_options())
    if (opt->get_type_name().rfind("FLOAT", 0) == 0) opt->check(finite_number());
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) require_finite_numbers(*sub);
}

}  // namespace rigidfold::cli
