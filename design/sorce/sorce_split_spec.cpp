#include "design/sorce/sorce_split_spec.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "kernel/pattern/input_error.hpp"

namespace rigidfold::sorce {
namespace {

// The whole of `s` as a number, or NaN.
double whole_number(const std::string& s) {
  if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return std::nan("");
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || errno == ERANGE) return std::nan("");
  return x;
}

// The whole of `s` as a non-negative integer that fits an int, or -1.
int whole_index(const std::string& s) {
  if (s.empty() || s.size() > 9) return -1;
  int x = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return -1;
    x = 10 * x + (c - '0');
  }
  return x;
}

}  // namespace

PatternSorceRequest::Split parse_split_spec(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) throw InputError(text, "expected EDGE:SPEC, e.g. 0:linear:0.05");
  PatternSorceRequest::Split out;
  out.edge = whole_index(text.substr(0, colon));
  if (out.edge < 0) throw InputError(text, "EDGE must be an edge index (a non-negative integer)");
  const std::string spec = text.substr(colon + 1);
  const std::size_t second = spec.find(':');
  const std::string kind = spec.substr(0, second);
  if (kind != "linear" && kind != "quadratic")
    throw InputError(text, "SPEC must be linear:D or quadratic:D (d(t) = D t or D t^2)");
  if (second == std::string::npos) throw InputError(text, "SPEC " + kind + " needs its size, " + kind + ":D");
  const double d = whole_number(spec.substr(second + 1));
  if (!std::isfinite(d) || !(std::abs(d) <= 1e6)) throw InputError(text, "D must be a finite number with |D| <= 1e6");
  out.d = power_function(d, kind == "linear" ? 1 : 2);
  return out;
}

}  // namespace rigidfold::sorce
