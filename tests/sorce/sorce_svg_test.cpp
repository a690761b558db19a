// SORCE (seed 002) profile SVG: the polylines carry the generated profiles in panel-local
// model coordinates (parsed back and compared with the profile at the same t).
#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "design/sorce/sorce_svg.hpp"
#include "kernel/pattern/input_error.hpp"
#include "tests/sorce/sorce_examples.hpp"

namespace rigidfold::sorce {
namespace { namespace RIGIDFOLD_UNITY_ID {

// The points of every <polyline class="cls" ...>, in document order.
std::vector<std::vector<Vec2>> polylines(const std::string& svg, const std::string& cls) {
  std::vector<std::vector<Vec2>> out;
  const std::string tag = "<polyline class=\"" + cls + "\"";
  for (std::size_t at = svg.find(tag); at != std::string::npos; at = svg.find(tag, at + 1)) {
    const std::size_t b = svg.find("points=\"", at) + 8, e = svg.find('"', b);
    std::istringstream in(svg.substr(b, e - b));
    std::vector<Vec2> pts;
    std::string pair;
    while (in >> pair) {
      const std::size_t comma = pair.find(',');
      pts.emplace_back(std::strtod(pair.substr(0, comma).c_str(), nullptr), std::strtod(pair.substr(comma + 1).c_str(), nullptr));
    }
    out.push_back(pts);
  }
  return out;
}

TEST(SorceSvg, VertexDocumentCarriesTheProfiles) {
  const SorceVertex v = testing::vertex_b_split(2);
  SvgOptions o;
  o.samples = 57;
  const std::string svg = vertex_profiles_svg(v, o);
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_NE(svg.find("</svg>\n", svg.size() - 8), std::string::npos);
  const auto left = polylines(svg, "left"), right = polylines(svg, "right");
  ASSERT_EQ(left.size(), 4u);
  ASSERT_EQ(right.size(), 4u);
  double worst = 0.0;
  for (int j = 0; j < 4; ++j) {
    ASSERT_EQ(left[j].size(), 57u);
    for (int k = 0; k < 57; ++k) {
      const ProfilePoint p = profile_point(v.folds[j], k / 56.0);
      worst = std::max({worst, (left[j][k] - p.s_left).norm(), (right[j][k] - p.s_right).norm()});
    }
  }
  EXPECT_LE(worst, 1e-11);  // 12 significant digits of values below 1
  EXPECT_EQ(svg.find("nan"), std::string::npos);
}

TEST(SorceSvg, FoldGroupHasSlabFacesAtHalfThickness) {
  const SorceVertex v = testing::vertex_a_linear(1.0);
  const std::string g = fold_profiles_svg_group(v.folds[1], SvgOptions{});
  EXPECT_EQ(g.rfind("<g class=\"fold\"", 0), 0u);
  // Two dashed faces per panel at y = +-0.5 (thickness 1).
  std::size_t count = 0;
  for (std::size_t at = g.find("class=\"left-slab\""); at != std::string::npos; at = g.find("class=\"left-slab\"", at + 1)) ++count;
  EXPECT_EQ(count, 2u);
  EXPECT_NE(g.find("y1=\"0.5\""), std::string::npos);
  EXPECT_NE(g.find("y1=\"-0.5\""), std::string::npos);
  SvgOptions bad;
  bad.samples = 1;
  EXPECT_THROW(fold_profiles_svg_group(v.folds[1], bad), InputError);
}

}}  // namespace
}  // namespace rigidfold::sorce
