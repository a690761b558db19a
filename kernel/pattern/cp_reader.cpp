#include "kernel/pattern/cp_reader.hpp"
#include "kernel/pattern/read_pattern.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>
#include <vector>

#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/opx_reader.hpp"

namespace rigidfold {
namespace {

constexpr int kMaxQuoted = 40;  // characters of a bad field quoted in a message

bool blank(char c) { return c == ' ' || c == '\t'; }

// Calls f(line_number, line) for every line of the text (LF, CRLF or CR), without the end.
template <class F>
void for_each_line(std::string_view text, F&& f) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  long number = 1;
  std::size_t at = 0;
  while (at <= text.size()) {
    std::size_t end = text.find_first_of("\r\n", at);
    if (end == std::string_view::npos) end = text.size();
    if (!f(number, text.substr(at, end - at))) return;
    if (end == text.size()) return;
    at = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
    ++number;
  }
}

std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

std::optional<long> parse_integer(std::string_view t) {
  if (t.size() > 1 && t[0] == '+' && t[1] != '-') t.remove_prefix(1);
  long v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

// A decimal number as Java writes or reads it ("200.0", "-0.0", "1.2E-14", "+3").
std::optional<double> parse_number(std::string_view t) {
  if (t.size() > 1 && t[0] == '+' && t[1] != '-') t.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v, std::chars_format::general);
  if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size()) return std::nullopt;
  return v;
}

std::string quoted(std::string_view t) {
  return "'" + std::string(t.substr(0, kMaxQuoted)) + (t.size() > kMaxQuoted ? "...'" : "'");
}

std::string line_place(const std::string& source, long line) { return source + ": line " + std::to_string(line); }

}  // namespace

bool is_cp_path(const std::string& path) { return pattern_format_of_path(path) == PatternFormat::Cp; }

bool looks_like_cp(const std::string& text) {
  bool yes = false;
  for_each_line(text, [&](long, std::string_view line) {
    const auto f = fields_of(line);
    if (f.empty()) return true;  // blank: look further
    yes = f.size() == 5 && parse_integer(f[0]).has_value();
    for (std::size_t k = 1; yes && k < 5; ++k) yes = parse_number(f[k]).has_value();
    return false;
  });
  return yes;
}

CreasePattern parse_cp(const std::string& text, const std::string& source, const SvgReadOptions& options, CpImportSummary* summary_out) {
  CpImportSummary summary;
  std::vector<OripaCreaseLine> drawn;
  for_each_line(text, [&](long number, std::string_view line) {
    const auto f = fields_of(line);
    if (f.empty()) return true;
    const std::string place = line_place(source, number);
    if (f.size() != 5)
      throw InputError(place, std::to_string(f.size()) + (f.size() == 1 ? " field" : " fields") + " where 5 (type x1 y1 x2 y2) were expected");
    if (summary.lines >= kMaxSvgSegments)
      throw InputError(source, "more than " + std::to_string(kMaxSvgSegments) + " lines (input_limits.hpp)");
    ++summary.lines;
    const std::optional<long> type = parse_integer(f[0]);
    if (!type) throw InputError(place + ": type", quoted(f[0]) + " is not an integer");
    if (*type < 0 || *type > 4)
      throw InputError(place + ": type", "unknown line type " + std::to_string(*type) + " (1 cut, 2 mountain, 3 valley; 0 and 4 auxiliary)");
    static const char* const kNames[4] = {"x1", "y1", "x2", "y2"};
    double c[4];
    for (int k = 0; k < 4; ++k) {
      const std::optional<double> v = parse_number(f[k + 1]);
      if (!v || !std::isfinite(*v)) throw InputError(place + ": " + kNames[k], quoted(f[k + 1]) + " is not a finite number");
      c[k] = *v;
    }
    ++summary.lines_by_type[*type];
    if (*type == 0 || *type == 4) return true;  // auxiliary
    OripaCreaseLine l;
    l.x0 = c[0], l.y0 = c[1], l.x1 = c[2], l.y1 = c[3];
    l.assignment = *type == 1 ? Assignment::Boundary : *type == 2 ? Assignment::Mountain : Assignment::Valley;
    l.name = "line " + std::to_string(number);
    drawn.push_back(std::move(l));
    return true;
  });
  if (summary.lines == 0) throw InputError(source, "no lines: not a .cp crease pattern (lines \"type x1 y1 x2 y2\")");
  if (drawn.empty())
    throw InputError(source, "no crease lines: " + std::to_string(summary.lines) + " lines, none of type 1 (cut), 2 (mountain) or 3 (valley)");
  CreasePattern p = arrange_oripa_lines(drawn, source, options, &summary.arrangement);
  const int aux = summary.lines_by_type[0] + summary.lines_by_type[4];
  if (aux > 0) p.warnings.push_back(source + ": " + std::to_string(aux) + " auxiliary lines (type 0 or 4) ignored: they are no creases");
  p.extra["file_creator"] = "rigidfold import (.cp)";
  summary.arrangement.elements = summary.lines;
  summary.arrangement.drawn_elements = static_cast<int>(drawn.size());
  summary.arrangement.ignored_elements = aux;
  if (summary_out) *summary_out = summary;
  return p;
}

CreasePattern read_cp(const std::string& path, const SvgReadOptions& options, CpImportSummary* summary) {
  return parse_cp(read_input_file(path), path, options, summary);
}

}  // namespace rigidfold
