// Per-crease stiffness from a JSON spec (kernel/energy/stiffness_spec.hpp) on the bundled
// waterbomb base: precedence (edges > letter > material > default), the flexure formula per
// crease length, and errors that name the JSON path.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/stiffness_spec.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

const CreasePattern& base() {
  static const CreasePattern p = read_fold(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/waterbomb_base.fold");
  return p;
}

bool spring(Assignment a) { return a == Assignment::Mountain || a == Assignment::Valley || a == Assignment::Unassigned; }

TEST(EnergyStiffnessSpec, PrecedenceEdgesOverLettersOverDefault) {
  const CreasePattern& p = base();
  int first_valley = -1;
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] == Assignment::Valley && first_valley < 0) first_valley = e;
  ASSERT_GE(first_valley, 0);
  const auto spec = nlohmann::ordered_json::parse("{\"default\": 3, \"mountain\": 2, \"edges\": {\"" +
                                                  std::to_string(first_valley) + "\": 7.5}}");
  const Eigen::VectorXd k = stiffness_from_spec(spec, p, "k.json");
  ASSERT_EQ(k.size(), p.num_edges());
  int checked = 0;
  for (int e = 0; e < p.num_edges(); ++e) {
    const double want = !spring(p.assignments[e])             ? 0.0
                        : e == first_valley                    ? 7.5
                        : p.assignments[e] == Assignment::Mountain ? 2.0
                                                               : 3.0;
    EXPECT_EQ(k[e], want) << e;
    checked += spring(p.assignments[e]);
  }
  EXPECT_EQ(checked, 8);
  // An empty spec is k = 1 on every crease, as stiffness_by_assignment's default.
  EXPECT_EQ(stiffness_from_spec(nlohmann::ordered_json::object(), p, "k.json"), stiffness_by_assignment(p, {}));
}

TEST(EnergyStiffnessSpec, MaterialIsTheFlexureOfEachCreaseLength) {
  const CreasePattern& p = base();
  // Seed 004 Table 2.1's flexure (E = 93 GPa, h = 0.02032 mm, l = 0.714 mm), pattern unit 50 mm.
  const auto spec = nlohmann::ordered_json::parse(
      R"({"material": {"youngs_modulus": 93e9, "thickness": 2.032e-5, "flexure_length": 7.14e-4, "length_scale": 0.05},
          "valley": 0.001})");
  const Eigen::VectorXd k = stiffness_from_spec(spec, p, "k.json");
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.assignments[e] == Assignment::Mountain) {
      const double L = 0.05 * (p.vertices[p.edges[e][1]] - p.vertices[p.edges[e][0]]).norm() * std::ldexp(1.0, p.length_exponent);
      EXPECT_DOUBLE_EQ(k[e], flexure_stiffness(93e9, L, 2.032e-5, 7.14e-4)) << e;
      EXPECT_DOUBLE_EQ(k[e], 93e9 * L * std::pow(2.032e-5, 3) / (12 * 7.14e-4)) << e;
    } else if (p.assignments[e] == Assignment::Valley) {
      EXPECT_EQ(k[e], 0.001);
    } else {
      EXPECT_EQ(k[e], 0.0);
    }
  }
}

TEST(EnergyStiffnessSpec, ErrorsNameTheJsonPath) {
  const CreasePattern& p = base();
  int boundary = -1;
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] == Assignment::Boundary && boundary < 0) boundary = e;
  ASSERT_GE(boundary, 0);
  const std::string b = std::to_string(boundary);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[1, 2]", "k.json"},
      {"{\"valey\": 1}", "k.json: valey"},
      {"{\"default\": -1}", "k.json: default"},
      {"{\"default\": \"1\"}", "k.json: default"},
      {"{\"mountain\": null}", "k.json: mountain"},
      {"{\"edges\": [1]}", "k.json: edges"},
      {"{\"edges\": {\"99\": 1}}", "k.json: edges.\"99\""},
      {"{\"edges\": {\"01\": 1}}", "k.json: edges.\"01\""},
      {"{\"edges\": {\"-1\": 1}}", "k.json: edges.\"-1\""},
      {"{\"edges\": {\"x\": 1}}", "k.json: edges.\"x\""},
      {"{\"edges\": {\"" + b + "\": 1}}", "k.json: edges.\"" + b + "\""},
      {"{\"edges\": {\"0\": -2}}", "k.json: edges.\"0\""},
      {"{\"material\": 5}", "k.json: material"},
      {"{\"material\": {\"youngs_modulus\": 1, \"thickness\": 1}}", "k.json: material.flexure_length"},
      {"{\"material\": {\"youngs_modulus\": 1, \"thickness\": 0, \"flexure_length\": 1}}", "k.json: material.thickness"},
      {"{\"material\": {\"youngs_modulus\": 1, \"thickness\": 1, \"flexure_length\": 1, \"width\": 2}}", "k.json: material.width"},
      {"{\"material\": {\"youngs_modulus\": 1e308, \"thickness\": 1e100, \"flexure_length\": 1e-300}}", "k.json: material"},
  };
  for (const auto& [text, place] : cases) {
    try {
      stiffness_from_spec(nlohmann::ordered_json::parse(text), p, "k.json");
      ADD_FAILURE() << text << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), place) << text << ": " << e.what();
    }
  }
}

}}  // namespace
}  // namespace rigidfold
