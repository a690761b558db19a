// SE(3) loop closure of thick-panel patterns (kernel/thick/thick_closure_system.hpp):
// the DH transform against the seed's explicit matrix, the exact sparse Jacobian against
// central differences on a pattern of three loops sharing creases, the spherical limit
// against the zero-thickness vertex loop, input errors, and the single-loop sheet adapter.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "kernel/closure/closure_system.hpp"
#include "kernel/thick/dh_link.hpp"
#include "kernel/thick/thick_closure_system.hpp"
#include "kernel/thick/thick_sheet.hpp"
#include "kernel/thick/thick_vertex_models.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

// Seed 003 eq. (1-2), written out entry by entry (independent of dh_transform's products).
Eigen::Matrix4d seed_dh_matrix(double theta, double R, double a, double alpha) {
  const double ct = std::cos(theta), st = std::sin(theta), ca = std::cos(alpha), sa = std::sin(alpha);
  Eigen::Matrix4d T;
  T << ct, -ca * st, sa * st, a * ct,
       st, ca * ct, -sa * ct, a * st,
       0, sa, ca, R,
       0, 0, 0, 1;
  return T;
}

TEST(ThickDh, TransformIsTheSeedMatrix) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-4, 4), length(-2, 2);
  for (int k = 0; k < 50; ++k) {
    const double theta = angle(rng);
    DhLink link{length(rng), length(rng), angle(rng)};
    const Eigen::Matrix4d expected = seed_dh_matrix(theta, link.offset, link.length, link.twist);
    EXPECT_LE((dh_transform(theta, link).matrix() - expected).cwiseAbs().maxCoeff(), 1e-15);
  }
}

// Three loops on 7 creases: loop 0 uses creases 0-3, loop 1 creases 2-5 (sharing 2 and 3,
// one of them with a sign flip), loop 2 uses crease 6 twice and crease 0.
ThickPattern three_loop_pattern(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(-3, 3), length(0.1, 2);
  auto joint = [&](int crease, double sign) {
    ThickJoint j;
    j.crease = crease;
    j.angle_sign = sign;
    j.angle_offset = angle(rng);
    j.link = DhLink{length(rng), length(rng) - 1.0, angle(rng)};
    return j;
  };
  ThickPattern p;
  p.num_creases = 7;
  p.loops.push_back(ThickLoop{"a", {joint(0, 1), joint(1, -1), joint(2, 1), joint(3, 1)}});
  p.loops.push_back(ThickLoop{"b", {joint(2, -1), joint(3, 1), joint(4, 1), joint(5, -1), joint(1, 1)}});
  p.loops.push_back(ThickLoop{"c", {joint(6, 1), joint(0, -1), joint(6, -1)}});
  return p;
}

TEST(ThickClosure, JacobianMatchesCentralDifferences) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(-3, 3);
  int checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    ThickClosureOptions options;
    if (trial % 2) options.fixed = {{4, angle(rng)}};
    const ThickClosureSystem system(three_loop_pattern(rng), options);
    ASSERT_EQ(system.num_rows(), 18);
    ASSERT_EQ(system.num_unknowns(), trial % 2 ? 6 : 7);
    Eigen::VectorXd x(system.num_unknowns());
    for (int i = 0; i < x.size(); ++i) x[i] = angle(rng);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    system.evaluate(x, r, J);
    // Only where the rotation left over is below pi is the log smooth.
    bool smooth = true;
    for (int k = 0; k < 3; ++k) smooth = smooth && r.segment<3>(6 * k).norm() < kPi - 0.1;
    if (!smooth) continue;
    ++checked;
    EXPECT_LE((r - system.residual(x)).cwiseAbs().maxCoeff(), 1e-15);
    const Eigen::MatrixXd dense = Eigen::MatrixXd(J);
    const double h = 1e-6;
    for (int i = 0; i < x.size(); ++i) {
      Eigen::VectorXd xp = x, xm = x;
      xp[i] += h;
      xm[i] -= h;
      const Eigen::VectorXd column = (system.residual(xp) - system.residual(xm)) / (2 * h);
      EXPECT_LE((column - dense.col(i)).cwiseAbs().maxCoeff(), 1e-8) << "trial " << trial << " unknown " << i;
    }
    // Rows of a loop that does not touch an unknown are structurally zero.
    EXPECT_EQ(dense.block(6, system.unknown_of_crease(0), 6, 1).cwiseAbs().maxCoeff(), 0.0);
  }
  EXPECT_GE(checked, 5);  // enough random states away from the log's cut
}

TEST(ThickClosure, SparsityPatternDoesNotDependOnTheState) {
  std::mt19937_64 rng(3);
  const ThickClosureSystem system(three_loop_pattern(rng));
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J1, J2;
  system.evaluate(Eigen::VectorXd::Zero(7), r, J1);
  system.evaluate(Eigen::VectorXd::Constant(7, 0.3), r, J2);
  ASSERT_EQ(J1.nonZeros(), J2.nonZeros());
  // 6 rows for each (loop, crease) pair: loop a 4 creases, loop b 5, loop c 2.
  EXPECT_EQ(J1.nonZeros(), 6 * (4 + 5 + 2));
  for (int k = 0; k <= J1.cols(); ++k) EXPECT_EQ(J1.outerIndexPtr()[k], J2.outerIndexPtr()[k]);
  for (int k = 0; k < J1.nonZeros(); ++k) EXPECT_EQ(J1.innerIndexPtr()[k], J2.innerIndexPtr()[k]);
}

// With every length and offset 0 the loop is spherical: prod Rz(theta_i) Rx(alpha_i), which
// is the kernel's vertex loop prod Rx(rho_i) Rz(alpha_i) conjugated by the x/z swap, so the
// rotation left over has the same angle, and nothing is translated.
TEST(ThickClosure, SphericalLimitIsTheVertexLoop) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> angle(-3, 3);
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 4 + trial % 3;
    ThickPattern p;
    p.num_creases = n;
    ThickLoop loop;
    std::vector<double> sectors(n), rho(n);
    for (int i = 0; i < n; ++i) {
      sectors[i] = angle(rng);
      rho[i] = angle(rng);
      ThickJoint j;
      j.crease = i;
      j.link.twist = sectors[i];
      loop.joints.push_back(j);
    }
    p.loops.push_back(loop);
    const ThickClosureSystem system(p);
    const Eigen::VectorXd r = system.residual(Eigen::Map<Eigen::VectorXd>(rho.data(), n));
    EXPECT_NEAR(r.head<3>().norm(), vertex_closure_residual(sectors, rho).norm(), 1e-13);
    EXPECT_EQ(r.tail<3>().norm(), 0.0);
  }
}

TEST(ThickClosure, RejectsBadInput) {
  ThickPattern p;
  p.num_creases = 2;
  p.loops.push_back(ThickLoop{"v", {ThickJoint{0, 1.0, 0.0, {}}, ThickJoint{2, 1.0, 0.0, {}}}});
  EXPECT_THROW(ThickClosureSystem{p}, std::invalid_argument);
  p.loops[0].joints[1].crease = 1;
  p.loops[0].joints[1].angle_sign = 0.5;
  EXPECT_THROW(ThickClosureSystem{p}, std::invalid_argument);
  p.loops[0].joints[1].angle_sign = -1.0;
  EXPECT_NO_THROW(ThickClosureSystem{p});
  ThickClosureOptions twice;
  twice.fixed = {{0, 0.1}, {0, 0.2}};
  EXPECT_THROW(ThickClosureSystem(p, twice), std::invalid_argument);
  p.loops[0].joints.pop_back();
  EXPECT_THROW(ThickClosureSystem{p}, std::invalid_argument);
}

// The single-loop adapter (thick_sheet.hpp) refuses what it cannot represent, and its
// ClosureSystem vanishes exactly where the DH loop closes.
TEST(ThickSheet, ClosesWhereTheDhLoopClosesAndRefusesOtherInput) {
  const ThickVertexModel model = bennett_vertex(0.7, 1.1, 0.3);
  const Eigen::VectorXd closed = Eigen::Map<const Eigen::VectorXd>(bennett_zero_thickness(0.7, 1.1, 1.2).data(), 4);
  const ThickSheet sheet = thick_sheet_from_loop(model.thick, closed);
  const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
  ASSERT_EQ(system.num_holes(), 1);
  ASSERT_EQ(system.num_rows(), 6);
  const ThickClosureSystem dh(model.thick);
  for (double rho0 : {0.3, 2.5}) {
    const Eigen::VectorXd other = Eigen::Map<const Eigen::VectorXd>(bennett_zero_thickness(0.7, 1.1, rho0).data(), 4);
    EXPECT_LE(system.residual(system.unknowns_from_edges(sheet.edge_angles_from_creases(other))).cwiseAbs().maxCoeff(), 1e-14);
    // Off the motion both residuals are non-zero.
    Eigen::VectorXd off = other;
    off[1] += 0.05;
    EXPECT_GT(system.residual(system.unknowns_from_edges(sheet.edge_angles_from_creases(off))).norm(), 1e-4);
    EXPECT_GT(dh.residual(off).norm(), 1e-4);
    // The crease <-> edge map round-trips.
    EXPECT_LE((sheet.creases_from_edge_angles(sheet.edge_angles_from_creases(off)) - off).cwiseAbs().maxCoeff(), 1e-15);
  }
  Eigen::VectorXd open = closed;
  open[2] += 0.1;
  EXPECT_THROW(thick_sheet_from_loop(model.thick, open), std::invalid_argument);
  ThickPattern two_loops = model.thick;
  two_loops.loops.push_back(two_loops.loops[0]);
  EXPECT_THROW(thick_sheet_from_loop(two_loops, closed), std::invalid_argument);
}

}}  // namespace
}  // namespace rigidfold
