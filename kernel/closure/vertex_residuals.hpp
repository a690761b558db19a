#pragma once
// The loop-closure error of a whole pattern at given fold angles, vertex by vertex.
#include <Eigen/Core>

#include "kernel/pattern/topology.hpp"

namespace rigidfold {

// Largest ||log(R_v)|| (radians) over the interior vertices of `topology`, where R_v is the
// loop product of vertex v (kernel/vertex/vertex_closure.hpp) at `edge_angles` (one fold
// angle per edge, radians). 0 when there is no interior vertex.
double max_vertex_closure_residual(const Topology& topology, const Eigen::VectorXd& edge_angles);

}  // namespace rigidfold
