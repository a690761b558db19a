#include "design/sorce/sorce_offsets_spec.hpp"

#include <cmath>

#include "kernel/math/number_text.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"

namespace rigidfold::sorce {
namespace {

double number(const nlohmann::json& v, const std::string& source, const std::string& ptr, double limit) {
  if (!v.is_number()) throw InputError(source + ": " + ptr, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || !(std::abs(x) <= limit))
    throw InputError(source + ": " + ptr, "must be a finite number of magnitude at most " + short_text(limit));
  return x;
}

void per_face(const nlohmann::json& v, const std::string& source, const std::string& ptr, int faces) {
  if (!v.is_array()) throw InputError(source + ": " + ptr, "must be an array with one entry per face");
  if (static_cast<long>(v.size()) != faces)
    throw InputError(source + ": " + ptr, "has " + std::to_string(v.size()) + " entries; the pattern has " + std::to_string(faces) + " faces");
}

}  // namespace

OffsetSpec parse_offset_spec(const std::string& text, const std::string& source, int faces) {
  const nlohmann::json doc = parse_json_input(text, source);
  if (!doc.is_object()) throw InputError(source + ": /", "must be a JSON object");
  for (const auto& item : doc.items())
    if (item.key() != "end_offsets" && item.key() != "coefficients")
      throw InputError(source + ": /" + item.key(), "unknown key (expected end_offsets, coefficients)");
  OffsetSpec spec;
  if (doc.contains("end_offsets")) {
    const nlohmann::json& e = doc["end_offsets"];
    per_face(e, source, "/end_offsets", faces);
    for (std::size_t f = 0; f < e.size(); ++f) spec.end_offsets.push_back(number(e[f], source, "/end_offsets/" + std::to_string(f), 1e300));
  }
  if (doc.contains("coefficients")) {
    const nlohmann::json& c = doc["coefficients"];
    per_face(c, source, "/coefficients", faces);
    for (std::size_t f = 0; f < c.size(); ++f) {
      const std::string ptr = "/coefficients/" + std::to_string(f);
      if (!c[f].is_array() || c[f].size() > 3) throw InputError(source + ": " + ptr, "must be an array of at most 3 numbers");
      std::vector<double> b;
      for (std::size_t k = 0; k < c[f].size(); ++k) b.push_back(number(c[f][k], source, ptr + "/" + std::to_string(k), 100));
      spec.coefficients.push_back(std::move(b));
    }
  }
  return spec;
}

}  // namespace rigidfold::sorce
