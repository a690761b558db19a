#pragma once
// The whole-pattern SORCE tests' single-vertex files and the request they share: fold 2
// (edge 1) driven to 180 deg in 40 steps, 401 profile samples.
#include <cmath>
#include <string>

#include "design/sorce/sorce_pattern.hpp"

namespace rigidfold::sorce::testing {

inline const std::string kVertexA = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/sorce/vertex_a.fold";
inline const std::string kVertexB = std::string(RIGIDFOLD_SOURCE_DIR) + "/data/sorce/vertex_b.fold";

inline PatternSorceRequest single_vertex_request(double thickness) {
  PatternSorceRequest rq;
  rq.thickness = thickness;
  rq.trace.drive = 1;  // fold 2
  rq.trace.to = M_PI;
  rq.trace.steps = 40;
  rq.report.samples = 401;
  return rq;
}

}  // namespace rigidfold::sorce::testing
