#include "kernel/network/linkage_network.hpp"

#include <cmath>
#include <stdexcept>

namespace rigidfold {

int LinkageNetwork::joint_index(const std::string& name) const {
  for (int j = 0; j < num_joints(); ++j)
    if (joint_names[j] == name) return j;
  return -1;
}

void validate_network(const LinkageNetwork& network) {
  std::vector<bool> used(network.num_joints(), false);
  for (int k = 0; k < network.num_linkages(); ++k) {
    const NetworkLinkage& l = network.linkages[k];
    std::string where = "linkage ";
    where += std::to_string(k);
    if (l.twists.size() < 3) throw std::invalid_argument(where + ": needs at least 3 joints");
    if (l.joints.size() != l.twists.size()) throw std::invalid_argument(where + ": as many joints as twists");
    std::vector<bool> here(network.num_joints(), false);
    for (std::size_t i = 0; i < l.twists.size(); ++i) {
      if (!std::isfinite(l.twists[i])) throw std::invalid_argument(where + ": twist not finite");
      const NetworkJointRef& r = l.joints[i];
      if (r.joint < 0 || r.joint >= network.num_joints()) throw std::invalid_argument(where + ": joint index out of range");
      if (r.sign != 1.0 && r.sign != -1.0) throw std::invalid_argument(where + ": joint sign must be +1 or -1");
      if (!std::isfinite(r.offset)) throw std::invalid_argument(where + ": joint offset not finite");
      if (here[r.joint]) throw std::invalid_argument(where + ": joint used twice in one linkage");
      here[r.joint] = true;
      used[r.joint] = true;
    }
  }
  for (int j = 0; j < network.num_joints(); ++j)
    if (!used[j]) throw std::invalid_argument("joint " + network.joint_names[j] + " belongs to no linkage");
}

std::vector<double> linkage_joint_angles(const NetworkLinkage& linkage, const std::vector<double>& q) {
  std::vector<double> t(linkage.joints.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const NetworkJointRef& r = linkage.joints[i];
    t[i] = r.sign * q[r.joint] + r.offset;
  }
  return t;
}

}  // namespace rigidfold
