#pragma once
// analyse_network: the front door of `rigidfold network`. From a network of spherical
// linkages (network_json.hpp) to its report: a closed configuration with the input at its start
// value, the mobility there, the verdict, and on request the input-output relation over equal
// input steps and the assembly as a crease pattern (network_crease_pattern.hpp).
//
// The verdict (NetworkAnalysis::mobility, and the shared vocabulary in verdict_class):
//   kRigid              DOF 0 at a closed configuration (first order; a proof at a regular point)
//   kMobile             DOF > 0 and the input moves by probe_step both ways or one way
//   kSingular           DOF > 0 at first order, but with the input held the DOF is 0 and the
//                       input does not move by probe_step: a singular configuration the network
//                       does not move through (evidence)
//   kInputLocked        DOF > 0 with the input held: other joints move, the input does not
//   kNoConfiguration    no closed configuration found at the input's start value (evidence)
// Every configuration reported closes to closure_tolerance (checked before it is returned).
#include <optional>
#include <string>
#include <vector>

#include "kernel/analysis/foldability_class.hpp"
#include "kernel/network/network_closure.hpp"
#include "kernel/network/network_crease_pattern.hpp"
#include "kernel/network/network_json.hpp"
#include "kernel/network/network_trace.hpp"
#include "kernel/solve/rank.hpp"

namespace rigidfold {

struct NetworkAnalysisOptions {
  double closure_tolerance = 1e-12;  // rad, every configuration reported
  double rank_tolerance = 1e-9;      // relative to sigma_max
  double probe_step = 1e-3;          // rad: the input must move this far for "mobile"
  int trace_steps = 0;               // > 0: trace the input to input.end_deg in this many steps
  bool crease_pattern = false;       // the assembly as a crease pattern (mobile networks only)
  std::string source = "network";    // names the input in messages

  // True when every field is in range; otherwise false with the field named in *error.
  bool IsValid(std::string* error) const;
};

enum class NetworkMobility { kRigid, kMobile, kSingular, kInputLocked, kNoConfiguration };
const char* to_string(NetworkMobility m);

struct NetworkAnalysis {
  NetworkMobility mobility = NetworkMobility::kNoConfiguration;
  FoldabilityClass verdict_class = FoldabilityClass::kUndecided;
  std::string verdict;                   // one sentence for the user
  int equations = 0;                     // closure rows of the network
  std::vector<std::string> flat_vertices;  // linkages that are flat paper vertices (2-33)
  NetworkConfiguration start;            // at the input's start value
  double residual = 0.0;                 // ||r||_inf at start.q (found)
  RankResult mobility_rank;              // at start.q, nothing held
  RankResult mobility_rank_input_held;   // at start.q, the input held
  int input_moves = 0;                   // probe_input_motion: 0, 1 or 2 directions
  std::optional<NetworkCreasePattern> crease_pattern;
  std::optional<NetworkTrace> trace;
};

// Throws InputError (an invalid option, input.end_deg missing for a trace, or a crease pattern
// asked of a network that is not mobile or whose vertices are not flat paper) and
// NoAnswerError (a trace or crease pattern asked where no closed configuration was found, or a
// configuration that does not close).
NetworkAnalysis analyse_network(const NetworkSpec& spec, const NetworkAnalysisOptions& options = {});

}  // namespace rigidfold
