#include "kernel/network/network_crease_pattern.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/assignment.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "kernel/closure/closure_system.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/no_answer_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/pattern/validate_pattern.hpp"

namespace rigidfold {
namespace {

constexpr double kAngleTolerance = 1e-9;  // (2-32), (2-33), radians
constexpr double kFlatFold = 1e-12;       // |rho| at or below: letter F

std::string deg(double rad) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g deg", rad * 180 / kPi);
  return text;
}

std::string linkage_place(const std::string& source, int k) {
  std::string s = source;
  s += ": linkages[";
  s += std::to_string(k);
  s += "]";
  return s;
}

// A linkage laid out counter-clockwise: its joint slot at position p and the sector between
// positions p and p + 1.
struct Layout {
  int orientation = 1;
  int slot(int p) const { return orientation > 0 ? ((p % 4) + 4) % 4 : ((3 - p) % 4 + 4) % 4; }
  int position(int s) const {
    for (int p = 0; p < 4; ++p)
      if (slot(p) == s) return p;
    return -1;
  }
  double sector_after(const NetworkLinkage& l, int p) const {
    // Forward: twist i lies between slots i and i + 1. Reversed: between slots j and j - 1
    // lies twist j - 1.
    const int s = slot(p);
    return orientation > 0 ? l.twists[s] : l.twists[(s + 3) % 4];
  }
};

}  // namespace

NetworkCreasePattern network_crease_pattern(const LinkageNetwork& net, const Eigen::VectorXd& q,
                                            const std::string& source, double tolerance) {
  validate_network(net);
  if (net.num_linkages() != 4)
    throw InputError(source + ": linkages", "a crease pattern is built from an assembly of four 4R linkages; this network has " +
                                                std::to_string(net.num_linkages()));
  for (int k = 0; k < 4; ++k)
    if (net.linkages[k].twists.size() != 4)
      throw InputError(linkage_place(source, k) + ".joints",
                       "a crease pattern is built from 4R linkages; this one has " +
                           std::to_string(net.linkages[k].twists.size()) + " joints");
  if (q.size() != net.num_joints()) throw std::invalid_argument("network_crease_pattern: q has the wrong size");

  // Which linkages use each joint, and where.
  std::vector<std::vector<std::array<int, 2>>> uses(net.num_joints());
  for (int k = 0; k < 4; ++k)
    for (int i = 0; i < 4; ++i) uses[net.linkages[k].joints[i].joint].push_back({k, i});
  for (int j = 0; j < net.num_joints(); ++j)
    if (uses[j].size() > 2)
      throw InputError(source + ": joints", "joint '" + net.joint_names[j] + "' is shared by " + std::to_string(uses[j].size()) +
                                                " linkages; a crease joins at most two vertices");
  // Shared slots of each linkage and the neighbour across each.
  std::array<std::vector<std::array<int, 2>>, 4> shared;  // (slot, neighbour linkage)
  for (int j = 0; j < net.num_joints(); ++j)
    if (uses[j].size() == 2) {
      const auto [ka, ia] = uses[j][0];
      const auto [kb, ib] = uses[j][1];
      shared[ka].push_back({ia, kb});
      shared[kb].push_back({ib, ka});
    }
  for (int k = 0; k < 4; ++k) {
    const auto& s = shared[k];
    if (s.size() != 2 || s[0][1] == s[1][1])
      throw InputError(linkage_place(source, k),
                       "linkage " + net.linkages[k].name + " shares " + std::to_string(s.size()) +
                           " joints; in an assembly laid out as a crease pattern each shares one joint with each of "
                           "two other linkages (the sides of the central panel)");
    const int d = ((s[0][0] - s[1][0]) % 4 + 4) % 4;
    if (d != 1 && d != 3)
      throw InputError(linkage_place(source, k), "the two joints linkage " + net.linkages[k].name +
                                                     " shares are not neighbours in its loop: no panel lies between them");
  }
  // (2-33) flat paper at every vertex.
  for (int k = 0; k < 4; ++k) {
    double sum = 0;
    for (int i = 0; i < 4; ++i) {
      const double a = net.linkages[k].twists[i];
      if (!(a > 0 && a < kPi))
        throw InputError(linkage_place(source, k) + ".twists_deg[" + std::to_string(i) + "]",
                         deg(a) + " is not a sector of flat paper (2-33 needs 0 < alpha < 180 deg)");
      sum += a;
    }
    if (std::fabs(sum - 2 * kPi) > kAngleTolerance)
      throw InputError(linkage_place(source, k) + ".twists_deg",
                       "the twists sum to " + deg(sum) + ", not 360 deg: the vertex is not flat paper (2-33)");
  }

  // Walk the cycle of linkages: P0 = linkage 0, as given.
  NetworkCreasePattern out;
  std::array<int, 4> order{};          // linkage at polygon vertex m
  std::array<Layout, 4> layout;        // per linkage
  std::array<int, 4> central_pos{};    // per polygon vertex: position p of the crease to P_{m+1}
  order[0] = 0;
  layout[0].orientation = 1;
  {
    const int pa = layout[0].position(shared[0][0][0]), pb = layout[0].position(shared[0][1][0]);
    // Central sector from position p (crease to P1) to p + 1 (crease to P3).
    const bool a_first = (pa + 1) % 4 == pb;
    central_pos[0] = a_first ? pa : pb;
    order[1] = a_first ? shared[0][0][1] : shared[0][1][1];
  }
  for (int m = 1; m < 4; ++m) {
    const int k = order[m], prev = order[m - 1];
    const auto& s = shared[k];
    const int s_prev = s[0][1] == prev ? s[0][0] : s[1][0];
    const int s_next = s[0][1] == prev ? s[1][0] : s[0][0];
    const int next = s[0][1] == prev ? s[1][1] : s[0][1];
    if (s[0][1] != prev && s[1][1] != prev) throw std::logic_error("network_crease_pattern: broken cycle");
    for (int o : {1, -1}) {
      Layout l;
      l.orientation = o;
      if ((l.position(s_next) + 1) % 4 == l.position(s_prev)) {
        layout[k] = l;
        central_pos[m] = l.position(s_next);
      }
    }
    if (m < 3) {
      for (int t = 0; t < m; ++t)
        if (order[t] == next)
          throw InputError(source + ": joints", "the shared joints do not join the four linkages in one cycle");
      order[m + 1] = next;
    } else if (next != order[0]) {
      throw InputError(source + ": joints", "the shared joints do not join the four linkages in one cycle");
    }
  }
  // One fold angle per crease.
  for (int j = 0; j < net.num_joints(); ++j) {
    if (uses[j].size() != 2) continue;
    const auto [ka, ia] = uses[j][0];
    const auto [kb, ib] = uses[j][1];
    const auto& ra = net.linkages[ka].joints[ia];
    const auto& rb = net.linkages[kb].joints[ib];
    const double oa = layout[ka].orientation, ob = layout[kb].orientation;
    if (oa * ra.sign != ob * rb.sign || std::fabs(oa * ra.offset - ob * rb.offset) > kAngleTolerance)
      throw InputError(linkage_place(source, kb) + ".joints[" + std::to_string(ib) + "]",
                       "joint '" + net.joint_names[j] + "' would fold by different angles at linkages " +
                           net.linkages[ka].name + " and " + net.linkages[kb].name +
                           " laid out in the plane (sign/offset of the shared joint do not match the vertices' "
                           "orientations): not one crease");
  }
  // (2-32) flat central panel.
  std::array<double, 4> c{};
  double csum = 0;
  for (int m = 0; m < 4; ++m) {
    const int k = order[m];
    c[m] = layout[k].sector_after(net.linkages[k], central_pos[m]);
    csum += c[m];
  }
  out.central_angle_sum = csum;
  if (std::fabs(csum - 2 * kPi) > kAngleTolerance) {
    std::string names;
    for (int m = 0; m < 4; ++m) {
      if (m > 0) names += " + ";
      names += deg(c[m]);
    }
    throw InputError(source + ": linkages",
                     "the central panel's angles " + names + " sum to " + deg(csum) + ", not 360 deg (2-32)");
  }

  // Central panel: edge directions d_m (P_m -> P_{m+1}), lengths maximising the shortest side.
  std::array<double, 4> d{};
  for (int m = 1; m < 4; ++m) d[m] = d[m - 1] + (kPi - c[m]);
  Eigen::Matrix<double, 2, 4> A;
  for (int m = 0; m < 4; ++m) A.col(m) << std::cos(d[m]), std::sin(d[m]);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(A), Eigen::ComputeFullV);
  const Eigen::Vector4d n1 = svd.matrixV().col(2), n2 = svd.matrixV().col(3);
  Eigen::Vector4d best = Eigen::Vector4d::Zero();
  double best_min = -1;
  for (int g = 0; g < 7200; ++g) {
    const double phi = 2 * kPi * g / 7200;
    Eigen::Vector4d l = std::cos(phi) * n1 + std::sin(phi) * n2;
    if (l.maxCoeff() <= 0) continue;
    l /= l.maxCoeff();
    if (l.minCoeff() > best_min) {
      best_min = l.minCoeff();
      best = l;
    }
  }
  if (!(best_min > 1e-3))
    throw InputError(source + ": linkages", "no convex central panel with these angles has sides longer than 1e-3 of the "
                                            "longest: the panel degenerates");
  std::array<Eigen::Vector2d, 4> P;
  P[0] = Eigen::Vector2d::Zero();
  for (int m = 1; m < 4; ++m) P[m] = P[m - 1] + best[m - 1] * Eigen::Vector2d(std::cos(d[m - 1]), std::sin(d[m - 1]));

  // Crease directions per polygon vertex and position.
  std::array<std::array<double, 4>, 4> dir{};
  for (int m = 0; m < 4; ++m) {
    const int k = order[m];
    double a = d[m];
    for (int r = 0; r < 4; ++r) {
      dir[m][(central_pos[m] + r) % 4] = a;
      a += layout[k].sector_after(net.linkages[k], (central_pos[m] + r) % 4);
    }
  }
  // Outer creases: positions p + 2 and p + 3. Lengths 1, halved where they would meet the
  // neighbour's outer crease across a side.
  std::array<std::array<double, 4>, 4> len{};
  for (int m = 0; m < 4; ++m)
    for (int r = 2; r < 4; ++r) len[m][(central_pos[m] + r) % 4] = 1.0;
  auto ray = [&](int m, int r) { return Eigen::Vector2d(std::cos(dir[m][(central_pos[m] + r) % 4]), std::sin(dir[m][(central_pos[m] + r) % 4])); };
  for (int m = 0; m < 4; ++m) {
    const int n = (m + 1) % 4;
    // Across side P_m P_{m+1}: P_m's position p + 3 and P_{m+1}'s position p' + 2.
    const Eigen::Vector2d u = ray(m, 3), v = ray(n, 2);
    Eigen::Matrix2d M;
    M << u, -v;
    if (std::fabs(M.determinant()) > 1e-14) {
      const Eigen::Vector2d st = M.inverse() * (P[n] - P[m]);
      if (st[0] > 0 && st[1] > 0) {
        double& lu = len[m][(central_pos[m] + 3) % 4];
        double& lv = len[n][(central_pos[n] + 2) % 4];
        lu = std::min(lu, 0.5 * st[0]);
        lv = std::min(lv, 0.5 * st[1]);
      }
    }
  }

  CreasePattern& p = out.pattern;
  p.coords_2d = true;
  for (int m = 0; m < 4; ++m) {
    p.vertices.emplace_back(P[m].x(), P[m].y(), 0.0);
    out.vertex_linkage.push_back(net.linkages[order[m]].name);
  }
  std::vector<double> rho;
  const auto angles = [&](int k) { return linkage_joint_angles(net.linkages[k], std::vector<double>(q.data(), q.data() + q.size())); };
  auto fold_of = [&](int k, int slot) {
    const double t = angles(k)[slot];
    return std::remainder(-layout[k].orientation * t, 2 * kPi);
  };
  auto add_edge = [&](int a, int b, int joint, double r, bool crease) {
    p.edges.push_back({a, b});
    Assignment letter = Assignment::Boundary;
    if (crease) letter = std::fabs(r) <= kFlatFold ? Assignment::Flat : (r > 0 ? Assignment::Valley : Assignment::Mountain);
    p.assignments.push_back(letter);
    p.fold_angles.push_back(crease ? std::optional<double>(r) : std::nullopt);
    out.edge_joint.push_back(joint);
    rho.push_back(crease ? r : 0.0);
  };
  // Sides P_m -> P_{m+1}: the joint at P_m's position p.
  for (int m = 0; m < 4; ++m) {
    const int k = order[m], slot = layout[k].slot(central_pos[m]);
    add_edge(m, (m + 1) % 4, net.linkages[k].joints[slot].joint, fold_of(k, slot), true);
  }
  // Outer creases and their ends, then the boundary through the ends in order.
  std::vector<int> ends;
  for (int m = 0; m < 4; ++m)
    for (int r = 2; r < 4; ++r) {
      const int pos = (central_pos[m] + r) % 4, k = order[m], slot = layout[k].slot(pos);
      const Eigen::Vector2d e = P[m] + len[m][pos] * ray(m, r);
      p.vertices.emplace_back(e.x(), e.y(), 0.0);
      const int v = static_cast<int>(p.vertices.size()) - 1;
      ends.push_back(v);
      add_edge(m, v, net.linkages[k].joints[slot].joint, fold_of(k, slot), true);
    }
  for (std::size_t i = 0; i < ends.size(); ++i) add_edge(ends[i], ends[(i + 1) % ends.size()], -1, 0.0, false);
  p.extra["file_spec"] = 1.1;
  p.extra["file_creator"] = "rigidfold network --out";
  p.extra["file_title"] = "Crease pattern of a four-4R assembly (seed 003 Fig 2-12)";
  p.extra["frame_classes"] = nlohmann::ordered_json::array({"creasePattern"});
  p.extra["frame_attributes"] = nlohmann::ordered_json::array({"2D"});
  try {
    complete_and_validate(p, source + " (crease pattern)");
  } catch (const InputError& e) {
    throw InputError(source + ": linkages", std::string("the laid-out crease pattern is not a valid sheet: ") + e.what());
  }
  out.orientation.assign(4, 1);
  for (int k = 0; k < 4; ++k) out.orientation[k] = layout[k].orientation;

  // The pattern's own vertex loops at the fold angles.
  const Topology topo = build_topology(p, source + " (crease pattern)");
  const ClosureSystem sys(p, topo);
  const Eigen::VectorXd x = sys.unknowns_from_edges(Eigen::Map<const Eigen::VectorXd>(rho.data(), static_cast<Eigen::Index>(rho.size())));
  out.residual = sys.residual(x).lpNorm<Eigen::Infinity>();
  if (!(out.residual <= tolerance))
    throw NoAnswerError("network --out: the crease pattern's vertex loops do not close at the network's configuration", out.residual);
  return out;
}

std::string NetworkCreasePattern::crease_letters() const {
  std::string letters;
  for (int e = 0; e < pattern.num_edges(); ++e)
    if (edge_joint[e] >= 0) letters += assignment_letter(pattern.assignments[e]);
  return letters;
}

int NetworkCreasePattern::num_creases() const {
  return static_cast<int>(std::count_if(edge_joint.begin(), edge_joint.end(), [](int j) { return j >= 0; }));
}

}  // namespace rigidfold
