// Branch exploration through bifurcations (kernel/analysis/branch_explorer.hpp), seed 001
// §4 (Types 1M and 2M at alpha = pi/6) and a flat-foldable degree-4 vertex.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "data/generators/square_twist.hpp"
#include "kernel/analysis/branch_explorer.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/newton_projection.hpp"
#include <Eigen/Dense>
#include <Eigen/SparseCore>

namespace rigidfold {
namespace {

constexpr double kPi = std::numbers::pi;

void print(const char* name, const BranchExploration& x) {
  std::cout << name << ": " << x.points.size() << " points, " << x.branches.size() << " branches, " << x.seconds
            << " s\n";
  for (std::size_t i = 0; i < x.points.size(); ++i) {
    const BranchPoint& p = x.points[i];
    std::cout << "  point " << i << " " << p.kind << " edge " << p.parameter_edge << " = " << p.parameter
              << " (+-" << p.parameter_uncertainty << ") k=" << p.kernel_dimension << " lines=" << p.tangent_lines
              << " sigma2/sigmax=" << p.sigma_second_smallest / std::max(p.sigma_max, 1e-300) << " |rho_AB|/pi="
              << std::abs(p.angles[0]) / kPi << "\n";
  }
  for (const BranchTrace& b : x.branches) {
    std::cout << "  branch " << b.id << " " << b.from_point << "->" << b.to_point << " " << b.stopped_by << " crease "
              << b.stop_crease << " pts " << b.path.size() << " letters " << b.signs_match_assignment << " (first wrong "
              << b.first_wrong_crease << ") maxfold/pi " << b.max_fold / kPi << " res " << b.max_residual
              << " AB end " << b.path.back()[0] << " switches";
    for (const auto& s : b.sign_switches) std::cout << " " << s.crease << "@" << s.driving_value << "(edge " << b.driving_edge << ")";
    std::cout << "\n    signs at departure:";
    if (b.path.size() > 1)
      for (int e = 0; e < 13; ++e) std::cout << (b.path[1][e] > 0 ? " V" : b.path[1][e] < 0 ? " M" : " 0");
    std::cout << "\n";
  }
}

TEST(BranchExplorer, Seed001Type2M) {
  generators::SquareTwistParams sp;
  sp.twist = kPi / 6;
  const CreasePattern p = generators::square_twist_modified(sp, generators::SquareTwistModifiedType::Type2M);
  const BranchExploration x = explore_branches(p, build_topology(p));
  print("type2m", x);
}

TEST(BranchExplorer, Seed001Type1M) {
  generators::SquareTwistParams sp;
  sp.twist = kPi / 6;
  const CreasePattern p = generators::square_twist_modified(sp, generators::SquareTwistModifiedType::Type1M);
  const BranchExploration x = explore_branches(p, build_topology(p));
  print("type1m", x);
}

}  // namespace
}  // namespace rigidfold
namespace rigidfold {
namespace {
TEST(BranchExplorerDebug, SigmaAlongType2MBranch) {
  generators::SquareTwistParams sp;
  sp.twist = kPi / 6;
  const CreasePattern p = generators::square_twist_modified(sp, generators::SquareTwistModifiedType::Type2M);
  const Topology t = build_topology(p);
  const BranchExploration x = explore_branches(p, t);
  const ClosureSystem sys(p, t);
  for (const BranchTrace& b : x.branches) {
    if (b.stopped_by != "bifurcation") continue;
    for (std::size_t i = b.path.size() > 6 ? b.path.size() - 6 : 0; i < b.path.size(); ++i) {
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> J;
      sys.evaluate(sys.unknowns_from_edges(b.path[i]), r, J);
      Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(J)};
      std::cout << "  " << i << " AB/pi " << b.path[i][0] / kPi << " sv: " << svd.singularValues().transpose() << " res " << r.norm() << "\n";
    }
    const Eigen::VectorXd xa = sys.unknowns_from_edges(b.path[b.path.size() - 2]);
    const Eigen::VectorXd xs = sys.unknowns_from_edges(b.path.back());
    const int j = sys.unknown_of_edge(b.driving_edge);
    for (int q = 0; q <= 20; ++q) {
      const double w = 0.9 + 0.01 * q;
      Eigen::VectorXd guess = xa + w * (xs - xa);
      NewtonOptions no;
      no.held_unknowns = {j};
      const NewtonResult nr = newton_project(sys, guess, no);
      Eigen::VectorXd r;
      Eigen::SparseMatrix<double> J;
      sys.evaluate(nr.x, r, J);
      Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(J)};
      std::cout << "  w " << w << " conv " << nr.converged << " sigmin " << svd.singularValues()[11] << " dist " << (nr.x - guess).norm() << " AB/pi " << nr.x[sys.unknown_of_edge(0)] / kPi << "\n";
    }
    break;
  }
}
}  // namespace
}  // namespace rigidfold
