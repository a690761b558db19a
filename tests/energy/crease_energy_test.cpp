// Crease-spring energy (kernel/energy): stiffness from a flexure (seed 004 Table 2.1), energy,
// exact gradient and Hessian against central differences, rest angles from a folded frame.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "data/generators/waterbomb.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/rest_angles.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/input_error.hpp"
#include "kernel/pattern/topology.hpp"
#include "tests/support/input_error_place.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// Seed 004 Table 2.1: l = 0.714 mm, b = 50 mm, h = 0.02032 mm, metallic glass E = 93 GPa
// (Table 2.3) -> k = 0.00455 N m/rad as printed (3 digits).
TEST(EnergyStiffness, FlexureMatchesSeedTable21) {
  const double k = flexure_stiffness(93e9, 50e-3, 0.02032e-3, 0.714e-3);
  EXPECT_NEAR(k, 0.00455, 0.000005);
  // k ~ h^3 / l: doubling the thickness gives 8x, doubling the length half.
  EXPECT_NEAR(flexure_stiffness(93e9, 50e-3, 2 * 0.02032e-3, 0.714e-3) / k, 8.0, 1e-12);
  EXPECT_NEAR(flexure_stiffness(93e9, 50e-3, 0.02032e-3, 2 * 0.714e-3) / k, 0.5, 1e-12);
}

TEST(EnergyStiffness, BadInputNamesTheParameter) {
  auto place_of = [](auto&& f) { return test::input_error_place(f); };
  EXPECT_EQ(place_of([] { flexure_stiffness(-1, 1, 1, 1); }), "youngs_modulus");
  EXPECT_EQ(place_of([] { flexure_stiffness(1, NAN, 1, 1); }), "width");
  EXPECT_EQ(place_of([] { flexure_stiffness(1, 1, 0, 1); }), "thickness");
  EXPECT_EQ(place_of([] { flexure_stiffness(1, 1, 1, INFINITY); }), "length");
  const CreasePattern p = generators::waterbomb_base({});
  EXPECT_EQ(place_of([&] { stiffness_by_assignment(p, {-1.0, 1.0, 1.0}); }), "stiffness.mountain");
  Eigen::VectorXd k = Eigen::VectorXd::Ones(p.num_edges()), rest = Eigen::VectorXd::Zero(p.num_edges());
  k[3] = -2;
  EXPECT_EQ(place_of([&] { make_crease_springs(p, k, rest); }), "stiffness[3]");
  k[3] = 1;
  rest[5] = 4.0;  // beyond pi
  EXPECT_EQ(place_of([&] { make_crease_springs(p, k, rest); }), "rest_angles[5]");
  EXPECT_EQ(place_of([&] { make_crease_springs(p, k.head(3), rest); }), "stiffness");
}

TEST(EnergyStiffness, ByAssignmentSkipsBoundary) {
  const CreasePattern p = generators::waterbomb_base({});
  const Eigen::VectorXd k = stiffness_by_assignment(p, {2.0, 3.0, 5.0});
  for (int e = 0; e < p.num_edges(); ++e) {
    const double want = p.assignments[e] == Assignment::Mountain ? 2.0 : p.assignments[e] == Assignment::Valley ? 3.0 : 0.0;
    EXPECT_EQ(k[e], want) << e;
  }
}

TEST(EnergyCrease, GradientAndHessianMatchCentralDifferences) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const CreasePattern p = generators::waterbomb_base({});
  const int m = p.num_edges();
  Eigen::VectorXd k(m), rest(m), rho(m);
  for (int e = 0; e < m; ++e) {
    k[e] = 1.0 + u(rng);
    rest[e] = 2.0 * u(rng);
    rho[e] = 2.0 * u(rng);
  }
  const CreaseSprings s = make_crease_springs(p, k, rest);
  // Energy by hand.
  double want = 0;
  for (int e = 0; e < m; ++e) want += 0.5 * k[e] * (rho[e] - rest[e]) * (rho[e] - rest[e]);
  EXPECT_NEAR(crease_energy(s, rho), want, 1e-14 * want);
  const Eigen::VectorXd g = crease_energy_gradient(s, rho);
  const Eigen::MatrixXd H(crease_energy_hessian(s));
  const double h = 1e-5;
  for (int e = 0; e < m; ++e) {
    Eigen::VectorXd a = rho, b = rho;
    a[e] += h;
    b[e] -= h;
    // E is quadratic: the central difference is exact up to rounding.
    EXPECT_NEAR(g[e], (crease_energy(s, a) - crease_energy(s, b)) / (2 * h), 1e-9) << e;
    const Eigen::VectorXd dg = (crease_energy_gradient(s, a) - crease_energy_gradient(s, b)) / (2 * h);
    for (int f = 0; f < m; ++f) EXPECT_NEAR(H(f, e), dg[f], 1e-9) << f << "," << e;
  }
  EXPECT_THROW(crease_energy(s, rho.head(3)), std::invalid_argument);
}

// A folded state written as a FOLD frame (coordinates only) gives back its fold angles as
// rest angles; with edges_foldAngle in the frame those are used.
TEST(EnergyRestAngles, FromFoldedFrame) {
  const CreasePattern p = generators::waterbomb_base({});
  const Topology topo = build_topology(p);
  // A symmetric waterbomb state (gamma_m, gamma_v) at theta = 60 deg, n = 4 (seed 004 eqs
  // 3.4-3.6 with the digest's simplified forms), closing the loop.
  const double th = to_radians(60.0), a = kPi / 4;
  const double d2 = std::asin(std::sin(th) * std::sin(a));
  const double gm = -std::fabs(kPi - 2 * th);
  const double gv = 2 * (std::acos(std::tan(d2) / std::tan(th)) + std::acos(std::tan(d2) / std::tan(a))) - kPi;
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(p.num_edges());
  for (int e = 0; e < 8; ++e) rho[e] = p.assignments[e] == Assignment::Mountain ? gm : gv;
  const FoldedGeometry folded = place_faces(p, topo, rho, reference_fold_angles(p, topo));
  ASSERT_LT(folded.relative_mismatch(), 1e-12);
  CreasePattern with = with_folded_frame(p, folded, rho, "rest");
  const Eigen::VectorXd from_angles = rest_angles_from_frame(with);
  EXPECT_LT((from_angles - rho).lpNorm<Eigen::Infinity>(), 1e-12);
  // Coordinates only: the angles are measured from the faces.
  for (auto& f : with.extra["file_frames"]) f.erase("edges_foldAngle");
  const Eigen::VectorXd measured = rest_angles_from_frame(with);
  EXPECT_LT((measured - rho).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_THROW(rest_angles_from_frame(p), InputError);        // no frames
  EXPECT_THROW(rest_angles_from_frame(with, 7), InputError);  // no such frame
}

}}  // namespace
}  // namespace rigidfold
