// Continuation by the fold's size (kernel/solve/norm_continuation.hpp):
//   - on the Miura-ori (DOF 1, so the family is its one curve) every point, out to 170 degrees
//     and back toward flat to 1/100 of the start's size, agrees with the closed form;
//   - on the waterbomb base (DOF 5) with the letters' margin every point closes and keeps
//     every M/V crease on its side by at least the margin;
//   - bad arguments are refused.
#include "kernel/solve/norm_continuation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "data/generators/miura.hpp"
#include "data/generators/waterbomb.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/topology.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "tests/closure/closure_test_utils.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

using testing::miura_edge_angles;

Eigen::VectorXd half_turn_box(int n, double sign) { return Eigen::VectorXd::Constant(n, sign * std::numbers::pi); }

TEST(NormContinuation, FollowsTheMiuraClosedFormOutAndTowardFlat) {
  generators::MiuraParams m;
  m.rows = 4;
  m.cols = 5;
  m.alpha = 1.1;
  const CreasePattern p = generators::miura_ori(m);
  const ClosureSystem sys(p, build_topology(p));
  const int n = sys.num_unknowns();
  // The closed form's parameter (the straight creases' fold) of a point on the mode, from the
  // largest |rho| (a zig-zag crease: |rho_z| = 2 atan(tan(|rho_s|/2) / cos(alpha)) is monotone).
  auto exact_at = [&](const Eigen::VectorXd& x) {
    const double z = x.cwiseAbs().maxCoeff();
    const double s = 2 * std::atan(std::tan(z / 2) * std::cos(m.alpha));
    const Eigen::VectorXd plus = sys.unknowns_from_edges(miura_edge_angles(p, m, s));
    const Eigen::VectorXd minus = sys.unknowns_from_edges(miura_edge_angles(p, m, -s));
    return (x - plus).norm() < (x - minus).norm() ? plus : minus;
  };
  const Eigen::VectorXd x0 = sys.unknowns_from_edges(miura_edge_angles(p, m, 0.3));
  NormContinuationOptions opt;
  double worst = 0, last_size = x0.norm();
  int points = 0;
  auto check = [&](const Eigen::VectorXd& x, bool outward) {
    ++points;
    EXPECT_LE(sys.residual(x).lpNorm<Eigen::Infinity>(), 1e-12);
    worst = std::max(worst, (x - exact_at(x)).lpNorm<Eigen::Infinity>());
    if (outward) EXPECT_GT(x.norm(), last_size);
    else EXPECT_LT(x.norm(), last_size);
    last_size = x.norm();
  };
  // Out until a zig-zag crease passes 170 degrees.
  opt.target_size = 1e3;
  const NormContinuationResult out =
      continue_by_norm(sys, x0, half_turn_box(n, -1), half_turn_box(n, 1), opt, [&](const Eigen::VectorXd& x) {
        check(x, true);
        return x.cwiseAbs().maxCoeff() >= to_radians(170.0);
      });
  EXPECT_EQ(out.reason, "stopped by the caller");
  EXPECT_EQ(out.rejected_steps, 0);
  EXPECT_GE(points, 10);
  // Toward flat, to 1/100 of the start's size.
  last_size = x0.norm();
  opt.target_size = x0.norm() / 100;
  const NormContinuationResult in = continue_by_norm(sys, x0, half_turn_box(n, -1), half_turn_box(n, 1), opt,
                                                     [&](const Eigen::VectorXd& x) {
                                                       check(x, false);
                                                       return false;
                                                     });
  EXPECT_TRUE(in.reached) << in.reason;
  EXPECT_LE(in.last_size, x0.norm() / 100);
  EXPECT_LE(worst, 1e-10);
  std::cout << "[ norm-cont ] miura 4x5: " << points << " points, worst error against the closed form " << worst
            << " rad\n";
}

TEST(NormContinuation, KeepsEveryLetterByItsMarginOnTheWaterbombBase) {
  const CreasePattern p = generators::waterbomb_base({});
  const ClosureSystem sys(p, build_topology(p));
  const int n = sys.num_unknowns();
  std::vector<int> sign(n);
  for (int i = 0; i < n; ++i) sign[i] = assigned_fold_sign(p.assignments[sys.edge_of_unknown(i)]);
  // A folded point with the letters' signs: a signed start, one crease held, the rest projected.
  Eigen::VectorXd x0(n);
  for (int i = 0; i < n; ++i) x0[i] = sign[i] * (0.1 + 0.02 * i);
  NewtonOptions nopt;
  nopt.held_unknowns = {0};
  const NewtonResult nr = newton_project(sys, x0, nopt);
  ASSERT_TRUE(nr.converged);
  for (int i = 0; i < n; ++i) ASSERT_GT(sign[i] * nr.x[i], 0) << i;
  NormContinuationOptions opt;
  opt.sign_floor = sign;
  for (double target : {nr.x.norm() / 100, 3.0}) {
    opt.target_size = target;
    int points = 0;
    double least_ratio = 1e300;  // min over points and creases of s_i x_i / (margin ||x||)
    const NormContinuationResult res = continue_by_norm(
        sys, nr.x, half_turn_box(n, -1), half_turn_box(n, 1), opt, [&](const Eigen::VectorXd& x) {
          ++points;
          EXPECT_LE(sys.residual(x).lpNorm<Eigen::Infinity>(), 1e-12);
          for (int i = 0; i < n; ++i) least_ratio = std::min(least_ratio, sign[i] * x[i] / (opt.sign_margin * x.norm()));
          return x.cwiseAbs().maxCoeff() >= to_radians(150.0);
        });
    EXPECT_GE(points, 5) << target;
    EXPECT_GE(least_ratio, 1.0 - 1e-9) << target;
    if (target < 1) {
      EXPECT_TRUE(res.reached) << res.reason;
    }
    std::cout << "[ norm-cont ] waterbomb base to size " << target << ": " << points << " points, " << res.reason
              << ", least letter margin ratio " << least_ratio << "\n";
  }
}

TEST(NormContinuation, RefusesBadArguments) {
  const CreasePattern p = generators::waterbomb_base({});
  const ClosureSystem sys(p, build_topology(p));
  const int n = sys.num_unknowns();
  const Eigen::VectorXd lo = half_turn_box(n, -1), hi = half_turn_box(n, 1);
  NormContinuationOptions opt;
  opt.target_size = 1;
  auto none = [](const Eigen::VectorXd&) { return false; };
  EXPECT_THROW(continue_by_norm(sys, Eigen::VectorXd::Zero(n), lo, hi, opt, none), std::invalid_argument);
  EXPECT_THROW(continue_by_norm(sys, Eigen::VectorXd::Ones(n + 1), lo, hi, opt, none), std::invalid_argument);
  opt.target_size = 0;
  EXPECT_THROW(continue_by_norm(sys, Eigen::VectorXd::Ones(n), lo, hi, opt, none), std::invalid_argument);
  opt.target_size = 1;
  opt.sign_margin = -1;
  EXPECT_THROW(continue_by_norm(sys, Eigen::VectorXd::Ones(n), lo, hi, opt, none), std::invalid_argument);
  opt.sign_margin = 1e-5;
  opt.sign_floor = {1};
  EXPECT_THROW(continue_by_norm(sys, Eigen::VectorXd::Ones(n), lo, hi, opt, none), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold
