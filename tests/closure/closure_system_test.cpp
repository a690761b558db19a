// ClosureSystem: unknown map, residual at closed-form states, exact Jacobian against central
// finite differences, fixed creases and equality rows, holes rejected.
#include "kernel/closure/closure_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <numbers>
#include <iostream>
#include <random>

#include "data/generators/miura.hpp"
#include "data/generators/square_twist.hpp"
#include "data/generators/waterbomb.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::miura_edge_angles;
using testing::random_vector;

// max |J - J_fd| / max(1, max |J|) with central differences of step h.
double jacobian_fd_error(const ClosureSystem& sys, const Eigen::VectorXd& x, double h = 1e-6) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(x, r, J);
  EXPECT_LE((r - sys.residual(x)).lpNorm<Eigen::Infinity>(), 1e-15);
  const Eigen::MatrixXd Jd = Eigen::MatrixXd(J);
  Eigen::MatrixXd Jfd(sys.num_rows(), sys.num_unknowns());
  for (int k = 0; k < sys.num_unknowns(); ++k) {
    Eigen::VectorXd xp = x, xm = x;
    xp[k] += h;
    xm[k] -= h;
    Jfd.col(k) = (sys.residual(xp) - sys.residual(xm)) / (2 * h);
  }
  return (Jd - Jfd).cwiseAbs().maxCoeff() / std::max(1.0, Jd.cwiseAbs().maxCoeff());
}

TEST(ClosureSystem, MiuraUnknownsAreTheInteriorCreases) {
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 5;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  // straight interior creases (rows-1)*cols, zig-zag rows*(cols-1)
  EXPECT_EQ(sys.num_unknowns(), 3 * 5 + 4 * 4);
  EXPECT_EQ(sys.num_vertices(), 3 * 4);
  EXPECT_EQ(sys.num_rows(), 36);
  for (int k = 0; k < sys.num_unknowns(); ++k) EXPECT_EQ(sys.unknown_of_edge(sys.edge_of_unknown(k)), k);
  for (int e = 0; e < p.num_edges(); ++e)
    if (p.assignments[e] == Assignment::Boundary) {
      EXPECT_EQ(sys.unknown_of_edge(e), -1);
    }
}

TEST(ClosureSystem, MiuraClosedFormClosesInFoldSignConvention) {
  generators::MiuraParams m;
  m.rows = 5;
  m.cols = 4;
  m.alpha = 1.1;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  for (double s : {-2.5, -0.3, 1e-4, 0.7, 2.9}) {
    const Eigen::VectorXd x = sys.unknowns_from_edges(miura_edge_angles(p, m, s));
    EXPECT_LE(sys.residual(x).lpNorm<Eigen::Infinity>(), 1e-13) << s;
    // Reversing only the zig-zag signs breaks the closure: the sign convention matters.
    Eigen::VectorXd rho = miura_edge_angles(p, m, s);
    const auto kinds = generators::miura_crease_kinds(m);
    for (int e = 0; e < p.num_edges(); ++e)
      if (kinds[e] == generators::MiuraCrease::ZigZag) rho[e] = -rho[e];
    if (std::fabs(s) > 0.1) {  // (near flat the error is second order in s)
      EXPECT_GT(sys.residual(sys.unknowns_from_edges(rho)).lpNorm<Eigen::Infinity>(), 1e-3) << s;
    }
  }
  const Eigen::VectorXd back = sys.edges_from_unknowns(sys.unknowns_from_edges(miura_edge_angles(p, m, 0.7)));
  EXPECT_LE((back - miura_edge_angles(p, m, 0.7)).lpNorm<Eigen::Infinity>(), 0.0);
}

TEST(ClosureSystem, JacobianMatchesFiniteDifferences) {
  std::mt19937_64 rng(7);
  std::vector<CreasePattern> patterns;
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 3;
  patterns.push_back(generators::miura_ori(m));
  m.perturbation = 0.1;
  m.seed = 3;
  patterns.push_back(generators::miura_ori(m));
  generators::SquareTwistParams st;
  patterns.push_back(generators::square_twist(st, generators::SquareTwistType::Type3));
  patterns.push_back(generators::square_twist_modified(st, generators::SquareTwistModifiedType::Type2M));
  for (int n : {3, 4, 6}) patterns.push_back(generators::waterbomb_base(generators::WaterbombParams{n, 1.0, true}));
  double worst = 0;
  for (std::size_t i = 0; i < patterns.size(); ++i) {
    const ClosureSystem sys(patterns[i], build_topology(patterns[i]));
    ASSERT_GT(sys.num_unknowns(), 0);
    for (double amplitude : {0.3, 1.5, 2.8}) {
      const Eigen::VectorXd x = random_vector(sys.num_unknowns(), rng, amplitude);
      const double err = jacobian_fd_error(sys, x);
      EXPECT_LE(err, 1e-7) << "pattern " << i << " amplitude " << amplitude;
      worst = std::max(worst, err);
    }
  }
  std::cout << "[ closure  ] worst relative Jacobian error vs central differences (h = 1e-6): " << worst << "\n";
}

TEST(ClosureSystem, FlatAndJoinHingesAreRigid) {
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  int flat_edge = -1, join_edge = -1;
  for (int e = 0; e < p.num_edges(); ++e) {
    if (!t.edge_is_hinge[e]) continue;
    if (flat_edge < 0) flat_edge = e, p.assignments[e] = Assignment::Flat;
    else if (join_edge < 0) join_edge = e, p.assignments[e] = Assignment::Join;
  }
  const ClosureSystem full(generators::miura_ori(m), t);
  const ClosureSystem sys(p, t);
  EXPECT_EQ(sys.num_unknowns(), full.num_unknowns() - 2);
  EXPECT_EQ(sys.unknown_of_edge(flat_edge), -1);
  EXPECT_EQ(sys.unknown_of_edge(join_edge), -1);
  std::mt19937_64 rng(1);
  const Eigen::VectorXd x = random_vector(sys.num_unknowns(), rng, 1.0);
  const Eigen::VectorXd rho = sys.edges_from_unknowns(x);
  EXPECT_EQ(rho[flat_edge], 0.0);
  EXPECT_EQ(rho[join_edge], 0.0);
  EXPECT_LE((sys.residual(x) - full.residual(full.unknowns_from_edges(rho))).lpNorm<Eigen::Infinity>(), 0.0);
}

TEST(ClosureSystem, FixedCreasesAreConstantsAndEqualitiesAreRows) {
  generators::MiuraParams m;
  m.rows = 3;
  m.cols = 4;
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const ClosureSystem full(p, t);
  const int e0 = full.edge_of_unknown(0), e1 = full.edge_of_unknown(1), e2 = full.edge_of_unknown(2);
  ClosureOptions opt;
  opt.fixed = {{e0, 0.4}};
  opt.equalities = {{e1, e2, -1.0}};
  ClosureSystem sys(p, t, opt);
  EXPECT_EQ(sys.num_unknowns(), full.num_unknowns() - 1);
  EXPECT_EQ(sys.num_rows(), full.num_rows() + 1);
  std::mt19937_64 rng(5);
  Eigen::VectorXd x = random_vector(sys.num_unknowns(), rng, 1.0);
  Eigen::VectorXd rho = sys.edges_from_unknowns(x);
  EXPECT_EQ(rho[e0], 0.4);
  const Eigen::VectorXd r = sys.residual(x);
  EXPECT_LE((r.head(full.num_rows()) - full.residual(full.unknowns_from_edges(rho))).lpNorm<Eigen::Infinity>(), 0.0);
  EXPECT_NEAR(r[full.num_rows()], rho[e1] + rho[e2], 1e-15);
  EXPECT_LE(jacobian_fd_error(sys, x), 1e-7);
  sys.set_fixed_value(e0, -0.2);
  EXPECT_EQ(sys.edges_from_unknowns(x)[e0], -0.2);
  EXPECT_THROW(sys.set_fixed_value(e1, 0.0), std::invalid_argument);
  ClosureOptions bad;
  bad.fixed = {{p.num_edges(), 0.0}};
  EXPECT_THROW(ClosureSystem(p, t, bad), std::invalid_argument);
}

TEST(ClosureSystem, SheetWithHoleIsRejected) {
  // A 3x3 Miura without its central panel: an annulus.
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  CreasePattern p = generators::miura_ori(m);
  // The central panel is the one whose vertices are all interior nodes (i, j), i, j in {1, 2}.
  auto interior_node = [&](int v) {
    const int i = v % (m.cols + 1), j = v / (m.cols + 1);
    return i > 0 && i < m.cols && j > 0 && j < m.rows;
  };
  std::erase_if(p.faces, [&](const std::vector<int>& f) {
    return std::all_of(f.begin(), f.end(), interior_node);
  });
  ASSERT_EQ(p.num_faces(), 8);
  const Topology t = build_topology(p);
  try {
    ClosureSystem sys(p, t);
    FAIL() << "expected a runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("holes not supported yet"), std::string::npos) << e.what();
  }
}

}}  // namespace
}  // namespace rigidfold
