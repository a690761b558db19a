// Newton projection: quadratic convergence to 1e-12 rad from a perturbed Miura state, and the
// closed form recovered when the driving crease is held.
#include "kernel/solve/newton_projection.hpp"

#include <Eigen/QR>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

#include "data/generators/miura.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::miura_edge_angles;
using testing::random_vector;

void print_history(const char* name, const NewtonResult& res) {
  std::cout << "[ newton   ] " << name << ":";
  for (double r : res.residual_history) std::cout << " " << r;
  std::cout << "  (factorizations " << res.factorizations << ", analyses " << res.symbolic_analyses << ")\n";
}

// Asserts r_{k+1} <= C r_k^2 on the steps that start above the round-off floor.
void expect_quadratic(const std::vector<double>& h, double C) {
  ASSERT_GE(h.size(), 3u);
  int checked = 0;
  for (std::size_t k = 0; k + 1 < h.size(); ++k) {
    if (h[k] < 1e-7) continue;  // below this the next residual is at round-off level anyway
    EXPECT_LE(h[k + 1], C * h[k] * h[k]) << "step " << k;
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

TEST(SolverNewton, PerturbedMiuraConvergesQuadratically) {
  generators::MiuraParams m;
  m.rows = 6;
  m.cols = 7;
  m.alpha = 1.2;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  std::mt19937_64 rng(11);
  for (double s : {0.5, 1.5, 2.6}) {
    const Eigen::VectorXd exact = sys.unknowns_from_edges(miura_edge_angles(p, m, s));
    const Eigen::VectorXd x0 = exact + random_vector(sys.num_unknowns(), rng, 1e-3);
    const NewtonResult res = newton_project(sys, x0);
    print_history("miura 6x7 +1e-3", res);
    EXPECT_TRUE(res.converged);
    EXPECT_LE(res.residual_history.back(), 1e-12);
    EXPECT_LE(res.iterations, 6);
    EXPECT_EQ(res.symbolic_analyses, 1);
    expect_quadratic(res.residual_history, 100.0);
    // Minimum-norm steps move the point by about the size of the perturbation, not more.
    EXPECT_LE((res.x - x0).lpNorm<Eigen::Infinity>(), 1e-2);
  }
}

TEST(SolverNewton, HeldDrivingCreaseRecoversClosedForm) {
  generators::MiuraParams m;
  m.rows = 5;
  m.cols = 4;
  m.alpha = 0.9;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  const auto kinds = generators::miura_crease_kinds(m);
  int driver = -1;
  for (int k = 0; k < sys.num_unknowns() && driver < 0; ++k)
    if (kinds[sys.edge_of_unknown(k)] == generators::MiuraCrease::Straight) driver = k;
  ASSERT_GE(driver, 0);
  std::mt19937_64 rng(3);
  for (double s : {0.3, 1.2, 2.9}) {
    const Eigen::VectorXd exact = sys.unknowns_from_edges(miura_edge_angles(p, m, s));
    Eigen::VectorXd x0 = exact + random_vector(sys.num_unknowns(), rng, 1e-3);
    x0[driver] = exact[driver];
    NewtonOptions opt;
    opt.held_unknowns = {driver};
    const NewtonResult res = newton_project(sys, x0, opt);
    print_history("miura 5x4 held driver", res);
    EXPECT_TRUE(res.converged);
    EXPECT_EQ(res.x[driver], exact[driver]);
    EXPECT_LE((res.x - exact).lpNorm<Eigen::Infinity>(), 1e-10) << s;
    std::cout << "[ newton   ] s = " << s << " max |x - closed form| = " << (res.x - exact).lpNorm<Eigen::Infinity>()
              << "\n";
  }
}

TEST(SolverNewton, SameAnswerWithFixedCreaseInTheSystem) {
  generators::MiuraParams m;
  m.rows = m.cols = 4;
  const CreasePattern p = generators::miura_ori(m);
  const Topology t = build_topology(p);
  const auto kinds = generators::miura_crease_kinds(m);
  int driver_edge = -1;
  for (int e = 0; e < p.num_edges() && driver_edge < 0; ++e)
    if (kinds[e] == generators::MiuraCrease::Straight && t.edge_is_hinge[e]) driver_edge = e;
  const Eigen::VectorXd rho = miura_edge_angles(p, m, 1.0);
  ClosureOptions copt;
  copt.fixed = {{driver_edge, rho[driver_edge]}};
  const ClosureSystem sys(p, t, copt);
  std::mt19937_64 rng(9);
  const Eigen::VectorXd exact = sys.unknowns_from_edges(rho);
  const NewtonResult res = newton_project(sys, exact + random_vector(sys.num_unknowns(), rng, 1e-3));
  EXPECT_TRUE(res.converged);
  EXPECT_LE((res.x - exact).lpNorm<Eigen::Infinity>(), 1e-10);
}

TEST(SolverNewton, ReportsNonConvergenceWithoutThrowing) {
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  NewtonOptions opt;
  opt.max_iterations = 1;
  std::mt19937_64 rng(2);
  const NewtonResult res = newton_project(sys, random_vector(sys.num_unknowns(), rng, 1.0), opt);
  EXPECT_FALSE(res.converged);
  EXPECT_EQ(res.residual_history.size(), 2u);
  EXPECT_THROW(newton_project(sys, Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

// A perturbed Miura with a crease held at a fold has no solution: Gauss-Newton settles on
// a least-squares plateau. With the stall test it stops there early, at the same least
// residual (within 1%) as the full 60-step run; a converging projection is not cut short.
// Every unknown held (listed twice, too): nothing to solve for. It used to crash in the
// factorisation of an empty system; now the start is returned, converged iff it closes.
TEST(SolverNewton, EveryUnknownHeldReturnsTheStart) {
  const double q = std::numbers::pi / 2;
  const CreasePattern p = testing::single_vertex_pattern({0.0, q, 2 * q, 3 * q});
  const ClosureSystem sys(p, build_topology(p));
  NewtonOptions opt;
  opt.held_unknowns = {0, 1, 2, 3, 1};
  Eigen::VectorXd closed(4), open(4);
  closed << 0.5, 0, 0.5, 0;  // one straight line folded: closes exactly
  open << 0.5, 0.1, 0.5, 0;
  const NewtonResult a = newton_project(sys, closed, opt);
  EXPECT_TRUE(a.converged);
  EXPECT_EQ(a.iterations, 0);
  EXPECT_EQ(a.x, closed);
  const NewtonResult b = newton_project(sys, open, opt);
  EXPECT_FALSE(b.converged);
  EXPECT_EQ(b.x, open);
}

TEST(SolverNewton, StallTestStopsOnAPlateauButNotWhileConverging) {
  generators::MiuraParams m;
  m.rows = m.cols = 6;
  m.perturbation = 0.1;
  m.seed = 3;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  std::mt19937_64 rng(4);
  Eigen::VectorXd x0 = random_vector(sys.num_unknowns(), rng, 0.2);
  x0[0] = 0.3;
  NewtonOptions full;
  full.held_unknowns = {0};
  full.max_iterations = 60;
  NewtonOptions stall = full;
  stall.stall_window = 5;
  const NewtonResult a = newton_project(sys, x0, full), b = newton_project(sys, x0, stall);
  ASSERT_FALSE(a.converged);
  ASSERT_FALSE(b.converged);
  const double least_a = *std::min_element(a.residual_history.begin(), a.residual_history.end());
  const double least_b = *std::min_element(b.residual_history.begin(), b.residual_history.end());
  std::cout << "[ newton   ] plateau: full " << a.iterations << " steps, least " << least_a << "; stall test "
            << b.iterations << " steps, least " << least_b << "\n";
  EXPECT_LT(b.iterations, a.iterations);
  EXPECT_LE(least_b, 1.01 * least_a);
  EXPECT_GT(least_a, 1e-6);  // a real plateau, not a slow convergence

  generators::MiuraParams q = m;
  q.perturbation = 0.0;
  const CreasePattern pq = generators::miura_ori(q);
  const ClosureSystem sq(pq, build_topology(pq));
  const NewtonResult c = newton_project(sq, x0, stall);
  EXPECT_TRUE(c.converged);
}

// Projected Gauss-Newton (sign_bounds): every iterate keeps the signs asked for, a start
// whose unconstrained projection would flip a crease converges to a point that does not,
// and the bound vector's size is checked.
TEST(SolverNewton, SignBoundsKeepEveryIterateOnItsSide) {
  generators::MiuraParams m;
  m.rows = m.cols = 3;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  const int n = sys.num_unknowns();
  // The Miura's own signs at a fold: start there, scrambled by noise large enough to flip
  // several small creases of the start.
  const Eigen::VectorXd fold = sys.unknowns_from_edges(miura_edge_angles(p, m, 0.4));
  std::vector<int> bounds(n);
  for (int i = 0; i < n; ++i) bounds[i] = fold[i] > 0 ? 1 : -1;
  std::mt19937_64 rng(9);
  Eigen::VectorXd x0 = fold + random_vector(n, rng, 0.3);
  int flipped = 0;
  for (int i = 0; i < n; ++i) flipped += bounds[i] * x0[i] < 0;
  NewtonOptions opt;
  opt.sign_bounds = bounds;
  opt.max_iterations = 60;
  const NewtonResult res = newton_project(sys, x0, opt);
  print_history("sign bounds", res);
  EXPECT_TRUE(res.converged);
  for (int i = 0; i < n; ++i) EXPECT_GE(bounds[i] * res.x[i], 0.0) << "unknown " << i;
  std::cout << "[ newton   ] " << flipped << " of " << n << " start entries on the wrong side\n";
  opt.sign_bounds.pop_back();
  EXPECT_THROW(newton_project(sys, x0, opt), std::invalid_argument);
}

// The factor kind (CHOLMOD simplicial or supernodal, chosen by kSupernodalFlopsPerEntry) must
// not change the answer: both give the minimum-norm step of a dense complete orthogonal
// decomposition and the same null vector, with and without a held crease (the singular G of
// a 1-DOF Miura, regularised by lambda, and the regular one).
TEST(MinimumNormSolverFactor, SupernodalAndSimplicialFactorsGiveTheDenseMinimumNormStep) {
  generators::MiuraParams m;
  m.rows = 12;
  m.cols = 13;
  m.alpha = 1.1;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  std::mt19937_64 rng(17);
  const Eigen::VectorXd exact = sys.unknowns_from_edges(miura_edge_angles(p, m, 1.3));
  const Eigen::VectorXd x = exact + random_vector(sys.num_unknowns(), rng, 1e-4);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(x, r, J);
  const Eigen::VectorXd guess = Eigen::VectorXd::Ones(sys.num_unknowns());
  for (const std::vector<int>& held : {std::vector<int>{}, std::vector<int>{0}}) {
    // Dense reference: the minimum-norm least-squares solution of J_f dx = r.
    Eigen::MatrixXd Jf = Eigen::MatrixXd(J);
    for (int k : held) Jf.col(k).setZero();
    const Eigen::VectorXd reference = Jf.completeOrthogonalDecomposition().solve(r);
    MinimumNormSolver simplicial(J, held, FactorOrdering::kDefault, std::numeric_limits<double>::infinity());
    MinimumNormSolver supernodal(J, held, FactorOrdering::kDefault, 0.0);
    MinimumNormSolver by_default(J, held);
    ASSERT_TRUE(simplicial.factorize(J, 1e-14));
    ASSERT_TRUE(supernodal.factorize(J, 1e-14));
    ASSERT_TRUE(by_default.factorize(J, 1e-14));
    EXPECT_FALSE(simplicial.supernodal());
    EXPECT_TRUE(supernodal.supernodal());
    EXPECT_FALSE(by_default.supernodal()) << "a few hundred unknowns stay below the switch";
    const Eigen::VectorXd a = simplicial.solve(J, r), b = supernodal.solve(J, r);
    const double scale = reference.lpNorm<Eigen::Infinity>();
    EXPECT_LE((a - reference).lpNorm<Eigen::Infinity>(), 1e-8 * scale) << held.size();
    EXPECT_LE((b - reference).lpNorm<Eigen::Infinity>(), 1e-8 * scale) << held.size();
    EXPECT_LE((a - b).lpNorm<Eigen::Infinity>(), 1e-10 * scale) << held.size();
  }
  // The null vector of the exact (1-DOF) state, by inverse iteration on either factor.
  Eigen::VectorXd r0;
  Eigen::SparseMatrix<double> J0;
  sys.evaluate(exact, r0, J0);
  MinimumNormSolver simplicial(J0, {}, FactorOrdering::kDefault, std::numeric_limits<double>::infinity());
  MinimumNormSolver supernodal(J0, {}, FactorOrdering::kDefault, 0.0);
  ASSERT_TRUE(simplicial.factorize(J0, 1e-14));
  ASSERT_TRUE(supernodal.factorize(J0, 1e-14));
  const Eigen::VectorXd wa = simplicial.null_vector(J0, guess), wb = supernodal.null_vector(J0, guess);
  EXPECT_LE((wa - wb).lpNorm<Eigen::Infinity>(), 1e-10);
  EXPECT_LE((J0 * wb).lpNorm<Eigen::Infinity>(), 1e-13);
  EXPECT_THROW(MinimumNormSolver(J, {}, FactorOrdering::kDefault, -1.0), std::invalid_argument);
}

// Stale-factor Newton steps (NewtonOptions::stale_factor_min_unknowns = 0 forces them at this
// size): the same converged point as fresh factorisations, fewer factorisations, and the
// fallback to a fresh factor when the stale solve is not allowed to converge.
TEST(SolverNewton, StaleFactorStepsReachTheSamePointWithFewerFactorisations) {
  generators::MiuraParams m;
  m.rows = 14;
  m.cols = 15;
  m.alpha = 1.05;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  std::mt19937_64 rng(23);
  const Eigen::VectorXd exact = sys.unknowns_from_edges(miura_edge_angles(p, m, 1.7));
  Eigen::VectorXd x0 = exact + random_vector(sys.num_unknowns(), rng, 1e-3);
  x0[0] = exact[0];
  for (const std::vector<int>& held : {std::vector<int>{0}, std::vector<int>{}}) {
    NewtonOptions fresh_opt, stale_opt;
    fresh_opt.held_unknowns = stale_opt.held_unknowns = held;
    fresh_opt.stale_factor_min_unknowns = std::numeric_limits<int>::max();
    stale_opt.stale_factor_min_unknowns = 0;
    const NewtonResult fresh = newton_project(sys, x0, fresh_opt);
    const NewtonResult stale = newton_project(sys, x0, stale_opt);
    print_history("miura 14x15 stale-factor steps", stale);
    ASSERT_TRUE(fresh.converged);
    ASSERT_TRUE(stale.converged);
    EXPECT_EQ(fresh.stale_steps, 0);
    EXPECT_GE(stale.stale_steps, 1) << held.size();
    EXPECT_EQ(stale.stale_rejections, 0) << held.size();
    EXPECT_LT(stale.factorizations, fresh.factorizations) << held.size();
    EXPECT_EQ(stale.factorizations + stale.stale_steps, stale.iterations) << "one factorisation per fresh step";
    EXPECT_LE(stale.residual_history.back(), 1e-12);
    expect_quadratic(stale.residual_history, 1e4);
    if (!held.empty()) {
      // Full column rank: one solution on the manifold through the held crease's value.
      EXPECT_LE((stale.x - exact).lpNorm<Eigen::Infinity>(), 1e-10);
      EXPECT_LE((stale.x - fresh.x).lpNorm<Eigen::Infinity>(), 1e-10);
    } else {
      // 1 DOF free: the first step is the same fresh minimum-norm step; the later ones are
      // least-squares steps, not necessarily of minimum norm, so the end points may differ
      // along the manifold, but by no more than the size of those later steps (~ the residual
      // left after the first step), not by the size of the whole correction.
      const double later = 10 * stale.residual_history[1];
      EXPECT_NEAR((stale.x - x0).norm(), (fresh.x - x0).norm(), later);
      EXPECT_LE((stale.x - fresh.x).lpNorm<Eigen::Infinity>(), later);
    }
  }
  // No CGLS iteration allowed: every stale attempt is rejected and a fresh factorisation
  // takes the step, as without stale steps.
  NewtonOptions none;
  none.held_unknowns = {0};
  none.stale_factor_min_unknowns = 0;
  none.stale_max_iterations = 0;
  const NewtonResult fallback = newton_project(sys, x0, none);
  EXPECT_TRUE(fallback.converged);
  EXPECT_EQ(fallback.stale_steps, 0);
  EXPECT_GE(fallback.stale_rejections, 1);
  EXPECT_EQ(fallback.factorizations, fallback.iterations);
  EXPECT_LE((fallback.x - exact).lpNorm<Eigen::Infinity>(), 1e-10);
}

// MinimumNormSolver::solve_with_stale_factor against the direct solve on a fresh factor at a
// point 1e-3 rad away from the factor's (regular G: one crease held).
TEST(MinimumNormSolverFactor, StaleFactorSolveMatchesTheFreshLeastSquaresStep) {
  generators::MiuraParams m;
  m.rows = 10;
  m.cols = 11;
  m.alpha = 1.2;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  std::mt19937_64 rng(29);
  const Eigen::VectorXd exact = sys.unknowns_from_edges(miura_edge_angles(p, m, 0.9));
  const Eigen::VectorXd xo = exact + random_vector(sys.num_unknowns(), rng, 1e-3);
  const Eigen::VectorXd x = exact + random_vector(sys.num_unknowns(), rng, 1e-3);
  Eigen::VectorXd ro, r;
  Eigen::SparseMatrix<double> Jo, J;
  sys.evaluate(xo, ro, Jo);
  sys.evaluate(x, r, J);
  MinimumNormSolver stale(Jo, {0}), fresh(J, {0});
  ASSERT_TRUE(stale.factorize(Jo, 1e-14));
  ASSERT_TRUE(fresh.factorize(J, 1e-14));
  const Eigen::VectorXd reference = fresh.solve(J, r);
  const StaleSolveResult s = stale.solve_with_stale_factor(J, r, 1e-12, 50);
  ASSERT_TRUE(s.converged);
  EXPECT_GE(s.iterations, 2) << "a stale factor is not the exact inverse";
  EXPECT_LE(s.relative_residual, 1e-12);
  EXPECT_EQ(s.dx[0], 0.0) << "held unknown";
  EXPECT_LE((s.dx - reference).lpNorm<Eigen::Infinity>(), 1e-9 * reference.lpNorm<Eigen::Infinity>());
  // Too few iterations: reported as not converged, with no step.
  const StaleSolveResult short_run = stale.solve_with_stale_factor(J, r, 1e-12, 1);
  EXPECT_FALSE(short_run.converged);
  EXPECT_EQ(short_run.iterations, 1);
  EXPECT_EQ(short_run.dx.lpNorm<Eigen::Infinity>(), 0.0);
}

}}  // namespace
}  // namespace rigidfold
