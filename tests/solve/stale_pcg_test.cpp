// The augmented Newton step by CGLS preconditioned with a stale factorisation
// (kernel/solve/stale_pcg.hpp): the same step as the direct solve, a Newton corrector built on
// it converges quadratically to 1e-12, and a preconditioner from a very different G fails to
// converge within the cap (the continuation's cue to refactorise).
#include "kernel/solve/stale_pcg.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "data/generators/miura.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::miura_edge_angles;
using testing::random_vector;

struct Miura {
  generators::MiuraParams m;
  CreasePattern p;
  ClosureSystem sys;
  explicit Miura(int n) : m(params(n)), p(generators::miura_ori(m)), sys(p, build_topology(p)) {}
  static generators::MiuraParams params(int n) {
    generators::MiuraParams m;
    m.rows = m.cols = n;
    m.alpha = 1.1;
    return m;
  }
  Eigen::VectorXd at(double straight) const { return sys.unknowns_from_edges(miura_edge_angles(p, m, straight)); }
};

// The direct step of [J; a^T] dx = [r; c] from a fresh factorisation at J: dx = J^+ r + beta w.
Eigen::VectorXd direct_step(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r, const Eigen::VectorXd& a,
                            double c) {
  MinimumNormSolver fresh(J);
  EXPECT_TRUE(fresh.factorize(J, 1e-14));
  const Eigen::VectorXd d = fresh.solve(J, r);
  const Eigen::VectorXd w = fresh.null_vector(J, a);
  return d + ((c - a.dot(d)) / a.dot(w)) * w;
}

// A corrector iterate at a continuation step of a 20 x 20 Miura (s = 1.0 -> 1.03, 1e-5 rad of
// noise), the factor 0.03 rad behind it: the PCG step equals the direct one to 1e-12 relative.
TEST(SolverStalePcg, StepEqualsTheDirectStepOnAMiuraJacobian) {
  const Miura mi(20);
  const Eigen::VectorXd x_fac = mi.at(1.0);
  std::mt19937_64 rng(7);
  const Eigen::VectorXd x = mi.at(1.03) + random_vector(mi.sys.num_unknowns(), rng, 1e-5);
  Eigen::VectorXd r_fac, r;
  Eigen::SparseMatrix<double> J_fac, J;
  mi.sys.evaluate(x_fac, r_fac, J_fac);
  mi.sys.evaluate(x, r, J);
  MinimumNormSolver stale(J_fac);
  ASSERT_TRUE(stale.factorize(J_fac, 1e-14));
  const Eigen::VectorXd t = (mi.at(1.0 + 1e-6) - x_fac).normalized();  // the tangent at x_fac
  const Eigen::VectorXd w_fac = stale.null_vector(J_fac, t);
  const double c = 2e-5;  // the arclength row's residual
  const Eigen::VectorXd direct = direct_step(J, r, t, c);
  StalePcgOptions o;
  o.relative_tolerance = 1e-13;
  o.max_iterations = 40;
  const StalePcgResult pcg = stale_pcg_step(stale, w_fac, J, r, t, c, o);
  const double rel = (pcg.dx - direct).norm() / direct.norm();
  std::cout << "[ pcg      ] miura 20x20: " << pcg.iterations << " CG iterations, |dx_pcg - dx_direct| / |dx_direct| = "
            << rel << ", |dx| = " << direct.norm() << "\n";
  EXPECT_TRUE(pcg.converged);
  EXPECT_LE(pcg.relative_residual, 1e-13);
  EXPECT_LE(rel, 1e-12);
  EXPECT_LE(pcg.iterations, 20);  // a useful preconditioner: far fewer than the ~n CG would need without
  // The arclength row and J dx agree too (the row holds only up to the Jacobian's smallest
  // singular value off the manifold, for both).
  EXPECT_NEAR(t.dot(pcg.dx), t.dot(direct), 1e-12 * direct.norm());
  EXPECT_LE((J * (pcg.dx - direct)).lpNorm<Eigen::Infinity>(), 1e-12 * r.lpNorm<Eigen::Infinity>());
}

// The stopping criterion (relative tolerance = ||r||_inf, clamped to [1e-10, 1e-4], as the
// continuation uses it): a corrector of PCG steps with a factor from the previous point,
// from the predictor of a 0.05-rad step, has the residuals of the direct Newton corrector
// (fresh factor every step) within 2x at every iteration - the same quadratic convergence -
// and ends at <= 1e-12.
TEST(SolverStalePcg, NewtonWithPcgStepsStaysQuadratic) {
  const Miura mi(20);
  const Eigen::VectorXd xk = mi.at(1.2);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  mi.sys.evaluate(xk, r, J);
  MinimumNormSolver stale(J);
  ASSERT_TRUE(stale.factorize(J, 1e-14));
  const Eigen::VectorXd w_fac = stale.null_vector(J, mi.at(1.2 + 1e-6) - xk);
  const Eigen::VectorXd& t = w_fac;  // the tangent at xk
  const double h = 0.05 / t.lpNorm<Eigen::Infinity>();  // the largest crease moves by 0.05 rad
  const Eigen::VectorXd xp = xk + h * t;
  // The direct corrector's residuals.
  std::vector<double> direct_history;
  Eigen::VectorXd x = xp;
  for (int it = 0; it < 8; ++it) {
    mi.sys.evaluate(x, r, J);
    const double arc = t.dot(x - xk) - h;
    const double res = std::max(r.lpNorm<Eigen::Infinity>(), std::abs(arc));
    direct_history.push_back(res);
    if (res <= 1e-12) break;
    x -= direct_step(J, r, t, arc);
  }
  x = xp;
  std::vector<double> history;
  int cg = 0;
  for (int it = 0; it < 8; ++it) {
    mi.sys.evaluate(x, r, J);
    const double arc = t.dot(x - xk) - h;
    const double res = std::max(r.lpNorm<Eigen::Infinity>(), std::abs(arc));
    history.push_back(res);
    if (res <= 1e-12) break;
    StalePcgOptions o;
    o.relative_tolerance = std::clamp(res, 1e-10, 1e-4);
    o.max_iterations = 40;
    const StalePcgResult step = stale_pcg_step(stale, w_fac, J, r, t, arc, o);
    ASSERT_TRUE(step.converged) << it;
    cg += step.iterations;
    x -= step.dx;
  }
  std::cout << "[ pcg      ] miura 20x20 corrector (" << cg << " CG iterations):";
  for (double v : history) std::cout << " " << v;
  std::cout << "; direct:";
  for (double v : direct_history) std::cout << " " << v;
  std::cout << "\n";
  ASSERT_GE(history.size(), 3u);
  EXPECT_LE(history.back(), 1e-12);
  ASSERT_EQ(history.size(), direct_history.size());
  for (std::size_t k = 1; k < history.size(); ++k) {
    EXPECT_LE(history[k], 2.0 * direct_history[k] + 1e-14) << k;
  }
  // On the Miura path: the closed form at the reached driving angle.
  int driver = -1;
  const auto kinds = generators::miura_crease_kinds(mi.m);
  for (int k = 0; k < mi.sys.num_unknowns() && driver < 0; ++k)
    if (kinds[mi.sys.edge_of_unknown(k)] == generators::MiuraCrease::Straight &&
        mi.p.assignments[mi.sys.edge_of_unknown(k)] == Assignment::Valley)
      driver = k;
  ASSERT_GE(driver, 0);
  EXPECT_LE((x - mi.at(x[driver])).lpNorm<Eigen::Infinity>(), 1e-10);
}

// A preconditioner from a very different G (the same pattern, every column of J scaled by a
// random factor in [0.1, 10]) does not reach the tolerance within the cap: `converged` is
// false after exactly max_iterations, which is where the continuation refactorises.
TEST(SolverStalePcg, BadPreconditionerDoesNotConvergeWithinTheCap) {
  const Miura mi(20);
  const Eigen::VectorXd x = mi.at(1.0);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  mi.sys.evaluate(x, r, J);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> expo(-1.0, 1.0);
  Eigen::SparseMatrix<double> J_bad = J;
  for (int col = 0; col < J_bad.cols(); ++col) J_bad.col(col) *= std::pow(10.0, expo(rng));
  MinimumNormSolver bad(J_bad);
  ASSERT_TRUE(bad.factorize(J_bad, 1e-14));
  const Eigen::VectorXd t = (mi.at(1.0 + 1e-6) - x).normalized();
  const Eigen::VectorXd w_bad = bad.null_vector(J_bad, t);
  const Eigen::VectorXd y = random_vector(static_cast<int>(J.rows()), rng, 1e-6);
  StalePcgOptions o;  // the defaults: 8 iterations
  o.relative_tolerance = 1e-8;
  const StalePcgResult res = stale_pcg_step(bad, w_bad, J, J * t * 1e-3 + y, t, 0.0, o);
  std::cout << "[ pcg      ] bad preconditioner: " << res.iterations << " iterations, relative residual "
            << res.relative_residual << "\n";
  EXPECT_FALSE(res.converged);
  EXPECT_EQ(res.iterations, o.max_iterations);
  EXPECT_GT(res.relative_residual, o.relative_tolerance);
  // The same solve with the factor of J itself converges within the cap.
  MinimumNormSolver good(J);
  ASSERT_TRUE(good.factorize(J, 1e-14));
  const StalePcgResult ok = stale_pcg_step(good, good.null_vector(J, t), J, J * t * 1e-3 + y, t, 0.0, o);
  EXPECT_TRUE(ok.converged);
  EXPECT_LT(ok.iterations, o.max_iterations);
}

TEST(SolverStalePcg, RejectsHeldUnknownsAndWrongSizes) {
  const Miura mi(3);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  mi.sys.evaluate(mi.at(1.0), r, J);
  MinimumNormSolver held(J, {0});
  ASSERT_TRUE(held.factorize(J, 1e-14));
  const Eigen::VectorXd a = Eigen::VectorXd::Ones(J.cols());
  EXPECT_THROW(stale_pcg_step(held, a, J, r, a, 0.0), std::invalid_argument);
  MinimumNormSolver free(J);
  ASSERT_TRUE(free.factorize(J, 1e-14));
  EXPECT_THROW(stale_pcg_step(free, a, J, Eigen::VectorXd::Zero(2), a, 0.0), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold
