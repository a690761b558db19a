// The network JSON reader: shared joints, signs, offsets, and every bad input named by its
// JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "kernel/math/angle_units.hpp"
#include "kernel/network/network_json.hpp"
#include "tests/support/input_error_place.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using nlohmann::json;

json two_linkages() {
  return json::parse(R"({
    "linkages": [
      {"name": "A", "twists_deg": [40, 60, 130, 100], "joints": ["a1", "a2", "a3", "a4"]},
      {"name": "B", "twists_deg": [40, 60, 130, 100],
       "joints": ["b1", {"joint": "a2", "sign": -1, "offset_deg": 180}, "b3", "b4"]}
    ],
    "input": {"joint": "a1", "start_deg": 30, "end_deg": 60},
    "outputs": ["b3"],
    "guess_deg": {"b3": 12}
  })");
}

TEST(NetworkJson, ReadsSharedJointsSignsAndOffsets) {
  const NetworkSpec s = parse_network_json(two_linkages(), "n.json");
  ASSERT_EQ(s.network.num_joints(), 7);
  ASSERT_EQ(s.network.num_linkages(), 2);
  const NetworkJointRef& shared = s.network.linkages[1].joints[1];
  EXPECT_EQ(shared.joint, s.network.joint_index("a2"));
  EXPECT_EQ(shared.sign, -1.0);
  EXPECT_DOUBLE_EQ(shared.offset, to_radians(180));
  EXPECT_DOUBLE_EQ(s.network.linkages[0].twists[2], to_radians(130));
  EXPECT_EQ(s.input, s.network.joint_index("a1"));
  EXPECT_TRUE(s.has_end);
  EXPECT_DOUBLE_EQ(s.input_end, to_radians(60));
  EXPECT_EQ(s.outputs, (std::vector<int>{s.network.joint_index("b3")}));
  EXPECT_DOUBLE_EQ(s.guess[s.network.joint_index("b3")], to_radians(12));
  EXPECT_DOUBLE_EQ(s.guess[s.input], to_radians(30));
}

std::string place_of(const json& doc) {
  return test::input_error_place([&] { parse_network_json(doc, "n.json"); });
}

TEST(NetworkJson, BadInputNamesItsPlace) {
  json d = two_linkages();
  d["linkages"][1]["twists_deg"][2] = "x";
  EXPECT_EQ(place_of(d), "n.json: linkages[1].twists_deg[2]");
  d = two_linkages();
  d["linkages"][0]["twists_deg"][0] = 400;
  EXPECT_EQ(place_of(d), "n.json: linkages[0].twists_deg[0]");
  d = two_linkages();
  d["linkages"][1]["joints"][1]["sign"] = 2;
  EXPECT_EQ(place_of(d), "n.json: linkages[1].joints[1].sign");
  d = two_linkages();
  d["linkages"][1]["joints"][2] = "b1";
  EXPECT_EQ(place_of(d), "n.json: linkages[1].joints[2]");
  d = two_linkages();
  d["linkages"][0]["joints"].erase(3);
  EXPECT_EQ(place_of(d), "n.json: linkages[0].joints");
  d = two_linkages();
  d["linkages"][0]["twist_deg"] = 1;
  EXPECT_EQ(place_of(d), "n.json: linkages[0].twist_deg");
  d = two_linkages();
  d["input"]["joint"] = "zz";
  EXPECT_EQ(place_of(d), "n.json: input.joint");
  d = two_linkages();
  d["outputs"][0] = "zz";
  EXPECT_EQ(place_of(d), "n.json: outputs[0]");
  d = two_linkages();
  d["guess_deg"]["zz"] = 1;
  EXPECT_EQ(place_of(d), "n.json: guess_deg.zz");
  d = two_linkages();
  d["linkages"] = json::array();
  EXPECT_EQ(place_of(d), "n.json: linkages");
  d = two_linkages();
  d["linkages"][0]["twists_deg"] = json::array({10, 20});
  d["linkages"][0]["joints"] = json::array({"a1", "a2"});
  EXPECT_EQ(place_of(d), "n.json: linkages[0].twists_deg");
  EXPECT_EQ(place_of(json::array()), "n.json");
}

}}  // namespace
}  // namespace rigidfold
