// Vertex-height load from JSON (kernel/energy/load_spec.hpp) on the bundled waterbomb base:
// default supports (the valley creases), explicit supports, and errors naming the JSON path.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kernel/energy/load_spec.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

struct Base {
  CreasePattern p = read_fold(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/waterbomb_base.fold");
  Topology t = build_topology(p);
};
const Base& base() {
  static const Base b;
  return b;
}

TEST(EnergyLoadSpec, DefaultSupportsAreTheValleyCreases) {
  const auto& b = base();
  const VertexHeightLoad l = load_from_spec(nlohmann::ordered_json::parse(R"({"vertex": 0, "height": 0.25})"), b.p, b.t, "l.json");
  EXPECT_EQ(l.vertex, 0);
  EXPECT_EQ(l.height, 0.25);
  std::vector<int> valleys;
  for (int e = 0; e < b.p.num_edges(); ++e)
    if (b.p.assignments[e] == Assignment::Valley) valleys.push_back(e);
  EXPECT_EQ(l.support_edges, valleys);
  const VertexHeightLoad m =
      load_from_spec(nlohmann::ordered_json::parse(R"({"vertex": 0, "height": -1, "supports": [1, 3, 5]})"), b.p, b.t, "l.json");
  EXPECT_EQ(m.support_edges, (std::vector<int>{1, 3, 5}));
}

TEST(EnergyLoadSpec, ErrorsNameTheJsonPath) {
  const auto& b = base();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"7", "l.json"},
      {R"({"height": 1})", "l.json: vertex"},
      {R"({"vertex": 1, "height": 1})", "l.json: vertex"},  // a corner, not interior
      {R"({"vertex": -1, "height": 1})", "l.json: vertex"},
      {R"({"vertex": 99, "height": 1})", "l.json: vertex"},
      {R"({"vertex": 0.5, "height": 1})", "l.json: vertex"},
      {R"({"vertex": 0})", "l.json: height"},
      {R"({"vertex": 0, "height": "1"})", "l.json: height"},
      {R"({"vertex": 0, "force": 1})", "l.json: force"},
      {R"({"vertex": 0, "height": 1, "load": 1})", "l.json: load"},
      {R"({"vertex": 0, "height": 1, "supports": 3})", "l.json: supports"},
      {R"({"vertex": 0, "height": 1, "supports": [0, 2, 9]})", "l.json: supports[2]"},  // a boundary edge
      {R"({"vertex": 0, "height": 1, "supports": [0, 2, 2]})", "l.json: supports[2]"},
      {R"({"vertex": 0, "height": 1, "supports": [0, 2]})", "l.json: supports"},
      {R"({"vertex": 0, "height": 1, "supports": [0, 2, 99]})", "l.json: supports[2]"},
  };
  for (const auto& [text, place] : cases) {
    try {
      load_from_spec(nlohmann::ordered_json::parse(text), b.p, b.t, "l.json");
      ADD_FAILURE() << text << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.place(), place) << text << ": " << e.what();
    }
  }
}

}}  // namespace
}  // namespace rigidfold
