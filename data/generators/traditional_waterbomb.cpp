#include "data/generators/traditional_waterbomb.hpp"

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "data/generators/generator_common.hpp"

namespace rigidfold::generators {

namespace {

enum class Kind { Diagonal, Midline, Side };

}  // namespace

CreasePattern traditional_waterbomb(const TraditionalWaterbombParams& params) {
  require(params.rows >= 1 && params.rows <= 200, "rows", std::string("must be between 1 and 200, got ") + std::to_string(params.rows));
  require(params.cols >= 1 && params.cols <= 200, "cols", std::string("must be between 1 and 200, got ") + std::to_string(params.cols));
  using Point = std::pair<int, int>;  // (y, x): sorted by row first
  // Every crease piece with its kind and how many squares have it on their side.
  std::map<std::pair<Point, Point>, std::pair<Kind, int>> pieces;
  auto add = [&](Point a, Point b, Kind kind) {
    if (b < a) std::swap(a, b);
    auto [it, inserted] = pieces.try_emplace({a, b}, kind, 0);
    if (kind == Kind::Side) ++it->second.second;
  };
  for (int r = 0; r < params.rows; ++r)
    for (int i = 0; i < params.cols; ++i) {
      const int x = 2 * i + (r % 2), y = 2 * r;
      for (int sx : {-1, 1})
        for (int sy : {-1, 1}) add({y, x}, {y + sy, x + sx}, Kind::Diagonal);
      for (int sy : {-1, 1}) {
        add({y, x}, {y + sy, x}, Kind::Midline);
        add({y + sy, x - 1}, {y + sy, x}, Kind::Side);  // top / bottom side, two pieces
        add({y + sy, x}, {y + sy, x + 1}, Kind::Side);
      }
      for (int sx : {-1, 1}) add({y - 1, x + sx}, {y + 1, x + sx}, Kind::Side);  // left / right side, one piece
    }
  std::map<Point, int> index;
  for (const auto& [ends, kind] : pieces) {
    index.try_emplace(ends.first, 0);
    index.try_emplace(ends.second, 0);
  }
  CreasePattern p;
  p.coords_2d = true;
  for (auto& [point, id] : index) {
    id = p.num_vertices();
    p.vertices.emplace_back(static_cast<double>(point.second), static_cast<double>(point.first), 0.0);
  }
  for (const auto& [ends, kind] : pieces) {
    p.edges.push_back({index.at(ends.first), index.at(ends.second)});
    switch (kind.first) {
      case Kind::Diagonal: p.assignments.push_back(Assignment::Mountain); break;
      case Kind::Midline: p.assignments.push_back(Assignment::Valley); break;
      case Kind::Side: p.assignments.push_back(kind.second >= 2 ? Assignment::Valley : Assignment::Boundary); break;
    }
  }
  p.fold_angles.assign(p.edges.size(), std::nullopt);
  nlohmann::ordered_json g;
  g["kind"] = "traditional_waterbomb";
  g["rows"] = params.rows;
  g["cols"] = params.cols;
  return finish_pattern(std::move(p), std::string("Traditional waterbomb ") + std::to_string(params.rows) + "x" + std::to_string(params.cols),
                        "six-crease waterbomb bases in shifted rows; D and W vertices", g);
}

}  // namespace rigidfold::generators
