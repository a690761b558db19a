#pragma once
// A minimal ASCII DXF (AutoCAD R12, AC1009) document: a HEADER naming the version, a LAYER
// table, and LINE / POLYLINE entities in the z = 0 plane. Shared by the crease-pattern
// writer (dxf_writer.hpp) and the SORCE profile drawings (design/sorce/sorce_dxf.hpp).
// Coordinates are written as the shortest decimal that reads back to the same double
// (std::to_chars), -0 as 0. Lines end with "\n" (DXF readers accept it as well as "\r\n").
// Units: whatever the caller's coordinates are in (DXF R12 has no unit field).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace rigidfold {

class DxfDocument {
 public:
  // A layer with its AutoCAD Colour Index (1..255) and continuous line type. Layers appear
  // in the table in the order added.
  void add_layer(const std::string& name, int colour);
  // A LINE from a to b on `layer` (colour BYLAYER).
  void line(const std::string& layer, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
  // A 2D POLYLINE through `points` (VERTEX entities, then SEQEND) on `layer`; closed when
  // `closed`. Needs at least 2 points (throws std::invalid_argument otherwise).
  void polyline(const std::string& layer, const std::vector<Eigen::Vector2d>& points, bool closed = false);
  // The whole document: HEADER, TABLES (LAYER), ENTITIES, EOF.
  std::string text() const;

 private:
  std::string layers_;
  int layer_count_ = 0;
  std::string entities_;
};

// x as the shortest text that reads back to the same double (no "-0").
std::string dxf_number(double x);

}  // namespace rigidfold
