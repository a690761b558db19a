#include "kernel/closure/vertex_residuals.hpp"

#include <algorithm>
#include <vector>

#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {

double max_vertex_closure_residual(const Topology& t, const Eigen::VectorXd& rho) {
  double worst = 0;
  std::vector<double> angles;
  for (int v : t.interior_vertices) {
    const Fan& fan = t.stars[v].fans[0];
    angles.clear();
    for (int e : fan.edges) angles.push_back(rho[e]);
    worst = std::max(worst, vertex_closure_residual(fan.sectors, angles).norm());
  }
  return worst;
}

}  // namespace rigidfold
