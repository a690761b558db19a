#include "kernel/pattern/dxf_document.hpp"

#include <charconv>
#include <stdexcept>

namespace rigidfold {
namespace {

// One group: its code and value, each on its own line.
void group(std::string& s, int code, const std::string& value) {
  s += std::to_string(code);
  s += '\n';
  s += value;
  s += '\n';
}

void point(std::string& s, int code, const Eigen::Vector2d& p) {
  group(s, code, dxf_number(p.x()));
  group(s, code + 10, dxf_number(p.y()));
  group(s, code + 20, "0");
}

}  // namespace

std::string dxf_number(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x + 0.0);  // shortest round trip; no -0
  return std::string(buf, r.ptr);
}

void DxfDocument::add_layer(const std::string& name, int colour) {
  group(layers_, 0, "LAYER");
  group(layers_, 2, name);
  group(layers_, 70, "0");
  group(layers_, 62, std::to_string(colour));
  group(layers_, 6, "CONTINUOUS");
  ++layer_count_;
}

void DxfDocument::line(const std::string& layer, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  group(entities_, 0, "LINE");
  group(entities_, 8, layer);
  point(entities_, 10, a);
  point(entities_, 11, b);
}

void DxfDocument::polyline(const std::string& layer, const std::vector<Eigen::Vector2d>& points, bool closed) {
  if (points.size() < 2) throw std::invalid_argument("DXF polyline needs at least 2 points");
  group(entities_, 0, "POLYLINE");
  group(entities_, 8, layer);
  group(entities_, 66, "1");  // vertices follow
  point(entities_, 10, Eigen::Vector2d::Zero());
  group(entities_, 70, closed ? "1" : "0");
  for (const Eigen::Vector2d& p : points) {
    group(entities_, 0, "VERTEX");
    group(entities_, 8, layer);
    point(entities_, 10, p);
  }
  group(entities_, 0, "SEQEND");
  group(entities_, 8, layer);
}

std::string DxfDocument::text() const {
  std::string s;
  s.reserve(300 + layers_.size() + entities_.size());
  group(s, 0, "SECTION");
  group(s, 2, "HEADER");
  group(s, 9, "$ACADVER");
  group(s, 1, "AC1009");
  group(s, 0, "ENDSEC");
  group(s, 0, "SECTION");
  group(s, 2, "TABLES");
  group(s, 0, "TABLE");
  group(s, 2, "LAYER");
  group(s, 70, std::to_string(layer_count_));
  s += layers_;
  group(s, 0, "ENDTAB");
  group(s, 0, "ENDSEC");
  group(s, 0, "SECTION");
  group(s, 2, "ENTITIES");
  s += entities_;
  group(s, 0, "ENDSEC");
  group(s, 0, "EOF");
  return s;
}

}  // namespace rigidfold
