// The thick vertices of seed 003 ch. 4 (Bennett, Myard, plane-symmetric
// Bricard diamond and waterbomb) traced by the zero-thickness core's own solvers
// (ClosureSystem with one SE(3) hole closure, newton_project with a driven crease,
// continue_one_dof, jacobian_rank) through thick_sheet_from_loop, and compared with the
// zero-thickness fold angles over the whole range of the driving crease.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <Eigen/SVD>

#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/continuation.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/thick_closure_system.hpp"
#include "kernel/thick/thick_sheet.hpp"
#include "kernel/thick/thick_vertex_models.hpp"
#include "kernel/vertex/spherical_4r.hpp"
#include "kernel/vertex/vertex_closure.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

using ZeroThickness = std::function<std::vector<double>(double)>;

Eigen::VectorXd as_vector(const std::vector<double>& v) { return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()); }

// The general solver on one thick vertex: the sheet with a hole and its ClosureSystem.
struct GeneralSolver {
  ThickSheet sheet;
  ClosureSystem system;
  int driven = -1;  // unknown of crease 0's hinge

  GeneralSolver(const ThickVertexModel& model, const Eigen::VectorXd& closed_creases)
      : sheet(thick_sheet_from_loop(model.thick, closed_creases)),
        system(sheet.pattern, sheet.topology, sheet.options),
        driven(system.unknown_of_edge(sheet.edge_of_crease[0])) {}

  Eigen::VectorXd unknowns(const Eigen::VectorXd& creases) const {
    return system.unknowns_from_edges(sheet.edge_angles_from_creases(creases));
  }
  Eigen::VectorXd creases(const Eigen::VectorXd& x) const {
    return sheet.creases_from_edge_angles(system.edges_from_unknowns(x));
  }
};

double wrapped_difference(double a, double b) { return std::remainder(a - b, 2 * kPi); }

double max_deviation(const Eigen::VectorXd& rho, const std::vector<double>& expected) {
  double worst = 0.0;
  for (int i = 0; i < rho.size(); ++i) worst = std::max(worst, std::abs(wrapped_difference(rho[i], expected[i])));
  return worst;
}

int zero_thickness_dof(const ThickVertexModel& model, const std::vector<double>& rho) {
  Eigen::Vector3d r;
  Eigen::Matrix3Xd J;
  vertex_closure_jacobian(model.sectors, rho, r, J);
  return jacobian_rank(Eigen::MatrixXd(J).sparseView(0.0, 0.0)).dof;
}

struct MotionReport {
  double max_deviation_driven = 0.0;        // natural-parameter driving of crease 0, farther than 1e-4 * pi/2 from both ends
  double max_deviation_near_ends = 0.0;     // the same within 1e-4 * pi/2 of the ends (1e-5, 1e-6)
  double max_near_end_bound = 0.0;          // the conditioning bound there
  double max_deviation_continuation = 0.0;  // pseudo-arclength continuation
  double max_residual = 0.0;
  double continuation_low = 1e9, continuation_high = -1e9;  // |rho0| range the continuation covered
  int continuation_points = 0;
  int samples = 0;
};

// Drives crease 0 over [0, pi] (with its mountain-valley sign) in `steps` steps from the
// middle both ways with newton_project holding it, compares every crease with the zero-
// thickness relation, checks DOF at every sample; then traces both ways by continuation.
MotionReport trace_against_zero_thickness(const ThickVertexModel& model, const ZeroThickness& zero, int steps) {
  const int n = static_cast<int>(model.sectors.size());
  const double m0 = model.mountain_valley[0];
  const double middle = m0 * kPi / 2;
  const GeneralSolver solver(model, as_vector(zero(middle)));
  const ThickClosureSystem dh(model.thick);
  MotionReport report;

  // Newton stops at 1e-14 (not the default 1e-12): towards the fully folded state the
  // Jacobian's smallest singular value falls, and a residual of 1e-12 there leaves ~1e-10 rad
  // in the angles; quadratic convergence reaches 1e-14 in one more step.
  NewtonOptions newton;
  newton.held_unknowns = {solver.driven};
  newton.tolerance = 1e-14;
  // Distances s of |rho0| from pi/2 in units of pi/2: a uniform grid, then geometrically
  // towards the ends (1 - 1e-3 .. 1 - 1e-6). The ends themselves (flat, fully folded) are
  // bifurcation points, where holding rho0 does not determine the state; they are checked
  // below by closure of the mapped zero-thickness state instead.
  std::vector<double> distances;
  for (int k = 0; k < steps / 2; ++k) distances.push_back(static_cast<double>(k) / (steps / 2));
  for (double gap : {1e-3, 1e-4, 1e-5, 1e-6}) distances.push_back(1.0 - gap);
  for (int direction : {+1, -1}) {
    Eigen::VectorXd previous = solver.unknowns(as_vector(zero(middle)));
    Eigen::VectorXd x = previous;
    for (std::size_t k = 0; k < distances.size(); ++k) {
      const double rho0 = m0 * (kPi / 2) * (1 + direction * distances[k]);
      // Secant predictor from the last two points, then crease 0 set to its new value.
      Eigen::VectorXd guess = x;
      if (k >= 2) guess += (x - previous) * (distances[k] - distances[k - 1]) / (distances[k - 1] - distances[k - 2]);
      Eigen::VectorXd creases = solver.creases(guess);
      creases[0] = rho0;
      const NewtonResult result = newton_project(solver.system, solver.unknowns(creases), newton);
      EXPECT_TRUE(result.converged) << model.name << " rho0 = " << rho0 << " residual " << result.residual_history.back();
      previous = x;
      x = result.x;
      const Eigen::VectorXd rho = solver.creases(x);
      const double deviation = max_deviation(rho, zero(rho0));
      if (distances[k] <= 1 - 1e-4) {
        report.max_deviation_driven = std::max(report.max_deviation_driven, deviation);
      } else {
        // Within 1e-4 * pi/2 of a bifurcation end the state itself is ill-conditioned: the
        // smallest singular value of the Jacobian (crease 0 held) falls with the distance, and
        // the rounding of the residual's evaluation (~1e-15) moves the angles by
        // (|r| + 1e-15) / sigma_min. The deviation must stay within that bound there.
        Eigen::VectorXd r;
        Eigen::SparseMatrix<double> J;
        dh.evaluate(rho, r, J);
        const Eigen::MatrixXd held_free = Eigen::MatrixXd(J).rightCols(n - 1);
        const double sigma_min = Eigen::JacobiSVD<Eigen::MatrixXd>(held_free).singularValues().minCoeff();
        const double bound = (r.norm() + 1e-15) / sigma_min;
        EXPECT_LE(deviation, bound) << model.name << " rho0 = " << rho0;
        report.max_deviation_near_ends = std::max(report.max_deviation_near_ends, deviation);
        report.max_near_end_bound = std::max(report.max_near_end_bound, bound);
      }
      report.max_residual = std::max(report.max_residual, dh.residual(rho).cwiseAbs().maxCoeff());
      ++report.samples;
      if (static_cast<int>(k) < steps / 2) {  // DOF on the uniform grid
        Eigen::VectorXd r;
        Eigen::SparseMatrix<double> J, Jdh;
        solver.system.evaluate(x, r, J);
        dh.evaluate(rho, r, Jdh);
        EXPECT_EQ(jacobian_rank(J).dof, 1) << model.name << " rho0 = " << rho0;
        EXPECT_EQ(jacobian_rank(Jdh).dof, 1) << model.name << " rho0 = " << rho0;
        EXPECT_EQ(zero_thickness_dof(model, zero(rho0)), n - 3) << model.name << " rho0 = " << rho0;
      }
    }
  }
  // The ends: the zero-thickness flat and fully folded states close the thick loop too.
  for (double end : {0.0, m0 * kPi}) {
    const Eigen::VectorXd rho = as_vector(zero(end));
    report.max_residual = std::max(report.max_residual, dh.residual(rho).cwiseAbs().maxCoeff());
    report.max_residual = std::max(report.max_residual, solver.system.residual(solver.unknowns(rho)).cwiseAbs().maxCoeff());
  }

  ContinuationOptions options;
  options.max_angle_step = 0.05;
  const double margin = 1e-3;
  for (double direction : {+1.0, -1.0}) {
    Eigen::VectorXd along = Eigen::VectorXd::Zero(solver.system.num_unknowns());
    along[solver.driven] = direction * solver.sheet.factor[0] * m0;  // |rho0| grows for +1
    // Land exactly on |rho0| = margin or pi - margin, and stop there.
    const double end = direction > 0 ? kPi - margin : margin;
    Eigen::VectorXd end_creases = as_vector(zero(middle));
    end_creases[0] = m0 * end;
    options.landing_unknown = solver.driven;
    options.landing_values = {solver.unknowns(end_creases)[solver.driven]};
    const auto stop = [&](const Eigen::VectorXd& x) {
      const double r0 = m0 * solver.creases(x)[0];
      return direction > 0 ? r0 >= end - 1e-12 : r0 <= end + 1e-12;
    };
    const ContinuationResult trace =
        continue_one_dof(solver.system, solver.unknowns(as_vector(zero(middle))), along, stop, options);
    EXPECT_EQ(trace.reason, "stop") << model.name;
    for (const ContinuationPoint& point : trace.points) {
      const Eigen::VectorXd rho = solver.creases(point.x);
      const double r0 = m0 * rho[0];
      if (r0 < 0 || r0 > kPi) continue;  // the last point may step just past an end
      report.max_deviation_continuation = std::max(report.max_deviation_continuation, max_deviation(rho, zero(rho[0])));
      report.continuation_low = std::min(report.continuation_low, r0);
      report.continuation_high = std::max(report.continuation_high, r0);
      ++report.continuation_points;
    }
  }
  return report;
}

void expect_same_motion(const ThickVertexModel& model, const ZeroThickness& zero) {
  // The zero-thickness relation itself closes the kernel's vertex loop (independent check
  // of the digest's closed form) over the whole range.
  double worst_zero = 0.0;
  for (int k = 0; k <= 100; ++k) {
    const double rho0 = model.mountain_valley[0] * kPi * k / 100;
    worst_zero = std::max(worst_zero, vertex_closure_residual(model.sectors, zero(rho0)).norm());
  }
  EXPECT_LE(worst_zero, 1e-13) << model.name;

  const MotionReport r = trace_against_zero_thickness(model, zero, 200);
  EXPECT_LE(r.max_deviation_driven, 1e-10) << model.name;
  EXPECT_LE(r.max_deviation_continuation, 1e-10) << model.name;
  EXPECT_LE(r.max_residual, 1e-12) << model.name;
  EXPECT_LE(r.continuation_low, 1e-3 + 1e-12) << model.name;
  EXPECT_GE(r.continuation_high, kPi - 1e-3 - 1e-12) << model.name;
  std::printf("%s: %d driven samples, max |rho - rho_zero| %.2e rad; %d continuation points over |rho0| in [%.4f, %.4f], "
              "max %.2e rad; max DH residual %.2e; within 1.6e-4 rad of the ends %.2e rad (conditioning bound %.2e)\n",
              model.name.c_str(), r.samples, r.max_deviation_driven, r.continuation_points, r.continuation_low,
              r.continuation_high, r.max_deviation_continuation, r.max_residual, r.max_deviation_near_ends,
              r.max_near_end_bound);
}

TEST(ThickBennett, FoldsLikeTheZeroThicknessVertex) {
  const double a12 = 0.7, a23 = 1.1;
  expect_same_motion(bennett_vertex(a12, a23, 0.2), [&](double r0) { return bennett_zero_thickness(a12, a23, r0); });
}

TEST(ThickBennett, ZeroThicknessRelationIsABranchOfTheSpherical4rClosedForm) {
  const double a12 = 0.7, a23 = 1.1;
  const ThickVertexModel model = bennett_vertex(a12, a23, 1.0);
  const S4RSectors sectors{model.sectors[0], model.sectors[1], model.sectors[2], model.sectors[3]};
  for (int k = 1; k < 50; ++k) {
    const double rho0 = kPi * k / 50;
    const std::vector<double> expected = bennett_zero_thickness(a12, a23, rho0);
    double best = 1e9;
    for (const S4RFoldAngles& branch : s4r_branches_checked(sectors, rho0).branches)
      best = std::min(best, max_deviation(as_vector({branch.begin(), branch.end()}), expected));
    EXPECT_LE(best, 1e-12) << "rho0 = " << rho0;
  }
}

TEST(ThickBennett, ThickAnglesSatisfyTheBennettClosure) {
  // Seed eq. (1-8): theta1 + theta3 = theta2 + theta4 = 2pi (mod 2pi),
  // tan(theta1/2) tan(theta2/2) = sin((a23 + a12)/2) / sin((a23 - a12)/2).
  const double a12 = 0.4, a23 = 1.3;
  const ThickVertexModel model = bennett_vertex(a12, a23, 0.5);
  const ThickClosureSystem dh(model.thick);
  for (int k = 1; k < 40; ++k) {
    const Eigen::VectorXd rho = as_vector(bennett_zero_thickness(a12, a23, kPi * k / 40));
    EXPECT_LE(dh.residual(rho).cwiseAbs().maxCoeff(), 1e-14);
    std::vector<double> th(4);
    for (int i = 0; i < 4; ++i) th[i] = joint_angle(model.thick.loops[0].joints[i], rho[i]);
    EXPECT_NEAR(wrapped_difference(th[0] + th[2], 0.0), 0.0, 1e-14);
    EXPECT_NEAR(wrapped_difference(th[1] + th[3], 0.0), 0.0, 1e-14);
    EXPECT_NEAR(std::tan(th[0] / 2) * std::tan(th[1] / 2), std::sin((a23 + a12) / 2) / std::sin((a23 - a12) / 2), 1e-12);
  }
}

TEST(ThickMyard, FoldsLikeTheSymmetricZeroThicknessVertex) {
  for (double a : {0.35, kPi / 6, 0.9}) {
    expect_same_motion(myard_vertex(a, 0.1), [&](double r0) { return myard_zero_thickness(a, r0); });
  }
}

TEST(ThickBricard, DiamondFoldsLikeTheZeroThicknessVertex) {
  for (double a : {0.3, kPi / 4}) {
    expect_same_motion(diamond_vertex(a, 0.1, 0.15), [&](double r0) { return diamond_zero_thickness(a, r0); });
  }
}

TEST(ThickBricard, WaterbombWithMuOneFoldsLikeTheZeroThicknessVertex) {
  expect_same_motion(waterbomb_vertex(1.0, 0.1), [](double r0) { return waterbomb_zero_thickness(r0); });
}

}}  // namespace
}  // namespace rigidfold
