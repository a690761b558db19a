#include "kernel/pattern/svg_reader.hpp"


#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <regex>
#include <unordered_map>
#include <stdexcept>
#include <string_view>

#include "kernel/pattern/guarded_xml_parser.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/input_limits.hpp"
#include "kernel/pattern/json_input.hpp"
#include "kernel/pattern/loose_end_snap.hpp"
#include "kernel/pattern/planar_arrangement.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/pattern/validate_pattern.hpp"

namespace rigidfold {
namespace {

constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";
constexpr char kNamespaceSeparator = '|';
constexpr int kMaxListedWarnings = 10;
constexpr int kMaxListedMerges = 10;  // warnings about lines drawn twice (the summary lists all)

using Affine = Eigen::Matrix3d;  // homogeneous 2D affine map, last row (0 0 1)

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Reads SVG numbers and separators from a string (path data, points, transform arguments).
// The number grammar is SVG's: sign, digits, fraction, exponent; "10-92" is two numbers and
// "1.5.5" is 1.5 then .5. std::from_chars keeps it locale-independent.
class NumberScanner {
 public:
  explicit NumberScanner(std::string_view s) : s_(s) {}
  void skip_separators() {
    while (pos_ < s_.size() && (is_space(s_[pos_]) || s_[pos_] == ',')) ++pos_;
  }
  void skip_spaces() {
    while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
  }
  bool at_end() {
    skip_separators();
    return pos_ >= s_.size();
  }
  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
  void advance() { ++pos_; }
  std::size_t position() const { return pos_; }
  bool at_number() {
    skip_separators();
    if (pos_ >= s_.size()) return false;
    const char c = s_[pos_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
  }
  // Throws std::invalid_argument with the offset when no number starts here.
  double number() {
    skip_separators();
    std::size_t i = pos_;
    if (i < s_.size() && (s_[i] == '+' || s_[i] == '-')) ++i;
    const std::size_t digits_start = i;
    while (i < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i]))) ++i;
    bool any = i > digits_start;
    int fraction_digits = 0;
    if (i < s_.size() && s_[i] == '.') {
      ++i;
      const std::size_t f = i;
      while (i < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i]))) ++i;
      any = any || i > f;
      fraction_digits = static_cast<int>(i - f);
    }
    if (!any) throw std::invalid_argument("expected a number at character " + std::to_string(pos_ + 1));
    if (i < s_.size() && (s_[i] == 'e' || s_[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < s_.size() && (s_[j] == '+' || s_[j] == '-')) ++j;
      const std::size_t e = j;
      while (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) ++j;
      if (j > e) {  // an 'e' without digits is not part of the number (e.g. "em")
        int exponent = 0;
        std::from_chars(s_.data() + e - (s_[e - 1] == '-' ? 1 : 0), s_.data() + j, exponent);  // saturates silently
        fraction_digits = std::clamp(fraction_digits - exponent, -400, 400);
        i = j;
      }
    }
    std::size_t from = pos_;
    if (s_[from] == '+') ++from;
    double value = 0;
    const auto r = std::from_chars(s_.data() + from, s_.data() + i, value);
    if (r.ec != std::errc() || r.ptr != s_.data() + i || !std::isfinite(value))
      throw std::invalid_argument("number '" + std::string(s_.substr(pos_, i - pos_)) + "' is out of range");
    pos_ = i;
    last_decimals_ = fraction_digits;
    last_magnitude_ = value == 0 ? kNoMagnitude : static_cast<int>(std::floor(std::log10(std::fabs(value))));
    return value;
  }
  std::string_view rest() const { return s_.substr(pos_); }
  // Of the last number read: decimal places as written (1.25e2: 0; 5e-3: 3) and
  // floor(log10 |value|) (kNoMagnitude for 0).
  int last_decimals() const { return last_decimals_; }
  int last_magnitude() const { return last_magnitude_; }
  static constexpr int kNoMagnitude = std::numeric_limits<int>::min();

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  int last_decimals_ = 0;
  int last_magnitude_ = kNoMagnitude;
};

// The rounding of a coordinate as written: how many rounded numbers were added to make it
// (1 for an absolute coordinate, more along a chain of relative path commands), the largest
// magnitude among them, and the unit they were written in (px per unit). The rounding itself,
// which needs the whole file's digits (decimal places D, significant digits S), is
//   count x unit x max(0.5 10^-D, 0.5 10^(magnitude - S + 1))   (coordinate_precision.hpp).
struct WrittenDigits {
  int count = 0;
  int magnitude = NumberScanner::kNoMagnitude;
  double unit = 1;
  WrittenDigits plus(const WrittenDigits& o) const {
    return {count + o.count, std::max(magnitude, o.magnitude), std::max(unit, o.unit)};
  }
};

// A point of the drawing with the digits of its two coordinates.
struct DrawnPoint {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  std::array<WrittenDigits, 2> digits{};
};
using DrawnSegment = std::array<DrawnPoint, 2>;

struct WrittenLength {
  double px = 0;
  int decimals = 0;
  WrittenDigits digits;
};

// A length attribute: a number with an optional absolute unit, in px.
WrittenLength parse_length(std::string_view text) {
  NumberScanner sc(trim(text));
  const double v = sc.number();
  const std::string unit = lower(trim(sc.rest()));
  double scale = 1;
  if (unit.empty() || unit == "px") scale = 1;
  else if (unit == "in") scale = 96;
  else if (unit == "cm") scale = 96 / 2.54;
  else if (unit == "mm") scale = 96 / 25.4;
  else if (unit == "pt") scale = 96.0 / 72;
  else if (unit == "pc") scale = 16;
  else if (unit == "%" || unit == "em" || unit == "ex" || unit == "rem")
    throw std::invalid_argument("relative unit '" + unit + "' is not supported (use px or an absolute unit)");
  else throw std::invalid_argument("'" + std::string(text) + "' is not a length");
  if (!std::isfinite(v * scale)) throw std::invalid_argument("length is out of range");
  return {v * scale, sc.last_decimals(), {1, sc.last_magnitude(), scale}};
}

// transform="..." as one affine map (the functions compose left to right, as SVG applies them).
Affine parse_transform(std::string_view text) {
  Affine m = Affine::Identity();
  NumberScanner sc(text);
  while (!sc.at_end()) {
    std::string name;
    while (std::isalpha(static_cast<unsigned char>(sc.peek()))) {
      name += sc.peek();
      sc.advance();
    }
    if (name.empty()) throw std::invalid_argument("expected a transform function at character " + std::to_string(sc.position() + 1));
    sc.skip_spaces();
    if (sc.peek() != '(') throw std::invalid_argument("expected '(' after " + name);
    sc.advance();
    std::vector<double> a;
    while (sc.at_number()) a.push_back(sc.number());
    sc.skip_separators();
    if (sc.peek() != ')') throw std::invalid_argument("expected ')' to close " + name + "(");
    sc.advance();
    auto need = [&](std::initializer_list<std::size_t> counts) {
      for (std::size_t c : counts)
        if (a.size() == c) return;
      throw std::invalid_argument(name + "() takes " + std::to_string(*counts.begin()) +
                                  (counts.size() > 1 ? " or " + std::to_string(*(counts.end() - 1)) : std::string()) + " numbers, not " +
                                  std::to_string(a.size()));
    };
    Affine t = Affine::Identity();
    const double deg = std::numbers::pi / 180;
    if (name == "matrix") {
      need({6});
      t << a[0], a[2], a[4], a[1], a[3], a[5], 0, 0, 1;
    } else if (name == "translate") {
      need({1, 2});
      t(0, 2) = a[0];
      t(1, 2) = a.size() > 1 ? a[1] : 0;
    } else if (name == "scale") {
      need({1, 2});
      t(0, 0) = a[0];
      t(1, 1) = a.size() > 1 ? a[1] : a[0];
    } else if (name == "rotate") {
      need({1, 3});
      const double c = std::cos(a[0] * deg), s = std::sin(a[0] * deg);
      t << c, -s, 0, s, c, 0, 0, 0, 1;
      if (a.size() == 3) {
        Affine to = Affine::Identity(), back = Affine::Identity();
        to(0, 2) = a[1];
        to(1, 2) = a[2];
        back(0, 2) = -a[1];
        back(1, 2) = -a[2];
        t = to * t * back;
      }
    } else if (name == "skewX") {
      need({1});
      t(0, 1) = std::tan(a[0] * deg);
    } else if (name == "skewY") {
      need({1});
      t(1, 0) = std::tan(a[0] * deg);
    } else {
      throw std::invalid_argument("unknown transform function '" + name + "'");
    }
    m = m * t;
  }
  if (!m.allFinite()) throw std::invalid_argument("transform is not finite");
  return m;
}

struct Rgba {
  int r = 0, g = 0, b = 0;
  double alpha = 1;
};

const std::map<std::string, std::array<int, 3>, std::less<>>& named_colours() {
  // CSS named colours: the basic sixteen, Origami Simulator's names, and common others.
  static const std::map<std::string, std::array<int, 3>, std::less<>> table = {
      {"black", {0, 0, 0}},          {"silver", {192, 192, 192}},   {"gray", {128, 128, 128}},
      {"grey", {128, 128, 128}},     {"white", {255, 255, 255}},    {"maroon", {128, 0, 0}},
      {"red", {255, 0, 0}},          {"purple", {128, 0, 128}},     {"fuchsia", {255, 0, 255}},
      {"magenta", {255, 0, 255}},    {"green", {0, 128, 0}},        {"lime", {0, 255, 0}},
      {"olive", {128, 128, 0}},      {"yellow", {255, 255, 0}},     {"navy", {0, 0, 128}},
      {"blue", {0, 0, 255}},         {"teal", {0, 128, 128}},       {"aqua", {0, 255, 255}},
      {"cyan", {0, 255, 255}},       {"orange", {255, 165, 0}},     {"darkgray", {169, 169, 169}},
      {"darkgrey", {169, 169, 169}}, {"lightgray", {211, 211, 211}}, {"lightgrey", {211, 211, 211}},
      {"darkred", {139, 0, 0}},      {"darkblue", {0, 0, 139}},     {"darkgreen", {0, 100, 0}},
      {"pink", {255, 192, 203}},     {"brown", {165, 42, 42}},      {"gold", {255, 215, 0}},
  };
  return table;
}

// A paint value: none, currentColor, a colour, or something else (a gradient url, an
// unknown name) kept as text for the warning.
struct Paint {
  enum Kind { None, CurrentColor, Colour, Other } kind = None;
  Rgba rgba;
  std::string text;
};

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

double colour_component(std::string_view s, double full) {
  s = trim(s);
  NumberScanner sc(s);
  double v = sc.number();
  const std::string_view unit = trim(sc.rest());
  if (unit == "%") v = v / 100 * full;
  else if (!unit.empty()) throw std::invalid_argument("bad colour component '" + std::string(s) + "'");
  return std::clamp(v, 0.0, full);
}

Paint parse_paint(std::string_view raw) {
  Paint p;
  const std::string s = lower(trim(raw));
  p.text = s;
  if (s == "none") return p;
  if (s == "currentcolor") {
    p.kind = Paint::CurrentColor;
    return p;
  }
  p.kind = Paint::Colour;
  if (!s.empty() && s[0] == '#') {
    const std::string_view h = std::string_view(s).substr(1);
    std::vector<int> d;
    for (char c : h) d.push_back(hex_digit(c));
    if (std::count(d.begin(), d.end(), -1) == 0) {
      if (d.size() == 3 || d.size() == 4) {
        p.rgba = {d[0] * 17, d[1] * 17, d[2] * 17, d.size() == 4 ? d[3] * 17 / 255.0 : 1.0};
        return p;
      }
      if (d.size() == 6 || d.size() == 8) {
        p.rgba = {d[0] * 16 + d[1], d[2] * 16 + d[3], d[4] * 16 + d[5], d.size() == 8 ? (d[6] * 16 + d[7]) / 255.0 : 1.0};
        return p;
      }
    }
    throw std::invalid_argument("'" + s + "' is not a colour");
  }
  if (s.rfind("rgb(", 0) == 0 || s.rfind("rgba(", 0) == 0) {
    const std::size_t open = s.find('('), close = s.rfind(')');
    if (close == std::string::npos || close < open) throw std::invalid_argument("'" + s + "' is not a colour (no ')')");
    std::string inner = s.substr(open + 1, close - open - 1);
    std::replace(inner.begin(), inner.end(), '/', ',');  // CSS 4 "rgb(r g b / a)"
    std::vector<std::string> parts;
    std::string cur;
    for (char c : inner + ",") {
      if (c == ',' || is_space(c)) {
        if (!cur.empty()) parts.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    if (parts.size() != 3 && parts.size() != 4) throw std::invalid_argument("'" + s + "' is not a colour (3 or 4 components)");
    auto to_int = [](double v) { return static_cast<int>(std::lround(v)); };
    p.rgba = {to_int(colour_component(parts[0], 255)), to_int(colour_component(parts[1], 255)),
              to_int(colour_component(parts[2], 255)), parts.size() == 4 ? colour_component(parts[3], 1) : 1.0};
    return p;
  }
  if (auto it = named_colours().find(s); it != named_colours().end()) {
    p.rgba = {it->second[0], it->second[1], it->second[2], 1.0};
    return p;
  }
  p.kind = Paint::Other;  // url(#gradient), a name outside the table: not a crease colour
  return p;
}

double parse_opacity(std::string_view raw) {
  NumberScanner sc(trim(raw));
  double v = sc.number();
  const std::string_view unit = trim(sc.rest());
  if (unit == "%") v /= 100;
  else if (!unit.empty()) throw std::invalid_argument("'" + std::string(raw) + "' is not an opacity");
  return std::clamp(v, 0.0, 1.0);
}

// Origami Simulator's colour table (js/pattern.js typeForStroke), on exact RGB values.
std::optional<Assignment> assignment_for(const Rgba& c) {
  const std::array<int, 3> v = {c.r, c.g, c.b};
  if (v == std::array<int, 3>{0, 0, 0}) return Assignment::Boundary;
  if (v == std::array<int, 3>{255, 0, 0}) return Assignment::Mountain;
  if (v == std::array<int, 3>{0, 0, 255}) return Assignment::Valley;
  if (v == std::array<int, 3>{0, 255, 0} || v == std::array<int, 3>{0, 128, 0}) return Assignment::Cut;
  if (v == std::array<int, 3>{255, 255, 0}) return Assignment::Flat;
  if (v == std::array<int, 3>{255, 0, 255}) return Assignment::Unassigned;
  return std::nullopt;
}

std::string hex(const Rgba& c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

// The inherited drawing state at one element.
struct Frame {
  bool skip = false;  // inside something that is not drawn
  Affine ctm = Affine::Identity();
  std::optional<Paint> stroke;  // unset: nothing in the ancestry set it (SVG default none)
  std::optional<Paint> color;   // the color property, for currentColor
  double stroke_opacity = 1;    // inherited
  double group_opacity = 1;     // product of the ancestors' opacity
};

struct Label {
  Assignment assignment;
  std::optional<double> fold_angle;
  bool operator==(const Label& o) const { return assignment == o.assignment && fold_angle == o.fold_angle; }
};

class SvgParser : public GuardedXmlParser {
 public:
  explicit SvgParser(const std::string& source) : GuardedXmlParser(source) {}

  void parse(const std::string& text) {
    parse_xml(text, kNamespaceSeparator);
    if (!saw_root_) throw InputError(source_, "no <svg> root element");
  }

  std::vector<LabelledSegment> segments;
  std::vector<Label> labels;
  std::vector<std::string> element_names;  // "<line> #3 (line 12)", by segment source
  std::vector<std::string> warnings;
  SvgImportSummary summary;

 private:
  void start_element(const char* name, const char** atts) override { start(name, atts); }
  void end_element() override { stack_.pop_back(); }

  void start(const char* qname, const char** atts) {
    if (++summary.elements > kMaxSvgElements)
      throw InputError(source_, "more than " + std::to_string(kMaxSvgElements) + " XML elements (input_limits.hpp)");
    if (static_cast<int>(stack_.size()) >= kMaxSvgDepth)
      throw InputError(here(), "elements nested more than " + std::to_string(kMaxSvgDepth) + " deep (input_limits.hpp)");
    const std::string_view full(qname);
    std::string_view ns, local = full;
    if (const auto bar = full.find(kNamespaceSeparator); bar != std::string_view::npos) {
      ns = full.substr(0, bar);
      local = full.substr(bar + 1);
    }
    const std::string tag(local);
    const int ordinal = ++tag_count_[tag];
    const std::string place = source_ + ": <" + tag + "> #" + std::to_string(ordinal) + " (line " +
                              std::to_string(current_line()) + ")";
    if (stack_.empty()) {
      if (tag != "svg" || (!ns.empty() && ns != kSvgNamespace)) throw InputError(source_, "root element is <" + tag + ">, not <svg>");
      saw_root_ = true;
      stack_.emplace_back();
    }
    Frame frame = stack_.back();
    const bool foreign = !ns.empty() && ns != kSvgNamespace;
    static const char* const kNotDrawn[] = {"defs", "clipPath", "mask", "symbol", "marker", "pattern", "metadata", "title", "desc",
                                            "linearGradient", "radialGradient", "filter", "foreignObject", "script", "style"};
    if (!frame.skip && !foreign && tag == "style" && !warned_style_) {
      warned_style_ = true;
      warnings.push_back(place + ": <style> sheets are not applied; colours are read from stroke= and style= only");
    }
    if (frame.skip || foreign || std::find(std::begin(kNotDrawn), std::end(kNotDrawn), tag) != std::end(kNotDrawn)) {
      frame.skip = true;
      stack_.push_back(frame);
      return;
    }
    // Presentation attributes first, then style="..." declarations, which take precedence.
    std::map<std::string, std::string, std::less<>> props;
    std::map<std::string, std::string, std::less<>> attrs;
    for (int i = 0; atts[i]; i += 2) {
      std::string_view an(atts[i]);
      if (an.find(kNamespaceSeparator) != std::string_view::npos) continue;  // namespaced attributes
      attrs[std::string(an)] = atts[i + 1];
    }
    static const char* const kProps[] = {"stroke", "stroke-opacity", "opacity", "color", "display"};
    for (const char* k : kProps)
      if (auto it = attrs.find(k); it != attrs.end()) props[k] = it->second;
    if (auto it = attrs.find("style"); it != attrs.end()) {
      std::string_view st = it->second;
      while (!st.empty()) {
        const auto semi = st.find(';');
        const std::string_view decl = st.substr(0, semi);
        st = semi == std::string_view::npos ? std::string_view() : st.substr(semi + 1);
        const auto colon = decl.find(':');
        if (colon == std::string_view::npos) continue;
        std::string key = lower(trim(decl.substr(0, colon)));
        std::string_view value = trim(decl.substr(colon + 1));
        if (const auto bang = value.find('!'); bang != std::string_view::npos) value = trim(value.substr(0, bang));
        if (std::find(std::begin(kProps), std::end(kProps), key) != std::end(kProps)) props[key] = std::string(value);
      }
    }
    auto with_place = [&](const std::string& what, auto&& f) {
      try {
        return f();
      } catch (const std::invalid_argument& e) {
        throw InputError(place + " " + what, e.what());
      }
    };
    if (auto it = props.find("display"); it != props.end() && lower(trim(it->second)) == "none") {
      frame.skip = true;
      stack_.push_back(frame);
      return;
    }
    auto inherit = [](const std::string& v) { return lower(trim(v)) == "inherit"; };
    if (auto it = props.find("color"); it != props.end() && !inherit(it->second))
      frame.color = with_place("color", [&] { return parse_paint(it->second); });
    if (auto it = props.find("stroke"); it != props.end() && !inherit(it->second))
      frame.stroke = with_place("stroke", [&] { return parse_paint(it->second); });
    if (auto it = props.find("stroke-opacity"); it != props.end() && !inherit(it->second))
      frame.stroke_opacity = with_place("stroke-opacity", [&] { return parse_opacity(it->second); });
    if (auto it = props.find("opacity"); it != props.end() && !inherit(it->second))
      frame.group_opacity *= with_place("opacity", [&] { return parse_opacity(it->second); });
    if (auto it = attrs.find("transform"); it != attrs.end())
      frame.ctm = frame.ctm * with_place("transform", [&] { return parse_transform(it->second); });
    stack_.push_back(frame);

    static const char* const kShapes[] = {"line", "polyline", "polygon", "path", "rect"};
    static const char* const kUnread[] = {"circle", "ellipse", "use", "text", "image"};
    const bool shape = std::find(std::begin(kShapes), std::end(kShapes), tag) != std::end(kShapes);
    const bool unread = std::find(std::begin(kUnread), std::end(kUnread), tag) != std::end(kUnread);
    if (!shape && !unread) return;  // svg, g, a, switch ...: containers
    const std::optional<Label> label = label_of(frame, place);
    if (!label) return;
    if (unread) {
      warn(place + ": <" + tag + "> is not read (only line, polyline, polygon, rect and path are crease lines); ignored");
      return;
    }
    auto attr = [&](const char* k) -> std::optional<std::string_view> {
      if (auto it = attrs.find(k); it != attrs.end()) return std::string_view(it->second);
      return std::nullopt;
    };
    auto length = [&](const char* k) {
      const auto v = attr(k);
      if (!v) return WrittenLength{};  // absent: exactly 0
      const WrittenLength l = with_place(k, [&] { return parse_length(*v); });
      note_digits(l.decimals, l.digits.magnitude);
      return l;
    };
    std::vector<DrawnSegment> local_segments;
    if (tag == "line") {
      const WrittenLength x1 = length("x1"), y1 = length("y1"), x2 = length("x2"), y2 = length("y2");
      local_segments.push_back({DrawnPoint{{x1.px, y1.px}, {x1.digits, y1.digits}}, DrawnPoint{{x2.px, y2.px}, {x2.digits, y2.digits}}});
    } else if (tag == "rect") {
      const WrittenLength x = length("x"), y = length("y"), w = length("width"), h = length("height");
      if (w.px < 0 || h.px < 0) throw InputError(place + " width", "negative size");
      if ((attr("rx") && length("rx").px > 0) || (attr("ry") && length("ry").px > 0))
        throw InputError(place + " rx", "rounded corners are curves, not straight creases");
      if (w.px > 0 && h.px > 0) {
        const WrittenDigits xw = x.digits.plus(w.digits), yh = y.digits.plus(h.digits);
        const DrawnPoint c[4] = {{{x.px, y.px}, {x.digits, y.digits}},
                                 {{x.px + w.px, y.px}, {xw, y.digits}},
                                 {{x.px + w.px, y.px + h.px}, {xw, yh}},
                                 {{x.px, y.px + h.px}, {x.digits, yh}}};
        for (int k = 0; k < 4; ++k) local_segments.push_back({c[k], c[(k + 1) % 4]});
      }
    } else if (tag == "polyline" || tag == "polygon") {
      const auto pts = attr("points").value_or("");
      std::vector<DrawnPoint> p;
      with_place("points", [&] {
        NumberScanner sc(pts);
        while (!sc.at_end()) {
          DrawnPoint q;
          q.at.x() = sc.number();
          q.digits[0] = take_digits(sc);
          if (sc.at_end()) throw std::invalid_argument("odd number of coordinates");
          q.at.y() = sc.number();
          q.digits[1] = take_digits(sc);
          p.push_back(q);
          check_segment_count(p.size());
        }
        return 0;
      });
      for (std::size_t k = 0; k + 1 < p.size(); ++k) local_segments.push_back({p[k], p[k + 1]});
      if (tag == "polygon" && p.size() > 2) local_segments.push_back({p.back(), p.front()});
    } else {
      with_place("d", [&] {
        parse_path(attr("d").value_or(""), local_segments);
        return 0;
      });
    }
    ++summary.drawn_elements;
    const int source = static_cast<int>(element_names.size());
    element_names.push_back(place.substr(source_.size() + 2));
    int label_index = static_cast<int>(std::find(labels.begin(), labels.end(), *label) - labels.begin());
    if (label_index == static_cast<int>(labels.size())) labels.push_back(*label);
    for (const auto& [a, b] : local_segments) {
      check_segment_count(0);
      LabelledSegment s;
      s.a = (frame.ctm * Eigen::Vector3d(a.at.x(), a.at.y(), 1)).head<2>();
      s.b = (frame.ctm * Eigen::Vector3d(b.at.x(), b.at.y(), 1)).head<2>();
      segment_digits.push_back({a.digits, b.digits});
      segment_linear.push_back(frame.ctm.topLeftCorner<2, 2>().cwiseAbs());
      if (!s.a.allFinite() || !s.b.allFinite()) throw InputError(place, "a transformed coordinate is not finite");
      s.label = label_index;
      s.source = source;
      segments.push_back(s);
      ++summary.segments;
      ++summary.segments_by_letter[static_cast<int>(label->assignment)];
    }
  }

  void check_segment_count(std::size_t pending) const {
    if (segments.size() + pending > static_cast<std::size_t>(kMaxSvgSegments))
      throw InputError(source_, "more than " + std::to_string(kMaxSvgSegments) + " line segments (input_limits.hpp)");
  }

  void warn(const std::string& w) {
    ++warned_;
    if (warned_ <= kMaxListedWarnings) warnings.push_back(w);
  }

  // The crease letter and fold angle of an element, or nullopt when it is not drawn or not
  // drawn in a crease colour (then warned).
  std::optional<Label> label_of(const Frame& f, const std::string& place) {
    if (!f.stroke || f.stroke->kind == Paint::None) return std::nullopt;  // not stroked: not drawn as a line
    Paint paint = *f.stroke;
    if (paint.kind == Paint::CurrentColor) {
      if (!f.color || f.color->kind != Paint::Colour) {
        ++summary.ignored_elements;
        warn(place + ": stroke currentColor with no colour set; ignored");
        return std::nullopt;
      }
      paint = *f.color;
    }
    std::optional<Assignment> a;
    if (paint.kind == Paint::Colour) a = assignment_for(paint.rgba);
    if (!a) {
      ++summary.ignored_elements;
      warn(place + ": stroke " + (paint.kind == Paint::Colour ? hex(paint.rgba) : "'" + paint.text + "'") +
           " is not a crease colour (black B, red M, blue V, yellow F, magenta U, green C); ignored");
      return std::nullopt;
    }
    Label label{*a, std::nullopt};
    const double opacity = f.group_opacity * f.stroke_opacity * paint.rgba.alpha;
    if (*a == Assignment::Flat) label.fold_angle = 0.0;
    if ((*a == Assignment::Mountain || *a == Assignment::Valley) && opacity > 0)
      label.fold_angle = (*a == Assignment::Mountain ? -1 : 1) * opacity * std::numbers::pi;
    return label;
  }

  // Path data: M L H V Z (absolute and relative, implicit repeats). Curves are refused.
  void parse_path(std::string_view d, std::vector<DrawnSegment>& out) {
    NumberScanner sc(d);
    Eigen::Vector2d cur(0, 0), start(0, 0);
    std::array<WrittenDigits, 2> cur_digits{}, start_digits{};
    char cmd = 0;
    bool first = true;
    while (!sc.at_end()) {
      const char c = sc.peek();
      if (std::isalpha(static_cast<unsigned char>(c))) {
        sc.advance();
        cmd = c;
        if (std::string_view("CcSsQqTtAa").find(c) != std::string_view::npos)
          throw std::invalid_argument(std::string("curve command '") + c + "' is not a straight crease (draw creases with M L H V Z)");
        if (std::string_view("MmLlHhVvZz").find(c) == std::string_view::npos)
          throw std::invalid_argument(std::string("unknown path command '") + c + "' at character " + std::to_string(sc.position()));
        if (first && c != 'M' && c != 'm') throw std::invalid_argument("path data must begin with M or m");
        if (c == 'Z' || c == 'z') {
          if ((cur - start).squaredNorm() > 0) out.push_back({DrawnPoint{cur, cur_digits}, DrawnPoint{start, start_digits}});
          cur = start;
          cur_digits = start_digits;
          continue;
        }
      } else if (cmd == 0 || cmd == 'Z' || cmd == 'z') {
        throw std::invalid_argument("expected a path command at character " + std::to_string(sc.position() + 1));
      }
      const bool rel = std::islower(static_cast<unsigned char>(cmd));
      Eigen::Vector2d next = cur;
      std::array<WrittenDigits, 2> next_digits = cur_digits;
      // A relative coordinate carries the rounding of every number added to make it.
      auto coordinate = [&](int axis, bool relative) {
        const double v = sc.number();
        const WrittenDigits d = take_digits(sc);
        next[axis] = relative ? cur[axis] + v : v;
        next_digits[axis] = relative ? cur_digits[axis].plus(d) : d;
      };
      switch (std::toupper(static_cast<unsigned char>(cmd))) {
        case 'M': {
          // A relative m at the very start is absolute (SVG 1.1, 8.3.2).
          coordinate(0, rel && !first);
          coordinate(1, rel && !first);
          cur = start = next;
          cur_digits = start_digits = next_digits;
          cmd = rel ? 'l' : 'L';  // further pairs are implicit line-tos
          first = false;
          continue;
        }
        case 'L':
          coordinate(0, rel);
          coordinate(1, rel);
          break;
        case 'H':
          coordinate(0, rel);
          break;
        case 'V':
          coordinate(1, rel);
          break;
      }
      if (!next.allFinite()) throw std::invalid_argument("coordinate is not finite");
      if (out.size() + segments.size() >= static_cast<std::size_t>(kMaxSvgSegments))
        throw std::invalid_argument("more than " + std::to_string(kMaxSvgSegments) + " line segments (input_limits.hpp)");
      out.push_back({DrawnPoint{cur, cur_digits}, DrawnPoint{next, next_digits}});
      cur = next;
      cur_digits = next_digits;
    }
  }

  // The file-wide digits of coordinate numbers (WrittenDigits), and one number's digits.
  void note_digits(int decimals, int magnitude) {
    max_decimals = std::max(max_decimals, decimals);
    if (magnitude != NumberScanner::kNoMagnitude) max_significant = std::max(max_significant, decimals + magnitude + 1);
  }
  WrittenDigits take_digits(const NumberScanner& sc) {
    note_digits(sc.last_decimals(), sc.last_magnitude());
    return {1, sc.last_magnitude(), 1};
  }

 public:
  // Per segment of `segments`: the digits of its two ends, and |linear part| of its transform.
  std::vector<std::array<std::array<WrittenDigits, 2>, 2>> segment_digits;
  std::vector<Eigen::Matrix2d> segment_linear;
  int max_decimals = 0, max_significant = 0;

 private:

  std::vector<Frame> stack_;
  std::map<std::string, int> tag_count_;
  bool saw_root_ = false;
  bool warned_style_ = false;
  int warned_ = 0;

 public:
  int unlisted_warnings() const { return std::max(0, warned_ - kMaxListedWarnings); }
};

const char* letter_name(Assignment a) {
  switch (a) {
    case Assignment::Boundary: return "boundary";
    case Assignment::Mountain: return "mountain";
    case Assignment::Valley: return "valley";
    case Assignment::Flat: return "facet";
    case Assignment::Unassigned: return "undriven";
    case Assignment::Cut: return "cut";
    case Assignment::Join: return "join";
  }
  return "?";
}

std::string fmt_point(const Eigen::Vector2d& p) { return "(" + fmt(p.x()) + ", " + fmt(p.y()) + ")"; }

std::string fold_angle_text(const std::optional<double>& a) {
  return a ? fmt(*a * 180 / std::numbers::pi) + " deg" : std::string("none");
}

// Lines drawn twice (svg_reader.hpp): the arrangement's records grouped by pair of elements
// and letters into summary.merged_lines (letter conflicts first, then duplicates, each in
// the order met), and their warnings, at most kMaxListedMerges of them and a tally.
std::vector<std::string> merged_lines(const PlanarArrangement& arr, const SvgParser& parser, const std::string& source,
                                      SvgImportSummary& summary) {
  struct Group {
    const LabelConflict* first;
    int stretches = 0, pieces = 0;
  };
  std::vector<Group> groups;
  std::map<std::array<int, 5>, std::size_t> index;
  for (const auto* list : {&arr.conflicts, &arr.duplicates})
    for (const LabelConflict& c : *list) {
      const std::array<int, 5> key = {c.source_a, c.source_b, c.label_a, c.label_b, c.label_kept};
      auto [it, fresh] = index.emplace(key, groups.size());
      if (fresh) groups.push_back({&c});
      ++groups[it->second].stretches;
      groups[it->second].pieces += c.pieces;
    }
  for (const LabelConflict& c : arr.conflicts) summary.overwritten_edges += c.pieces;
  std::vector<std::string> warnings;
  for (const Group& g : groups) {
    const LabelConflict& c = *g.first;
    const Label &la = parser.labels[c.label_a], &lb = parser.labels[c.label_b], &kept = parser.labels[c.label_kept];
    MergedLines m;
    m.first = parser.element_names[c.source_a];
    m.second = parser.element_names[c.source_b];
    m.first_letter = la.assignment;
    m.second_letter = lb.assignment;
    m.kept_letter = kept.assignment;
    m.first_fold_angle = la.fold_angle;
    m.second_fold_angle = lb.fold_angle;
    m.kept_fold_angle = kept.fold_angle;
    m.rule = c.label_a == c.label_b ? MergedLines::Rule::Duplicate : c.label_kept == c.label_b ? MergedLines::Rule::Later : MergedLines::Rule::Outline;
    m.from[0] = c.from.x(), m.from[1] = c.from.y();
    m.to[0] = c.to.x(), m.to[1] = c.to.y();
    m.stretches = g.stretches;
    m.pieces = g.pieces;
    summary.merged_lines.push_back(m);
    if (static_cast<int>(warnings.size()) >= kMaxListedMerges) continue;
    std::string w = source + ": " + (c.source_a == c.source_b ? m.first + " draws" : m.first + " and " + m.second + " draw") +
                    " the same crease from " + fmt_point(c.from) + " to " + fmt_point(c.to) +
                    (g.stretches > 1 ? " (and at " + std::to_string(g.stretches - 1) + " more places)" : std::string());
    switch (m.rule) {
      case MergedLines::Rule::Duplicate:
        w += std::string(c.source_a == c.source_b ? " twice" : "") + ", both as " + letter_name(la.assignment) + ": merged into one edge";
        break;
      case MergedLines::Rule::Later:
        if (la.assignment == lb.assignment)
          w += " as " + std::string(letter_name(la.assignment)) + " with two opacities (fold angles " + fold_angle_text(la.fold_angle) +
               " and " + fold_angle_text(lb.fold_angle) + "): kept " + fold_angle_text(lb.fold_angle) + " (the later line, as ORIPA's editor does)";
        else
          w += " as " + std::string(letter_name(la.assignment)) + " and " + letter_name(lb.assignment) + ": kept " + letter_name(lb.assignment) +
               " (the later line, as ORIPA's editor does)";
        break;
      case MergedLines::Rule::Outline:
        w += " as " + std::string(letter_name(la.assignment)) + " and " + letter_name(lb.assignment) + ": kept " + letter_name(la.assignment) +
             " (a crease drawn over the paper's outline or a cut does not replace it)";
        break;
    }
    warnings.push_back(w);
  }
  if (static_cast<int>(groups.size()) > kMaxListedMerges)
    warnings.push_back(source + ": ... and " + std::to_string(groups.size() - kMaxListedMerges) +
                       " more pairs of lines drawing the same crease, merged by the same rule (import --json lists each)");
  return warnings;
}

// Faces outside the black boundary: where the drawing's B lines close into loops (every
// vertex on an even number of them), a face is paper when a point just inside it lies
// inside an odd number of those loops (so holes are not paper either). Lines overshooting
// the boundary can close small faces outside it; those faces, and the edges only they use,
// are removed. Keeps `arr` (SVG coordinates, sources) in step with `p`. Returns the count.
int drop_faces_outside_boundary(CreasePattern& p, PlanarArrangement& arr) {
  std::vector<int> b_degree(p.num_vertices(), 0);
  std::vector<int> b_edges;
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] == Assignment::Boundary) {
      b_edges.push_back(e);
      for (int v : p.edges[e]) ++b_degree[v];
    }
  if (b_edges.empty()) return 0;
  for (int d : b_degree)
    if (d % 2) return 0;  // the black lines do not close: no region to test against
  double size = 0;
  for (const auto& v : p.vertices) size = std::max(size, v.head<2>().norm());
  std::vector<char> keep(p.num_faces(), 1);
  int dropped = 0;
  for (int f = 0; f < p.num_faces(); ++f) {
    const auto& face = p.faces[f];
    // The face's longest side; a point a little to its left (faces are counter-clockwise).
    std::size_t k_best = 0;
    double len_best = -1;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const double len = (p.vertices[face[(k + 1) % face.size()]] - p.vertices[face[k]]).norm();
      if (len > len_best) len_best = len, k_best = k;
    }
    const Eigen::Vector2d a = p.vertices[face[k_best]].head<2>(), b = p.vertices[face[(k_best + 1) % face.size()]].head<2>();
    const Eigen::Vector2d d = (b - a) / len_best;
    const double area = 0.5 * std::fabs(newell_normal(p, face).z());
    const double inset = std::min(1e-3 * area / len_best, 1e-9 * std::max(size, 1.0) + 1e-6 * area / len_best);
    const Eigen::Vector2d q = 0.5 * (a + b) + inset * Eigen::Vector2d(-d.y(), d.x());
    bool inside = false;
    for (int e : b_edges) {
      const Eigen::Vector2d u = p.vertices[p.edges[e][0]].head<2>(), w = p.vertices[p.edges[e][1]].head<2>();
      if ((u.y() > q.y()) != (w.y() > q.y()) && q.x() < u.x() + (q.y() - u.y()) * (w.x() - u.x()) / (w.y() - u.y())) inside = !inside;
    }
    if (!inside) {
      keep[f] = 0;
      ++dropped;
    }
  }
  if (dropped == 0 || dropped == p.num_faces()) return 0;
  std::vector<char> used(p.num_edges(), 0);
  std::unordered_map<std::uint64_t, int> edge_of;
  for (int e = 0; e < p.num_edges(); ++e)
    edge_of[(static_cast<std::uint64_t>(std::min(p.edges[e][0], p.edges[e][1])) << 32) | static_cast<std::uint32_t>(std::max(p.edges[e][0], p.edges[e][1]))] = e;
  for (int f = 0; f < p.num_faces(); ++f) {
    if (!keep[f]) continue;
    const auto& face = p.faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int u = face[k], w = face[(k + 1) % face.size()];
      used[edge_of.at((static_cast<std::uint64_t>(std::min(u, w)) << 32) | static_cast<std::uint32_t>(std::max(u, w)))] = 1;
    }
  }
  CreasePattern q;
  q.coords_2d = true;
  q.length_exponent = p.length_exponent;
  const bool bounded = p.position_bounds.covers(p.num_vertices());
  q.position_bounds = p.position_bounds;
  q.position_bounds.lo.clear();
  q.position_bounds.hi.clear();
  q.extra = p.extra;
  q.warnings = p.warnings;
  PlanarArrangement kept = arr;
  kept.vertices.clear();
  kept.vertex_lo.clear();
  kept.vertex_hi.clear();
  kept.edges.clear();
  kept.edge_label.clear();
  kept.edge_source.clear();
  std::vector<int> id(p.num_vertices(), -1);
  auto vertex = [&](int v) {
    if (id[v] < 0) {
      id[v] = q.num_vertices();
      q.vertices.push_back(p.vertices[v]);
      if (bounded) {
        q.position_bounds.lo.push_back(p.position_bounds.lo[v]);
        q.position_bounds.hi.push_back(p.position_bounds.hi[v]);
      }
      kept.vertices.push_back(arr.vertices[v]);
      kept.vertex_lo.push_back(arr.vertex_lo[v]);
      kept.vertex_hi.push_back(arr.vertex_hi[v]);
    }
    return id[v];
  };
  for (int e = 0; e < p.num_edges(); ++e) {
    if (!used[e]) continue;
    q.edges.push_back({vertex(p.edges[e][0]), vertex(p.edges[e][1])});
    q.assignments.push_back(p.assignments[e]);
    q.fold_angles.push_back(p.fold_angles[e]);
    kept.edges.push_back(q.edges.back());
    kept.edge_label.push_back(arr.edge_label[e]);
    kept.edge_source.push_back(arr.edge_source[e]);
  }
  q.fold_angles_in_file = p.fold_angles_in_file;
  for (int f = 0; f < p.num_faces(); ++f) {
    if (!keep[f]) continue;
    std::vector<int> face;
    for (int v : p.faces[f]) face.push_back(vertex(v));
    q.faces.push_back(std::move(face));
  }
  p = std::move(q);
  arr = std::move(kept);
  return dropped;
}

}  // namespace

CreasePattern parse_svg(const std::string& text, const std::string& source, const SvgReadOptions& options, SvgImportSummary* summary_out) {
  if (!(options.merge_tolerance > 0 && options.merge_tolerance < 0.1))
    throw InputError(source, "merge tolerance " + fmt(options.merge_tolerance) + " must lie in (0, 0.1) of the pattern size");
  SvgParser parser(source);
  parser.parse(text);
  SvgImportSummary& summary = parser.summary;
  if (parser.segments.empty())
    throw InputError(source, "no crease lines: no line, polyline, polygon, rect or path is stroked in a crease colour "
                             "(black B, red M, blue V, yellow F, magenta U, green C)");

  Eigen::Vector2d lo = parser.segments[0].a, hi = lo;
  for (const auto& s : parser.segments) {
    lo = lo.cwiseMin(s.a).cwiseMin(s.b);
    hi = hi.cwiseMax(s.a).cwiseMax(s.b);
  }
  summary.pattern_size = (hi - lo).norm();
  if (!(summary.pattern_size > 0) || !std::isfinite(summary.pattern_size))
    throw InputError(source, "the crease lines span no area (size " + fmt(summary.pattern_size) + ")");
  summary.merge_tolerance_relative = options.merge_tolerance;
  summary.merge_tolerance = options.merge_tolerance * summary.pattern_size;

  // The rounding of each segment end (WrittenDigits), through its transform's linear part
  // (the transform's own numbers are taken as exact: a rounded translation, rotation or
  // uniform scale moves the drawing as a whole, which no verdict depends on).
  {
    const int D = std::max(parser.max_decimals, 0);
    const int S = parser.max_significant;
    auto rounding = [&](const WrittenDigits& d) {
      if (d.count == 0) return 0.0;  // an absent attribute: exactly 0
      double u = 0.5 * std::pow(10.0, -D);
      if (d.magnitude != NumberScanner::kNoMagnitude) u = std::max(u, 0.5 * std::pow(10.0, d.magnitude - S + 1));
      return d.count * d.unit * u;
    };
    for (std::size_t k = 0; k < parser.segments.size(); ++k) {
      const auto& [da, db] = parser.segment_digits[k];
      const Eigen::Matrix2d& A = parser.segment_linear[k];
      parser.segments[k].a_rounding = A * Eigen::Vector2d(rounding(da[0]), rounding(da[1]));
      parser.segments[k].b_rounding = A * Eigen::Vector2d(rounding(db[0]), rounding(db[1]));
    }
  }
  ArrangementOptions ao;
  ao.tolerance = summary.merge_tolerance;
  ao.max_candidate_pairs = kMaxSvgCandidatePairs;
  // Lines drawn twice (svg_reader.hpp): B and C over the creases, else the later line.
  for (const Label& l : parser.labels)
    ao.label_priority.push_back(l.assignment == Assignment::Boundary || l.assignment == Assignment::Cut ? 1 : 0);
  auto arrange = [&] {
    try {
      return build_planar_arrangement(parser.segments, ao);
    } catch (const std::length_error& e) {
      throw InputError(source, std::string(e.what()) + " (input_limits.hpp)");
    } catch (const std::invalid_argument& e) {
      throw InputError(source, e.what());
    }
  };
  PlanarArrangement arr = arrange();
  // Lines stopping short of their vertex joined to it (loose_end_snap.hpp), then rebuilt.
  if (!(options.loose_end_snap >= 0) || !std::isfinite(options.loose_end_snap))
    throw InputError(source, "loose-end snap distance " + fmt(options.loose_end_snap) + " must be finite and >= 0");
  summary.loose_end_snap = std::min(options.loose_end_snap, 1e-2 * summary.pattern_size);
  const LooseEndSnap snapped =
      snap_loose_ends(parser.segments, arr, summary.loose_end_snap, summary.merge_tolerance, kMaxSvgCandidatePairs);
  if (snapped.ends_snapped > 0) {
    summary.loose_ends_snapped = snapped.ends_snapped;
    summary.loose_ends_onto_lines = snapped.onto_lines;
    summary.max_snap_distance = snapped.max_distance;
    arr = arrange();
  }
  auto point = [](const Eigen::Vector2d& p) { return "(" + fmt(p.x()) + ", " + fmt(p.y()) + ")"; };
  if (options.strict_lines && !arr.conflicts.empty()) {
    const auto& c = arr.conflicts.front();
    const Label &la = parser.labels[c.label_a], &lb = parser.labels[c.label_b];
    const bool same_letter = la.assignment == lb.assignment;
    throw InputError(source + ": " + parser.element_names[c.source_a] + " and " + parser.element_names[c.source_b],
                     "draw the same crease from " + point(c.from) + " to " + point(c.to) + " " +
                         (same_letter ? "with two opacities (fold angles)" : std::string("as ") + letter_name(la.assignment) + " and " + letter_name(lb.assignment)));
  }
  const std::vector<std::string> merge_warnings = merged_lines(arr, parser, source, summary);
  summary.crossings = arr.crossings;
  summary.touches = arr.touches;
  summary.merged_points = arr.merged_points;
  summary.max_merge_distance = arr.max_merge_distance;
  summary.duplicate_edges = arr.duplicate_edges;
  summary.collinear_vertices_removed = arr.collinear_vertices_removed;
  summary.zero_length_segments = arr.zero_length_segments;

  // Dangling lines (an end on no other line: overshoots, a crease stopping inside a face)
  // divide no face, so they cannot fold; they are removed, chains of them included.
  std::vector<std::string> dangling_names;
  double dangling_longest = 0;
  {
    const int nv = static_cast<int>(arr.vertices.size()), ne = static_cast<int>(arr.edges.size());
    std::vector<std::vector<int>> incident(nv);
    for (int e = 0; e < ne; ++e)
      for (int v : arr.edges[e]) incident[v].push_back(e);
    std::vector<int> degree(nv);
    for (int v = 0; v < nv; ++v) degree[v] = static_cast<int>(incident[v].size());
    std::vector<char> gone(ne, 0);
    std::vector<int> work;
    for (int v = 0; v < nv; ++v)
      if (degree[v] == 1) work.push_back(v);
    while (!work.empty()) {
      const int v = work.back();
      work.pop_back();
      if (degree[v] != 1) continue;
      for (int e : incident[v]) {
        if (gone[e]) continue;
        gone[e] = 1;
        ++summary.dangling_edges_removed;
        dangling_longest = std::max(dangling_longest, (arr.vertices[arr.edges[e][0]] - arr.vertices[arr.edges[e][1]]).norm());
        if (dangling_names.size() < 3) dangling_names.push_back(parser.element_names[arr.edge_source[e]]);
        for (int w : arr.edges[e])
          if (--degree[w] == 1) work.push_back(w);
        break;
      }
    }
    PlanarArrangement kept = arr;
    kept.vertices.clear();
    kept.vertex_lo.clear();
    kept.vertex_hi.clear();
    kept.edges.clear();
    kept.edge_label.clear();
    kept.edge_source.clear();
    std::vector<int> id(nv, -1);
    for (int e = 0; e < ne; ++e) {
      if (gone[e]) continue;
      std::array<int, 2> edge{};
      for (int k = 0; k < 2; ++k) {
        const int v = arr.edges[e][k];
        if (id[v] < 0) {
          id[v] = static_cast<int>(kept.vertices.size());
          kept.vertices.push_back(arr.vertices[v]);
          kept.vertex_lo.push_back(arr.vertex_lo[v]);
          kept.vertex_hi.push_back(arr.vertex_hi[v]);
        }
        edge[k] = id[v];
      }
      kept.edges.push_back(edge);
      kept.edge_label.push_back(arr.edge_label[e]);
      kept.edge_source.push_back(arr.edge_source[e]);
    }
    arr = std::move(kept);
    if (arr.edges.empty()) throw InputError(source, "the crease lines enclose no face (every line is dangling)");
  }

  CreasePattern p;
  p.coords_2d = true;
  // SVG's y points down (0 - y, not -y: no -0 in the written FOLD).
  for (const auto& v : arr.vertices) p.vertices.emplace_back(v.x(), 0.0 - v.y(), 0.0);
  p.edges = arr.edges;
  for (int label : arr.edge_label) {
    p.assignments.push_back(parser.labels[label].assignment);
    p.fold_angles.push_back(parser.labels[label].fold_angle);
    p.fold_angles_in_file = p.fold_angles_in_file || parser.labels[label].fold_angle.has_value();
  }
  p.extra["file_creator"] = "rigidfold import (SVG, Origami Simulator colours)";
  p.extra["frame_classes"] = {"creasePattern"};
  p.warnings = parser.warnings;
  if (parser.unlisted_warnings() > 0)
    p.warnings.push_back(source + ": ... and " + std::to_string(parser.unlisted_warnings()) + " more elements ignored");
  p.warnings.insert(p.warnings.end(), merge_warnings.begin(), merge_warnings.end());
  if (arr.merged_points > 0)
    p.warnings.push_back(source + ": " + std::to_string(arr.merged_points) + " near-coincident points merged into vertices (tolerance " +
                         fmt(summary.merge_tolerance) + " = " + fmt(options.merge_tolerance) + " x pattern size " + fmt(summary.pattern_size) +
                         "; largest move " + fmt(arr.max_merge_distance) + ")");
  if (snapped.ends_snapped > 0)
    p.warnings.push_back(source + ": " + std::to_string(snapped.ends_snapped) + " loose line ends joined to the " +
                         (snapped.onto_lines == snapped.ends_snapped ? std::string("line")
                          : snapped.onto_lines > 0                   ? std::string("vertex or line")
                                                                     : std::string("vertex")) +
                         " they stop short of (largest move " + fmt(snapped.max_distance) + ", snap distance " +
                         fmt(summary.loose_end_snap) +
                         (summary.loose_end_snap == 3.0 ? " = Origami Simulator's vertex tolerance" : std::string()) + "; e.g. " +
                         parser.element_names[snapped.source_example] + ")");
  if (snapped.skipped_too_many)
    p.warnings.push_back(source + ": too many loose line ends to join them to their vertices (input_limits.hpp); they are removed as dangling");
  if (summary.dangling_edges_removed > 0) {
    std::string names;
    for (const auto& n : dangling_names) names += (names.empty() ? "" : ", ") + n;
    p.warnings.push_back(source + ": " + std::to_string(summary.dangling_edges_removed) +
                         " dangling line pieces removed (an end on no other line: they divide no face; longest " + fmt(dangling_longest) +
                         "; drawn by " + names + (summary.dangling_edges_removed > static_cast<int>(dangling_names.size()) ? ", ..." : "") + ")");
  }
  auto validate = [&] {
    try {
      complete_and_validate(p, source);
    } catch (const InputError& e) {
      // Name the drawing: the FOLD paths mean nothing to the author of an SVG.
      std::smatch m;
      const std::string what = e.what();
      std::string where;
      if (std::regex_search(what, m, std::regex(R"(edges_vertices\[(\d+)\])"))) {
        const std::size_t k = std::stoul(m[1]);
        if (k < arr.edges.size())
          where = " [the " + std::string(letter_name(p.assignments[k])) + " line from " + point(arr.vertices[arr.edges[k][0]]) + " to " +
                  point(arr.vertices[arr.edges[k][1]]) + ", drawn by " + parser.element_names[arr.edge_source[k]] + "]";
      } else if (std::regex_search(what, m, std::regex(R"(vertices_coords\[(\d+)\])"))) {
        const std::size_t k = std::stoul(m[1]);
        if (k < arr.vertices.size()) where = " [the point " + point(arr.vertices[k]) + " of the drawing]";
      }
      throw InputError(e.place(), e.message() + where);
    }
  };
  // How precisely each vertex is placed (CreasePattern::position_bounds): the boxes of the
  // arrangement, in FOLD's axes (y flipped).
  p.position_bounds.decimal_places = parser.max_decimals;
  p.position_bounds.significant_digits = parser.max_significant;
  for (std::size_t v = 0; v < arr.vertices.size(); ++v) {
    p.position_bounds.lo.emplace_back(arr.vertex_lo[v].x(), 0.0 - arr.vertex_hi[v].y());
    p.position_bounds.hi.emplace_back(arr.vertex_hi[v].x(), 0.0 - arr.vertex_lo[v].y());
    const Eigen::Vector2d half = 0.5 * (arr.vertex_hi[v] - arr.vertex_lo[v]);
    p.position_bounds.max_half_width = std::max(p.position_bounds.max_half_width, half.maxCoeff());
  }
  const std::vector<std::string> base_warnings = p.warnings;
  validate();
  summary.faces_outside_boundary_removed = drop_faces_outside_boundary(p, arr);
  if (summary.faces_outside_boundary_removed > 0) {
    p.warnings = base_warnings;  // the first pass's remarks were about the removed faces
    p.warnings.push_back(source + ": " + std::to_string(summary.faces_outside_boundary_removed) +
                         " faces outside the black boundary removed (lines drawn past the boundary)");
    validate();
  }
  summary.shortest_edge = std::numeric_limits<double>::infinity();
  int shortest = 0;
  for (int e = 0; e < p.num_edges(); ++e) {
    const double len = (arr.vertices[arr.edges[e][0]] - arr.vertices[arr.edges[e][1]]).norm();
    if (len < summary.shortest_edge) summary.shortest_edge = len, shortest = e;
  }
  if (summary.shortest_edge < 10 * summary.merge_tolerance)
    p.warnings.push_back(source + ": shortest edge " + fmt(summary.shortest_edge) + " from " + point(arr.vertices[arr.edges[shortest][0]]) +
                         " to " + point(arr.vertices[arr.edges[shortest][1]]) + " is within 10 x the merge tolerance " +
                         fmt(summary.merge_tolerance) + ": lines that miss each other slightly? (import --merge-tolerance)");
  if (summary_out) *summary_out = summary;
  return p;
}

std::string_view merged_lines_rule_name(MergedLines::Rule rule) {
  switch (rule) {
    case MergedLines::Rule::Duplicate: return "same";
    case MergedLines::Rule::Later: return "later";
    case MergedLines::Rule::Outline: return "outline";
  }
  return "?";
}

CreasePattern read_svg(const std::string& path, const SvgReadOptions& options, SvgImportSummary* summary) {
  return parse_svg(read_input_file(path), path, options, summary);
}

}  // namespace rigidfold
