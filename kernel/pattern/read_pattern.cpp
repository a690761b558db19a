#include "kernel/pattern/read_pattern.hpp"

#include <algorithm>
#include <cctype>

#include "kernel/pattern/cp_reader.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/opx_reader.hpp"
#include "kernel/pattern/svg_reader.hpp"

namespace rigidfold {
namespace {

std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// The text after a UTF-8 byte order mark and leading white space.
std::string_view content_start(std::string_view t) {
  if (t.substr(0, 3) == "\xEF\xBB\xBF") t.remove_prefix(3);
  while (!t.empty() && std::isspace(static_cast<unsigned char>(t.front()))) t.remove_prefix(1);
  return t;
}

// The local name of the root element of XML text starting with '<' (after the declaration,
// processing instructions, comments and a document type); "" when there is none.
std::string root_element(std::string_view t) {
  std::size_t i = 0;
  while (i < t.size()) {
    while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
    if (i >= t.size() || t[i] != '<') return "";
    if (t.substr(i, 2) == "<?") {
      const std::size_t end = t.find("?>", i + 2);
      if (end == std::string_view::npos) return "";
      i = end + 2;
    } else if (t.substr(i, 4) == "<!--") {
      const std::size_t end = t.find("-->", i + 4);
      if (end == std::string_view::npos) return "";
      i = end + 3;
    } else if (t.substr(i, 2) == "<!") {  // <!DOCTYPE ... [ internal subset ] >
      bool subset = false;
      char quote = 0;
      for (i += 2; i < t.size(); ++i) {
        const char c = t[i];
        if (quote) {
          if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
          quote = c;
        } else if (c == '[') {
          subset = true;
        } else if (c == ']') {
          subset = false;
        } else if (c == '>' && !subset) {
          break;
        }
      }
      if (i >= t.size()) return "";
      ++i;
    } else {
      std::size_t end = i + 1;
      while (end < t.size() && !std::isspace(static_cast<unsigned char>(t[end])) && t[end] != '/' && t[end] != '>') ++end;
      std::string name(t.substr(i + 1, end - i - 1));
      if (const std::size_t colon = name.find(':'); colon != std::string::npos) name = name.substr(colon + 1);
      return name;
    }
  }
  return "";
}

// The first characters of the content, for the message refusing it.
std::string beginning(std::string_view t) {
  t = content_start(t);
  std::string out;
  for (char c : t.substr(0, 24)) {
    if (c == '\n' || c == '\r') break;
    const auto u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u >= 0x7f) ? '?' : c;
  }
  return out + (t.size() > out.size() && out.size() == 24 ? "..." : "");
}

}  // namespace

bool is_svg_path(const std::string& path) { return pattern_format_of_path(path) == PatternFormat::Svg; }

PatternFormat pattern_format_of_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".fold") return PatternFormat::Fold;
  if (ext == ".svg") return PatternFormat::Svg;
  if (ext == ".opx") return PatternFormat::Opx;
  if (ext == ".cp") return PatternFormat::Cp;
  return PatternFormat::Unknown;
}

PatternFormat detect_pattern_format(const std::string& text) {
  const std::string_view t = content_start(text);
  if (t.empty()) return PatternFormat::Unknown;
  if (t.front() == '{' || t.front() == '[') return PatternFormat::Fold;
  if (t.front() == '<') {
    const std::string root = root_element(t);
    if (root == "java") return PatternFormat::Opx;
    if (root == "svg") return PatternFormat::Svg;
    return PatternFormat::Unknown;
  }
  if (looks_like_cp(text)) return PatternFormat::Cp;
  return PatternFormat::Unknown;
}

std::string_view pattern_format_name(PatternFormat format) {
  switch (format) {
    case PatternFormat::Fold: return "FOLD";
    case PatternFormat::Svg: return "SVG";
    case PatternFormat::Opx: return "ORIPA .opx";
    case PatternFormat::Cp: return ".cp";
    case PatternFormat::Unknown: break;
  }
  return "unknown";
}

PatternFormat pattern_format_to_read(const std::string& text, const std::string& source) {
  const PatternFormat named = pattern_format_of_path(source);
  const PatternFormat format = detect_pattern_format(text);
  if (format != PatternFormat::Unknown) return format;
  if (named == PatternFormat::Svg || named == PatternFormat::Opx || named == PatternFormat::Cp)
    return named;  // its reader says what is wrong, in its terms
  if (content_start(text).empty()) return PatternFormat::Fold;  // "file is empty"
  throw InputError(source, "not a FOLD, SVG, ORIPA .opx or .cp file (it begins \"" + beginning(text) + "\")");
}

CreasePattern parse_pattern(const std::string& text, const std::string& source, const SvgReadOptions& options, SvgImportSummary* summary,
                            PatternFormat* format_out) {
  const PatternFormat named = pattern_format_of_path(source);
  const PatternFormat format = pattern_format_to_read(text, source);
  CreasePattern p;
  switch (format) {
    case PatternFormat::Svg: p = parse_svg(text, source, options, summary); break;
    case PatternFormat::Opx: {
      OpxImportSummary s;
      p = parse_opx(text, source, options, &s);
      if (summary) *summary = s.arrangement;
      break;
    }
    case PatternFormat::Cp: {
      CpImportSummary s;
      p = parse_cp(text, source, options, &s);
      if (summary) *summary = s.arrangement;
      break;
    }
    default: p = parse_fold(text, source); break;
  }
  if (named != PatternFormat::Unknown && named != format)
    p.warnings.push_back(source + ": read as " + std::string(pattern_format_name(format)) + " by its content, though its extension says " +
                         std::string(pattern_format_name(named)));
  if (format_out) *format_out = format;
  return p;
}

CreasePattern parse_pattern(const std::string& text, const std::string& source) { return parse_pattern(text, source, SvgReadOptions{}); }

CreasePattern read_pattern(const std::string& path) { return parse_pattern(read_input_file(path), path); }

CreasePattern read_pattern(const std::string& path, const SvgReadOptions& options, SvgImportSummary* summary, PatternFormat* format) {
  return parse_pattern(read_input_file(path), path, options, summary, format);
}

}  // namespace rigidfold
