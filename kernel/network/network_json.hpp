#pragma once
// The JSON input of `rigidfold network`: a network of spherical linkages given by twists
// (linkage_network.hpp). Degrees at this edge, radians inside.
//
//   {
//     "description": "any text (optional)",
//     "linkages": [                                    // one closed loop each
//       {"name": "A", "twists_deg": [40, 60, 130, 100], "joints": ["a1", "a2", "a3", "a4"]},
//       {"name": "B", "twists_deg": [...],
//        "joints": ["b1", "a2", {"joint": "b3", "sign": -1, "offset_deg": 180}, "b4"]}
//     ],
//     "input": {"joint": "a1", "start_deg": 30, "end_deg": 120},   // optional
//     "outputs": ["a2", "b3"],                                     // optional, default all
//     "guess_deg": {"a2": 10}                                      // optional search start
//   }
//
// - twists_deg[i]: the link between joints i and i+1 (the seed's alpha_{(i+1)(i+2)}), any
//   value in [-360, 360] (pi - alpha, -alpha, sums != 360 are legal).
// - joints[i]: a joint name (t_i = q_name), or {"joint", "sign" (+1/-1, default 1),
//   "offset_deg" (default 0)}: t_i = sign * q + offset. A name used by several linkages is
//   one shared revolute axis (seed 003 (2-23)); sign -1 is (2-15)'s theta^a = -theta^b.
// - input: the driven joint, its first value and (for a trace) its last, degrees in
//   [-360, 360]; without "input" the first joint of the first linkage is driven from 0.
// - guess_deg: starting values for the search of the first closed configuration.
// Every key is checked; unknown keys are refused (a typo must not pass silently).
// Throws InputError(source + ": " + JSON path, what), e.g. "net.json: linkages[2].twists_deg[1]".
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "kernel/network/linkage_network.hpp"

namespace rigidfold {

struct NetworkSpec {
  std::string description;
  LinkageNetwork network;
  int input = 0;                   // driven joint
  double input_start = 0.0;        // radians
  bool has_end = false;
  double input_end = 0.0;          // radians, when has_end
  std::vector<int> outputs;        // joints reported (all joints when "outputs" is absent)
  Eigen::VectorXd guess;           // size num_joints (radians), 0 where not given
};

// Largest linkage count and joints per linkage accepted: the configuration search runs up to
// 65 Newton solves and every traced point a rank check, so an input stays within seconds.
inline constexpr int kMaxNetworkLinkages = 200;
inline constexpr int kMaxLinkageJoints = 16;

NetworkSpec parse_network_json(const nlohmann::json& doc, const std::string& source);
// read_input_file + parse_json_input + parse_network_json.
NetworkSpec read_network_json(const std::string& path);

}  // namespace rigidfold
