// The thick waterbomb vertex for any mu (seed 003 eqs 4-55, 4-57, 4-58): the seed's closed
// form checked against the DH loop product and against the general solver, and mu = 1/2
// shown to keep one DOF at the vertex but to leave the zero-thickness motion (4-60: only
// mu = 1 keeps it).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernel/closure/closure_system.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "kernel/solve/rank.hpp"
#include "kernel/thick/thick_closure_system.hpp"
#include "kernel/thick/thick_sheet.hpp"
#include "kernel/thick/thick_vertex_models.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

constexpr double kPi = std::numbers::pi;

// Seed eq. (4-58), joint angles of the thick waterbomb from T = tan(theta2/2) (seed joints
// 1..6 = creases 0..5).
std::vector<double> seed_waterbomb_joint_angles(double mu, double T) {
  const double t1 = -(mu * (mu + 1) * T * T + mu + 1) / (mu * mu * T * (T * T + 1));
  const double t3 = (std::sqrt(2.0) * (mu + 1) / (2 * mu)) / T;
  const double t4 = (mu * (mu - 1) * T * T - mu - 1) / (mu * T * (mu * T * T + mu + 2));
  const double theta2 = 2 * std::atan(T), theta3 = 2 * std::atan(t3);
  return {2 * std::atan(t1), theta2, theta3, 2 * std::atan(t4), theta3, theta2};
}

// Crease fold angles (kernel convention, wrapped to (-pi, pi]) for the model's joint maps.
Eigen::VectorXd creases_from_joint_angles(const ThickVertexModel& model, const std::vector<double>& theta) {
  Eigen::VectorXd rho(theta.size());
  for (std::size_t i = 0; i < theta.size(); ++i) {
    const ThickJoint& j = model.thick.loops[0].joints[i];
    rho[i] = std::remainder((theta[i] - j.angle_offset) / j.angle_sign, 2 * kPi);
  }
  return rho;
}

TEST(ThickWaterbomb, SeedClosedFormClosesTheDhLoopForAnyMu) {
  for (double mu : {0.5, 1.0, 2.0}) {
    const ThickVertexModel model = waterbomb_vertex(mu, 0.3);
    const ThickClosureSystem dh(model.thick);
    double worst = 0.0;
    for (int k = 1; k < 60; ++k) {
      const double phi2 = kPi * k / 60;  // theta2 = pi + phi2 (4-59)
      const Eigen::VectorXd rho = creases_from_joint_angles(model, seed_waterbomb_joint_angles(mu, std::tan(0.5 * (kPi + phi2))));
      worst = std::max(worst, dh.residual(rho).cwiseAbs().maxCoeff());
    }
    EXPECT_LE(worst, 1e-13) << "mu = " << mu;
  }
}

TEST(ThickWaterbomb, GeneralSolverFollowsTheSeedClosedForm) {
  for (double mu : {0.5, 2.0}) {
    const ThickVertexModel model = waterbomb_vertex(mu, 0.3);
    auto seed_state = [&](double phi2) {
      return creases_from_joint_angles(model, seed_waterbomb_joint_angles(mu, std::tan(0.5 * (kPi + phi2))));
    };
    const ThickSheet sheet = thick_sheet_from_loop(model.thick, seed_state(kPi / 2));
    const ClosureSystem system(sheet.pattern, sheet.topology, sheet.options);
    NewtonOptions newton;
    newton.tolerance = 1e-14;
    newton.held_unknowns = {system.unknown_of_edge(sheet.edge_of_crease[1])};  // crease 1 (seed theta2) driven
    Eigen::VectorXd x = system.unknowns_from_edges(sheet.edge_angles_from_creases(seed_state(kPi / 2)));
    double worst = 0.0;
    for (int direction : {+1, -1}) {
      Eigen::VectorXd creases = sheet.creases_from_edge_angles(system.edges_from_unknowns(x));
      for (int k = 1; k <= 45; ++k) {
        const double phi2 = kPi / 2 + direction * k * (kPi / 100);
        const Eigen::VectorXd expected = seed_state(phi2);
        creases[1] = expected[1];
        const NewtonResult result = newton_project(system, system.unknowns_from_edges(sheet.edge_angles_from_creases(creases)), newton);
        ASSERT_TRUE(result.converged) << "mu = " << mu << " phi2 = " << phi2;
        creases = sheet.creases_from_edge_angles(system.edges_from_unknowns(result.x));
        for (int i = 0; i < 6; ++i) worst = std::max(worst, std::abs(std::remainder(creases[i] - expected[i], 2 * kPi)));
        Eigen::VectorXd r;
        Eigen::SparseMatrix<double> J;
        system.evaluate(result.x, r, J);
        EXPECT_EQ(jacobian_rank(J).dof, 1) << "mu = " << mu << " phi2 = " << phi2;
      }
    }
    EXPECT_LE(worst, 1e-10) << "mu = " << mu;
    std::printf("thick waterbomb mu = %.1f: general solver vs seed (4-58) max %.2e rad over phi2 in [0.05 pi, 0.95 pi]\n", mu, worst);
  }
}

// mu = 1/2: a regular closed state of the thick vertex whose fold angles are not those of the
// zero-thickness waterbomb at the same crease-0 angle.
TEST(ThickWaterbomb, MuOneHalfLeavesTheZeroThicknessMotion) {
  const ThickVertexModel model = waterbomb_vertex(0.5, 0.3);
  double largest = 0.0;
  for (int k = 5; k <= 95; k += 5) {
    const double phi2 = kPi * k / 100;
    const Eigen::VectorXd thick = creases_from_joint_angles(model, seed_waterbomb_joint_angles(0.5, std::tan(0.5 * (kPi + phi2))));
    const std::vector<double> zero = waterbomb_zero_thickness(thick[0]);
    for (int i = 0; i < 6; ++i) largest = std::max(largest, std::abs(std::remainder(thick[i] - zero[i], 2 * kPi)));
  }
  EXPECT_GE(largest, 0.05);
  std::printf("thick waterbomb mu = 0.5: largest |rho - rho_zero| at equal rho0 %.3f rad\n", largest);
}

}}  // namespace
}  // namespace rigidfold
