// Minimum-energy paths and their tops between two stable states of crease-spring patterns
// (kernel/energy/minimum_energy_path.hpp): a 1-DOF vertex against a Brent scan of the traced
// branch, the waterbomb base against design/waterbomb's symmetric-path barriers, and the
// checks that keep a failed search from reporting a barrier.
#include <gtest/gtest.h>

#include <boost/math/tools/minima.hpp>

#include <cmath>
#include <algorithm>
#include <limits>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "design/waterbomb/waterbomb_kinematics.hpp"
#include "kernel/closure/closure_second_order.hpp"
#include "kernel/analysis/trace_motion.hpp"
#include "kernel/solve/newton_projection.hpp"
#include "tests/closure/closure_test_utils.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/minimum_energy_path.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

// The bundled waterbomb base (n = 4) with rest at theta0 = 60 deg: the string method between
// its two stable states, started off the symmetric path (seeded perturbation) and with no
// symmetry imposed, relaxes to a path through the flat state. There the closure manifold is
// singular: the M-V-preserving rays of the two states lie on opposite nappes of the flat
// vertex's tangent cone (its quadratic closure condition has signature (1, 5) on the
// first-order tangent space), so every path near flat passes through it, and the energy has a
// cusp there, not a saddle. The climbing image's Newton refinement therefore finds no index-1
// saddle, and the path is reported with a singular top whose barriers are exactly the
// symmetric-path barriers of design/waterbomb (the cusp at theta = 90 deg), to 1e-9 relative.
TEST(MinimumEnergyPath, WaterbombBaseTopIsTheFlatCuspAtTheSymmetricBarrier) {
  const CreasePattern p = read_fold(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/waterbomb_base.fold");
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  for (double k_m : {2.0}) {  // unequal springs; the CLI test covers k_m = k_v = 1
    const auto design = waterbomb::waterbomb_bistability(4, to_radians(60.0), k_m, 1.0);
    const auto want = design.stable_states();
    ASSERT_EQ(want.size(), 2u);
    const auto symmetric = design.symmetric_path_barriers();
    ASSERT_EQ(symmetric.size(), 2u);
    auto by_letter = [&](double m, double v) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(p.num_edges());
      for (int i = 0; i < p.num_edges(); ++i) {
        if (p.assignments[i] == Assignment::Mountain) e[i] = m;
        if (p.assignments[i] == Assignment::Valley) e[i] = v;
      }
      return e;
    };
    const CreaseSprings springs = make_crease_springs(p, stiffness_by_assignment(p, {k_m, 1.0, 1.0}),
                                                      by_letter(design.springs.rest.gamma_m, design.springs.rest.gamma_v));
    // The two states as the general minimiser finds them (from the closed forms' angles).
    std::vector<Equilibrium> states;
    for (const auto& w : want) {
      states.push_back(find_equilibrium(sys, topo, springs, sys.unknowns_from_edges(by_letter(w.path.angles.gamma_m, w.path.angles.gamma_v))));
      ASSERT_TRUE(states.back().stable);
    }
    const MinimumEnergyPath mep = minimum_energy_path(sys, topo, springs, states[0].x, states[1].x);
    ASSERT_TRUE(mep.found) << mep.message;
    EXPECT_EQ(mep.top, PathTop::kSingularPoint) << "k_m " << k_m;
    EXPECT_TRUE(mep.string_converged);
    EXPECT_EQ(mep.saddle.x.lpNorm<Eigen::Infinity>(), 0.0);  // the flat state itself
    EXPECT_FALSE(mep.saddle.converged);                       // not stationary: a cusp
    // Barriers both ways equal the symmetric-path ones (the same cusp).
    EXPECT_NEAR(mep.barrier_from_a, symmetric[0].height, 1e-9 * symmetric[0].height) << "k_m " << k_m;
    EXPECT_NEAR(mep.barrier_from_b, symmetric[1].height, 1e-9 * symmetric[1].height) << "k_m " << k_m;
    EXPECT_NEAR(mep.saddle.energy, crease_energy(springs, Eigen::VectorXd::Zero(p.num_edges())), 1e-15);
    // Every image is on the manifold and below the top, rising to it and falling after it.
    ASSERT_GE(mep.climbing_image, 1);
    ASSERT_LT(mep.climbing_image, static_cast<int>(mep.images.size()) - 1);
    for (std::size_t i = 0; i < mep.images.size(); ++i) {
      EXPECT_LE(sys.residual(sys.unknowns_from_edges(mep.images[i].edge_angles)).lpNorm<Eigen::Infinity>(), 1e-12);
      if (static_cast<int>(i) < mep.climbing_image) {
        EXPECT_LT(mep.images[i].energy, mep.images[i + 1].energy);
      }
      if (static_cast<int>(i) > mep.climbing_image) {
        EXPECT_LT(mep.images[i].energy, mep.images[i - 1].energy);
      }
    }
    // The string really broke the symmetry it was started with: its images are not all
    // symmetric, yet it came back to the symmetric path's top.
    double spread = 0.0;
    for (const PathImage& im : mep.images) {
      double lo = 10, hi = -10;
      for (int e = 0; e < p.num_edges(); ++e)
        if (p.assignments[e] == Assignment::Mountain) {
          lo = std::min(lo, im.edge_angles[e]);
          hi = std::max(hi, im.edge_angles[e]);
        }
      spread = std::max(spread, hi - lo);
    }
    EXPECT_GT(spread, 0.0);

    // Without the singular-top step (radius 0) the same path has no top that passes a check:
    // no barrier is reported, and the message says why.
    MinimumEnergyPathOptions strict;
    strict.singular_top_radius = 0.0;
    const MinimumEnergyPath none = minimum_energy_path(sys, topo, springs, states[0].x, states[1].x, strict);
    EXPECT_FALSE(none.found);
    EXPECT_EQ(none.top, PathTop::kNone);
    EXPECT_TRUE(std::isnan(none.barrier_from_a) && std::isnan(none.barrier_from_b));
    EXPECT_NE(none.message.find("no singular top either"), std::string::npos) << none.message;
  }
  MinimumEnergyPathOptions bad;
  bad.images = 4;
  EXPECT_THROW(minimum_energy_path(sys, topo, make_crease_springs(p, Eigen::VectorXd::Ones(p.num_edges()), Eigen::VectorXd::Zero(p.num_edges())),
                                   Eigen::VectorXd::Zero(sys.num_unknowns()), Eigen::VectorXd::Zero(sys.num_unknowns()), bad),
               std::invalid_argument);
}

// Why the waterbomb path tops at the flat state: there the closure manifold is a cone. On the
// first-order tangent space L = null J(0) (dimension 2n - 2 = 6) the second-order closure
// condition is one quadratic form Q (the normal component of D^2 r[d, d]; the in-plane ones
// vanish), of signature (1, 5) or (5, 1): a cone with two nappes that meet only at flat. The
// tangent rays of the symmetric path into the two states (one-sided derivatives of the closed
// form at theta = 90 deg, by differences of 1e-5 rad) are null for Q and lie on opposite
// nappes (B(d1, d2) has the sign opposite to Q's lone eigenvalue), so near flat every path
// between the states passes through flat.
TEST(MinimumEnergyPath, WaterbombStatesLeaveFlatOnOppositeNappesOfTheTangentCone) {
  const CreasePattern p = read_fold(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/waterbomb_base.fold");
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  const int n = sys.num_unknowns();
  const Eigen::VectorXd flat = Eigen::VectorXd::Zero(n);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense_jacobian(sys, flat), Eigen::ComputeFullV);
  const int rank = static_cast<int>(svd.setThreshold(1e-9).rank());
  ASSERT_EQ(rank, 2);
  const Eigen::MatrixXd L = svd.matrixV().rightCols(n - rank);
  // Q(d): the normal row of D^2 r[d, d]; B by polarisation.
  auto second = [&](const Eigen::VectorXd& d) { return closure_second_derivative(sys, topo, flat, d); };
  auto B = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& v) { return 0.25 * (second(u + v)[2] - second(u - v)[2]); };
  Eigen::MatrixXd Q(L.cols(), L.cols());
  for (int i = 0; i < L.cols(); ++i) {
    EXPECT_LE(second(L.col(i)).head<2>().lpNorm<Eigen::Infinity>(), 1e-12);
    for (int j = 0; j < L.cols(); ++j) Q(i, j) = B(L.col(i), L.col(j));
  }
  const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (Q + Q.transpose())).eigenvalues();
  int positive = 0, negative = 0;
  for (Eigen::Index i = 0; i < ev.size(); ++i) {
    if (ev[i] > 1e-9) ++positive;
    if (ev[i] < -1e-9) ++negative;
  }
  ASSERT_EQ(positive + negative, 6);
  ASSERT_TRUE((positive == 1) != (negative == 1)) << positive << " positive, " << negative << " negative";
  const double lone = positive == 1 ? 1.0 : -1.0;  // the sign of the cone's axis
  const double h = 1e-5;
  auto ray = [&](double side) {
    const Eigen::VectorXd e = waterbomb::waterbomb_edge_angles(p, waterbomb::waterbomb_fold_angles(4, 0.5 * M_PI + side * h));
    return Eigen::VectorXd(sys.unknowns_from_edges(e) / h);
  };
  const Eigen::VectorXd d1 = ray(-1.0), d2 = ray(+1.0);  // towards state 1 (theta < 90) and state 2
  for (const Eigen::VectorXd* d : {&d1, &d2}) {
    EXPECT_LE((dense_jacobian(sys, flat) * *d).lpNorm<Eigen::Infinity>(), 1e-9);  // in L
    EXPECT_LE(std::fabs(B(*d, *d)), 1e-4 * d->squaredNorm());                     // null for Q
  }
  EXPECT_LT(lone * B(d1, d2), -0.1 * d1.norm() * d2.norm());  // opposite nappes
}

// A 1-DOF manifold: a flat-foldable degree-4 vertex (sectors 70, 80, 110, 100 deg), letters
// V M V V selecting the branch rho_0 = rho_2 > 0, rho_3 = -rho_1 > 0, tan(rho_1 / 2) =
// -(cos 75 / cos 5) tan(rho_0 / 2). Springs with rest angles off the manifold (0.2, -2.9, 0.2,
// 2.9 rad, unit stiffness) give two minima on the branch, rho_1 ~ -0.32 and -1.94 rad, away
// from the flat and fully folded singular points, with one smooth maximum between them.
// Independent reference: the branch traced by trace_motion (general solver, crease 1 driven),
// the energy along it as a function of the driven angle (Newton projection with that crease
// held), its extrema polished by Boost's Brent.
TEST(MinimumEnergyPath, OneDofBarrierMatchesBrentOnTheTracedBranch) {
  CreasePattern p = testing::single_vertex_from_sectors({to_radians(70.0), to_radians(80.0), to_radians(110.0), to_radians(100.0)});
  p.assignments[0] = p.assignments[2] = p.assignments[3] = Assignment::Valley;
  p.assignments[1] = Assignment::Mountain;
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  ASSERT_EQ(sys.num_unknowns(), 4);
  Eigen::VectorXd k = Eigen::VectorXd::Zero(p.num_edges()), rest = Eigen::VectorXd::Zero(p.num_edges());
  k.head(4).setOnes();
  rest.head(4) << 0.2, -2.9, 0.2, 2.9;
  const CreaseSprings springs = make_crease_springs(p, k, rest);

  TraceRequest req;
  req.force_general = true;
  req.drive = 0;
  req.to = 3.0;
  req.steps = 60;
  const MotionTrace trace = trace_motion(p, topo, req);
  ASSERT_EQ(trace.branches.size(), 1u);
  const MotionBranch& branch = trace.branches[0];
  ASSERT_TRUE(branch.traced) << branch.message;
  ASSERT_EQ(branch.dof, 1);

  // Energy at a driven angle u: the branch point with crease 1 held at u, projected from the
  // nearest traced step.
  auto energy_at = [&](double u) {
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < branch.steps.size(); ++i)
      if (std::fabs(branch.steps[i].drive - u) < std::fabs(branch.steps[nearest].drive - u)) nearest = i;
    Eigen::VectorXd x = sys.unknowns_from_edges(branch.steps[nearest].rho);
    x[sys.unknown_of_edge(0)] = u;
    NewtonOptions hold;
    hold.held_unknowns = {sys.unknown_of_edge(0)};
    const NewtonResult r = newton_project(sys, x, hold);
    EXPECT_TRUE(r.converged) << "u = " << u;
    return std::pair{crease_energy(springs, sys.edges_from_unknowns(r.x)), r.x};
  };
  // Extrema of the sampled energy, each polished by Brent on its two neighbouring intervals.
  std::vector<double> E;
  for (const auto& s : branch.steps) E.push_back(crease_energy(springs, s.rho));
  std::vector<std::size_t> minima, maxima;
  for (std::size_t i = 1; i + 1 < E.size(); ++i) {
    if (E[i] < E[i - 1] && E[i] < E[i + 1]) minima.push_back(i);
    if (E[i] > E[i - 1] && E[i] > E[i + 1]) maxima.push_back(i);
  }
  ASSERT_EQ(minima.size(), 2u);
  ASSERT_EQ(maxima.size(), 1u);
  auto polish = [&](std::size_t i, double sign) {
    const double lo = std::min(branch.steps[i - 1].drive, branch.steps[i + 1].drive);
    const double hi = std::max(branch.steps[i - 1].drive, branch.steps[i + 1].drive);
    boost::uintmax_t iterations = 200;
    const auto [u, v] = boost::math::tools::brent_find_minima([&](double t) { return sign * energy_at(t).first; }, lo, hi,
                                                               std::numeric_limits<double>::digits, iterations);
    return std::pair{u, sign * v};
  };
  const auto [ua, Ea] = polish(minima[0], 1.0);
  const auto [ub, Eb] = polish(minima[1], 1.0);
  const auto [us, Es] = polish(maxima[0], -1.0);
  ASSERT_GT(Es - Ea, 0.05);  // a real barrier both ways, not a shoulder
  ASSERT_GT(Es - Eb, 0.05);

  // The states handed to the path search: the kernel's minimisation from the Brent minima.
  const Equilibrium a = find_equilibrium(sys, topo, springs, energy_at(ua).second);
  const Equilibrium b = find_equilibrium(sys, topo, springs, energy_at(ub).second);
  ASSERT_TRUE(a.stable && b.stable);
  EXPECT_NEAR(a.energy, Ea, 1e-12 * Ea);  // the same minima
  EXPECT_NEAR(b.energy, Eb, 1e-12 * Eb);

  const MinimumEnergyPath mep = minimum_energy_path(sys, topo, springs, a.x, b.x);
  ASSERT_TRUE(mep.found) << mep.message;
  EXPECT_EQ(mep.saddle.tangent_dimension, 1);
  EXPECT_EQ(mep.negative_eigenvalues, 1);
  EXPECT_LE(mep.saddle.closure_residual, 1e-12);
  EXPECT_NEAR(mep.saddle.edge_angles[0], us, 1e-7);  // Brent's argument is good to ~sqrt(eps)
  EXPECT_NEAR(mep.barrier_from_a, Es - Ea, 1e-9 * (Es - Ea));
  EXPECT_NEAR(mep.barrier_from_b, Es - Eb, 1e-9 * (Es - Eb));
  EXPECT_EQ(mep.top, PathTop::kSaddle);
  EXPECT_TRUE(mep.connects);
  // The saddle's one negative reduced-Hessian eigenvalue is the curvature of E along the
  // branch: d2E/du2 / |dx/du|^2 at a stationary point, here by central differences of the
  // held-crease energy (h = 1e-4: truncation ~1e-8, rounding ~1e-7 relative).
  {
    const double h = 1e-4;
    const auto [Ep, xp] = energy_at(mep.saddle.edge_angles[0] + h);
    const auto [Em, xm] = energy_at(mep.saddle.edge_angles[0] - h);
    const double second = (Ep + Em - 2.0 * mep.saddle.energy) / (h * h);
    const double speed = (xp - xm).norm() / (2.0 * h);
    ASSERT_EQ(mep.saddle.reduced_hessian_eigenvalues.size(), 1);
    const double lambda = mep.saddle.reduced_hessian_eigenvalues[0];
    EXPECT_LT(lambda, 0.0);
    EXPECT_NEAR(lambda, second / (speed * speed), 1e-5 * std::fabs(lambda));
  }
  // The path is on the branch between the two states: every image's driven angle between theirs.
  for (const PathImage& im : mep.images) {
    EXPECT_GE(im.edge_angles[0], std::min(ua, ub) - 1e-6);
    EXPECT_LE(im.edge_angles[0], std::max(ua, ub) + 1e-6);
  }
}

}}  // namespace
}  // namespace rigidfold
