#include "kernel/thick/waterbomb_network.hpp"
#include "kernel/math/angle_units.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "kernel/thick/thick_vertex_models.hpp"

namespace rigidfold {

namespace {


bool near(double a, double b) { return std::abs(a - b) < 1e-9; }

// First fan position k whose sectors from k on are `pattern` (cyclic), or -1.
int match(const std::vector<double>& sectors, const std::vector<double>& pattern) {
  const int n = static_cast<int>(sectors.size());
  if (n != static_cast<int>(pattern.size())) return -1;
  for (int k = 0; k < n; ++k) {
    bool ok = true;
    for (int i = 0; i < n && ok; ++i) ok = near(sectors[(k + i) % n], pattern[i]);
    if (ok) return k;
  }
  return -1;
}

}  // namespace

WaterbombNetwork waterbomb_network(const CreasePattern& flat, const Topology& topology, double mu, double t, double t1,
                                   double t2) {
  const ThickVertexModel d_model = diamond_vertex(0.25 * kPi, t1, t2);  // validates t1, t2
  const ThickVertexModel w_model = waterbomb_vertex(mu, t);            // validates mu, t
  WaterbombNetwork net;
  net.thick.num_creases = flat.num_edges();
  for (int v : topology.interior_vertices) {
    const Fan& fan = topology.stars[v].fans[0];
    const int kd = match(fan.sectors, d_model.sectors);
    const int kw = kd < 0 ? match(fan.sectors, w_model.sectors) : -1;
    if (kd < 0 && kw < 0)
      throw std::invalid_argument(std::string("waterbomb network: interior vertex ") + std::to_string(v) + " is neither a D nor a W vertex");
    const bool is_d = kd >= 0;
    const int k0 = is_d ? kd : kw;
    const ThickLoop& model = is_d ? d_model.thick.loops[0] : w_model.thick.loops[0];
    ThickLoop loop;
    loop.name = std::string(is_d ? "D" : "W") + " vertex " + std::to_string(v);
    std::vector<int> creases;
    for (int i = 0; i < 6; ++i) {
      ThickJoint joint = model.joints[i];
      joint.crease = fan.edges[(k0 + i) % 6];
      if (!is_d) {  // mirror image: theta -> -theta, twist -> -twist (rho_model = -rho)
        joint.angle_offset = -joint.angle_offset;
        joint.link.twist = -joint.link.twist;
      }
      creases.push_back(joint.crease);
      loop.joints.push_back(joint);
    }
    net.thick.loops.push_back(loop);
    net.vertex_of_loop.push_back(v);
    net.kind.push_back(is_d ? WaterbombVertexKind::kD : WaterbombVertexKind::kW);
    net.creases.push_back(creases);
  }
  return net;
}

Eigen::VectorXd waterbomb_network_uniform_state(const CreasePattern& flat, const WaterbombNetwork& network, double rho_line) {
  Eigen::VectorXd fold = Eigen::VectorXd::Zero(flat.num_edges());
  for (std::size_t k = 0; k < network.thick.loops.size(); ++k) {
    std::vector<double> rho;
    if (network.kind[k] == WaterbombVertexKind::kD) {
      rho = diamond_zero_thickness(0.25 * kPi, rho_line);
    } else {
      rho = waterbomb_zero_thickness(-rho_line);  // the model's letters; the pattern sees it from the other side
      for (double& r : rho) r = -r;
    }
    for (int i = 0; i < 6; ++i) fold[network.creases[k][i]] = rho[i];
  }
  return fold;
}

}  // namespace rigidfold
