#include "kernel/pattern/opx_reader.hpp"
#include "kernel/pattern/read_pattern.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <exception>
#include <optional>
#include <regex>
#include <set>
#include <string_view>
#include <vector>

#include "kernel/pattern/guarded_xml_parser.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/svg_writer.hpp"

namespace rigidfold {
namespace {

constexpr int kTypeAux = 0;
constexpr int kMaxValueChars = 1000;  // the text of one <int>, <double> or field name
constexpr int kNewestFileVersion = 2;  // ORIPA's Version.FILE_MAJOR_VERSION since v1.65

struct OpxLine {
  int index = 0;        // in the lines array
  long xml_line = 0;    // of its <object> in the .opx
  long type = 0;        // as written; checked against the file format once the whole file is read
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // XMLEncoder leaves out properties equal to 0
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// ORIPA's line type codes in a file of format `version` (0: not stated): the letter of a
// crease, nullopt for an auxiliary line; unknown codes are refused by the caller.
bool known_type(long t, int version) { return (t >= 0 && t <= 4) || (version >= 2 && t == 9); }
std::optional<Assignment> type_letter(long t, int version) {
  switch (t) {
    case 1: return Assignment::Boundary;
    case 2: return Assignment::Mountain;
    case 3: return Assignment::Valley;
    case 4: return version >= 2 ? Assignment::Unassigned : Assignment::Cut;
    case 9: return Assignment::Cut;  // format 2 only (known_type)
    default: return std::nullopt;    // 0: auxiliary
  }
}

class OpxParser : public GuardedXmlParser {
 public:
  explicit OpxParser(const std::string& source) : GuardedXmlParser(source) {}

  void parse(const std::string& text) {
    parse_xml(text);
    if (!saw_dataset_) throw InputError(source_, "no <object class=\"oripa.DataSet\"> in <java>: not an ORIPA .opx");
    if (!saw_lines_) throw InputError(source_, "the oripa.DataSet has no \"lines\" property");
  }

  // "CP.opx: lines[3] (line 40)".
  std::string place_of(const OpxLine& l) const {
    return source_ + ": lines[" + std::to_string(l.index) + "] (line " + std::to_string(l.xml_line) + ")";
  }

  std::vector<OpxLine> lines;
  int elements = 0;
  int file_version = 0;      // mainVersion; 0 when the file has none
  bool field_form = false;

 private:
  enum class Role {
    Java,
    DataSet,
    Lines,       // <void property="lines">
    GetField,    // <void class="oripa.DataSet" method="getField">
    FieldName,   // its <string>
    FieldSet,    // <void method="set"> of the field "lines"
    Array,
    Entry,
    LineObject,
    Property,
    Value,
    Version,       // <void property="mainVersion">
    VersionValue,  // its <int>
    Skip
  };
  struct Node {
    Role role;
    std::string property;  // Property: its name
  };

  void start_element(const char* name, const char** atts) override { start(name, atts); }
  void end_element() override { end(); }
  void character_data(const char* text, int len) override {
    if (stack_.empty()) return;
    const Role r = stack_.back().role;
    if (r != Role::Value && r != Role::VersionValue && r != Role::FieldName) return;
    if (text_.size() + len > kMaxValueChars)
      throw InputError(r == Role::Value ? line_place() : here(), "a value longer than " + std::to_string(kMaxValueChars) + " characters");
    text_.append(text, len);
  }

  // The line being read: "CP.opx: lines[3] (line 40)".
  std::string line_place() const { return lines.empty() ? here() : place_of(lines.back()); }

  static const char* attribute(const char** atts, const char* key) {
    for (int i = 0; atts[i]; i += 2)
      if (std::string_view(atts[i]) == key) return atts[i + 1];
    return nullptr;
  }
  static bool is(const char* attr, std::string_view value) { return attr && std::string_view(attr) == value; }
  long integer(std::string_view raw, const std::string& place, const char* what) const {
    const std::string_view t = trim(raw);
    long v = 0;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
      throw InputError(place, std::string(what) + " '" + std::string(raw) + "' is not an integer");
    return v;
  }

  // The <array class="oripa.OriLineProxy" length="N"> of either form.
  void start_lines_array(const std::string& tag, const char* cls, const char** atts) {
    if (tag != "array" || !is(cls, "oripa.OriLineProxy"))
      throw InputError(here(), "lines: <" + tag + "> where <array class=\"oripa.OriLineProxy\"> was expected");
    if (saw_array_) throw InputError(here(), "lines: a second <array>");
    saw_array_ = true;
    const char* length = attribute(atts, "length");
    if (!length) throw InputError(here(), "lines: <array> without length");
    length_ = integer(length, here(), "lines: array length");
    if (length_ < 0 || length_ > kMaxSvgSegments)
      throw InputError(here(), "lines: array length " + std::to_string(length_) + " outside [0, " + std::to_string(kMaxSvgSegments) +
                                   "] (input_limits.hpp)");
    stack_.push_back({Role::Array, {}});
  }

  void start(const char* tag_c, const char** atts) {
    if (++elements > kMaxSvgElements)
      throw InputError(source_, "more than " + std::to_string(kMaxSvgElements) + " XML elements (input_limits.hpp)");
    if (static_cast<int>(stack_.size()) >= kMaxSvgDepth)
      throw InputError(here(), "elements nested more than " + std::to_string(kMaxSvgDepth) + " deep (input_limits.hpp)");
    const std::string tag(tag_c);
    const char* cls = attribute(atts, "class");
    const char* property = attribute(atts, "property");
    const char* method = attribute(atts, "method");
    if (stack_.empty()) {
      if (tag != "java") throw InputError(source_, "root element is <" + tag + ">, not <java>: not an ORIPA .opx");
      stack_.push_back({Role::Java, {}});
      return;
    }
    switch (stack_.back().role) {
      case Role::Java:
        if (tag == "object" && is(cls, "oripa.DataSet") && !saw_dataset_) {
          saw_dataset_ = true;
          if (const char* id = attribute(atts, "id")) dataset_id_ = id;
          stack_.push_back({Role::DataSet, {}});
        } else {
          stack_.push_back({Role::Skip, {}});
        }
        return;
      case Role::DataSet:
        if (tag == "void" && is(property, "lines")) {
          if (saw_lines_) throw InputError(here(), "a second \"lines\" property");
          saw_lines_ = true;
          stack_.push_back({Role::Lines, {}});
        } else if (tag == "void" && is(method, "getField") && (!cls || is(cls, "oripa.DataSet"))) {
          field_name_.reset();
          stack_.push_back({Role::GetField, {}});
        } else if (tag == "void" && is(property, "mainVersion")) {
          stack_.push_back({Role::Version, {}});
        } else {
          stack_.push_back({Role::Skip, {}});  // title, memo, subVersion, paperSize ...
        }
        return;
      case Role::Lines:
        start_lines_array(tag, cls, atts);
        return;
      case Role::GetField:
        if (tag == "string" && !field_name_) {
          text_.clear();
          stack_.push_back({Role::FieldName, {}});
        } else if (tag == "void" && is(method, "set") && field_name_ == "lines") {
          if (saw_lines_) throw InputError(here(), "a second \"lines\" property (set as a field)");
          saw_lines_ = true;
          field_form = true;
          saw_target_ = false;
          stack_.push_back({Role::FieldSet, {}});
        } else {
          stack_.push_back({Role::Skip, {}});  // the field title, memo ... of the DataSet
        }
        return;
      case Role::FieldName:
        throw InputError(here(), "<" + tag + "> inside the name of a field");
      case Role::FieldSet:
        // Field.set(object, value): the DataSet by reference, then the array.
        if (tag == "object" && !saw_target_ && !saw_array_) {
          const char* idref = attribute(atts, "idref");
          if (!idref || (!dataset_id_.empty() && dataset_id_ != idref))
            throw InputError(here(), std::string("lines: set on <object") + (idref ? " idref=\"" + std::string(idref) + "\"" : std::string()) +
                                         ">, not on the oripa.DataSet" + (dataset_id_.empty() ? "" : " (id \"" + dataset_id_ + "\")"));
          saw_target_ = true;
          stack_.push_back({Role::Skip, {}});
          return;
        }
        if (tag == "array" && !saw_target_)
          throw InputError(here(), "lines: the field is set with no <object idref=\"...\"> naming the oripa.DataSet before its <array>");
        start_lines_array(tag, cls, atts);
        return;
      case Role::Array: {
        const char* index = attribute(atts, "index");
        if (tag != "void" || !index) throw InputError(here(), "lines: <" + tag + "> in the array where <void index=\"i\"> was expected");
        const long i = integer(index, here(), "lines: index");
        if (i < 0 || i >= length_)
          throw InputError(here(), "lines: index " + std::to_string(i) + " outside the array of length " + std::to_string(length_));
        if (!indices_.insert(i).second) throw InputError(here(), "lines: index " + std::to_string(i) + " given twice");
        entry_index_ = static_cast<int>(i);
        stack_.push_back({Role::Entry, {}});
        return;
      }
      case Role::Entry: {
        if (tag != "object" || !is(cls, "oripa.OriLineProxy") || attribute(atts, "idref"))
          throw InputError(here(), "lines[" + std::to_string(entry_index_) + "]: <" + tag +
                                       "> where <object class=\"oripa.OriLineProxy\"> was expected");
        OpxLine l;
        l.index = entry_index_;
        l.xml_line = current_line();
        lines.push_back(l);
        seen_.clear();
        stack_.push_back({Role::LineObject, {}});
        return;
      }
      case Role::LineObject:
        if (tag != "void" || !property) throw InputError(line_place(), "<" + tag + "> where <void property=\"...\"> was expected");
        if (!seen_.insert(property).second) throw InputError(line_place(), std::string(property) + ": given twice");
        stack_.push_back({Role::Property, property});
        return;
      case Role::Property:
        if (tag != "int" && tag != "double")
          throw InputError(line_place(), stack_.back().property + ": <" + tag + "> where <int> or <double> was expected");
        text_.clear();
        value_tag_ = tag;
        stack_.push_back({Role::Value, {}});
        return;
      case Role::Value:
        throw InputError(line_place(), "<" + tag + "> inside a number");
      case Role::Version:
        if (tag != "int" || saw_version_) throw InputError(here(), "mainVersion: <" + tag + "> where one <int> was expected");
        saw_version_ = true;
        text_.clear();
        stack_.push_back({Role::VersionValue, {}});
        return;
      case Role::VersionValue:
        throw InputError(here(), "<" + tag + "> inside a number");
      case Role::Skip:
        stack_.push_back({Role::Skip, {}});
        return;
    }
  }

  void end() {
    const Role role = stack_.back().role;
    if (role == Role::Value) {
      const std::string& name = stack_[stack_.size() - 2].property;
      const std::string place = line_place() + ": " + name;
      OpxLine& l = lines.back();
      if (name == "type") {
        if (value_tag_ != "int") throw InputError(place, "<" + value_tag_ + "> where <int> was expected");
        l.type = integer(text_, place, "type");  // its meaning depends on mainVersion, which follows the lines
      } else if (name == "x0" || name == "y0" || name == "x1" || name == "y1") {
        const std::string_view t = trim(text_);
        double v = 0;
        const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
          throw InputError(place, "'" + text_ + "' is not a finite number");
        (name == "x0" ? l.x0 : name == "y0" ? l.y0 : name == "x1" ? l.x1 : l.y1) = v;
      }
      // Other properties of a line (none in ORIPA's files so far) carry nothing here.
    } else if (role == Role::VersionValue) {
      const long v = integer(text_, here() + ": mainVersion", "mainVersion");
      if (v < 0 || v > kNewestFileVersion)
        throw InputError(here() + ": mainVersion", "file format " + std::to_string(v) +
                                                       " is not one of ORIPA's (1, and 2 since ORIPA 1.65); ORIPA itself refuses a newer one");
      file_version = static_cast<int>(v);
    } else if (role == Role::FieldName) {
      field_name_ = std::string(trim(text_));
    } else if (role == Role::Lines || role == Role::FieldSet) {
      if (!saw_array_) throw InputError(here(), "lines: no <array class=\"oripa.OriLineProxy\">");
    }
    stack_.pop_back();
  }

  std::vector<Node> stack_;
  bool saw_dataset_ = false, saw_lines_ = false, saw_array_ = false, saw_target_ = false, saw_version_ = false;
  std::string dataset_id_;
  std::optional<std::string> field_name_;
  long length_ = 0;
  int entry_index_ = 0;
  std::set<long> indices_;
  std::set<std::string> seen_;
  std::string text_, value_tag_;
};

std::string number(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x + 0.0);
  return std::string(buf, r.ptr);
}

}  // namespace

bool is_opx_path(const std::string& path) { return pattern_format_of_path(path) == PatternFormat::Opx; }

CreasePattern arrange_oripa_lines(const std::vector<OripaCreaseLine>& lines, const std::string& source, const SvgReadOptions& options,
                                  SvgImportSummary* summary) {
  // The crease lines as an SVG of one <line> each (ORIPA's y points down, as SVG's), so
  // that they get the SVG import's arrangement, clean-up and validation; <line> #k of it is
  // lines[k - 1].
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\">\n";
  for (const OripaCreaseLine& l : lines) {
    const Assignment a = l.assignment;
    svg += "<line x1=\"" + number(l.x0) + "\" y1=\"" + number(l.y0) + "\" x2=\"" + number(l.x1) + "\" y2=\"" + number(l.y1) + "\" stroke=\"" +
           svg_stroke_colour(a) + "\"" + (has_fold_sign(a) ? " stroke-opacity=\"0\"" : "") + "/>\n";
  }
  svg += "</svg>\n";
  // "<line> #k (line N)" of the SVG -> the name of lines[k - 1].
  static const std::regex element(R"(<line> #(\d+) \(line \d+\))");
  auto rename = [&](const std::string& s) {
    std::string out;
    auto it = std::sregex_iterator(s.begin(), s.end(), element);
    std::size_t last = 0;
    for (; it != std::sregex_iterator(); ++it) {
      const auto& m = *it;
      out += s.substr(last, m.position() - last);
      const std::size_t k = std::stoul(m[1]);
      if (k >= 1 && k <= lines.size())
        out += lines[k - 1].name;
      else
        out += m.str();
      last = m.position() + m.length();
    }
    return out + s.substr(last);
  };
  CreasePattern p;
  try {
    p = parse_svg(svg, source, options, summary);
  } catch (const InputError& e) {
    throw InputError(rename(e.place()), rename(e.message()));
  }
  for (auto& w : p.warnings) w = rename(w);
  if (summary)
    for (MergedLines& m : summary->merged_lines) m.first = rename(m.first), m.second = rename(m.second);
  return p;
}

CreasePattern parse_opx(const std::string& text, const std::string& source, const SvgReadOptions& options, OpxImportSummary* summary_out) {
  OpxParser parser(source);
  parser.parse(text);
  OpxImportSummary summary;
  summary.lines = static_cast<int>(parser.lines.size());
  summary.file_version = parser.file_version;
  summary.field_form = parser.field_form;
  const int version = parser.file_version;
  std::vector<OripaCreaseLine> drawn;
  for (const OpxLine& l : parser.lines) {
    if (!known_type(l.type, version)) {
      std::string known = version >= 2 ? "0 aux, 1 cut, 2 mountain, 3 valley, 4 unassigned, 9 cut; file format 2"
                                       : "0 aux, 1 cut, 2 mountain, 3 valley, 4 cut";
      if (version < 2 && l.type == 9)
        known += std::string("; 9 is a cut only in ORIPA's file format 2, and this file ") +
                 (version == 1 ? "has mainVersion 1" : "states no mainVersion");
      throw InputError(parser.place_of(l) + ": type", "unknown line type " + std::to_string(l.type) + " (" + known + ")");
    }
    ++summary.lines_by_type[l.type];
    const std::optional<Assignment> a = type_letter(l.type, version);
    if (!a) continue;  // auxiliary
    OripaCreaseLine c;
    c.x0 = l.x0, c.y0 = l.y0, c.x1 = l.x1, c.y1 = l.y1;
    c.assignment = *a;
    c.name = "lines[" + std::to_string(l.index) + "] (line " + std::to_string(l.xml_line) + ")";
    drawn.push_back(std::move(c));
  }
  if (drawn.empty())
    throw InputError(source, "no crease lines: " + std::to_string(summary.lines) + " lines, none of type cut, mountain, valley" +
                                 (version >= 2 ? ", unassigned" : "") + " or model cut");
  CreasePattern p = arrange_oripa_lines(drawn, source, options, &summary.arrangement);
  if (summary.lines_by_type[kTypeAux] > 0)
    p.warnings.push_back(source + ": " + std::to_string(summary.lines_by_type[kTypeAux]) + " auxiliary lines (type 0) ignored: they are no creases");
  p.extra["file_creator"] = "rigidfold import (ORIPA .opx)";
  summary.arrangement.elements = parser.elements;
  summary.arrangement.drawn_elements = static_cast<int>(drawn.size());
  summary.arrangement.ignored_elements = summary.lines_by_type[kTypeAux];
  if (summary_out) *summary_out = summary;
  return p;
}

CreasePattern read_opx(const std::string& path, const SvgReadOptions& options, OpxImportSummary* summary) {
  return parse_opx(read_input_file(path), path, options, summary);
}

}  // namespace rigidfold
