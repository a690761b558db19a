// The general model on a waterbomb base given as a FOLD file (no
// waterbomb-specific code on the solving path: FOLD reader, rest state from a folded frame's
// coordinates, springs by letter, minimisation on the closure manifold from generic starts)
// gives the same stable states as `rigidfold waterbomb` (design/waterbomb).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "design/waterbomb/waterbomb_bistability.hpp"
#include "kernel/closure/closure_system.hpp"
#include "kernel/energy/constrained_equilibrium.hpp"
#include "kernel/energy/crease_energy.hpp"
#include "kernel/energy/crease_stiffness.hpp"
#include "kernel/energy/rest_angles.hpp"
#include "kernel/geometry/face_placement.hpp"
#include "kernel/geometry/fold_angles.hpp"
#include "kernel/geometry/folded_output.hpp"
#include "kernel/math/angle_units.hpp"
#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/topology.hpp"

namespace rigidfold {
namespace { namespace RIGIDFOLD_UNITY_ID {

TEST(EnergyFoldFile, BundledWaterbombMatchesDesignCommand) {
  const CreasePattern p = read_fold(std::string(RIGIDFOLD_SOURCE_DIR) + "/data/bundled/waterbomb_base.fold");
  const Topology topo = build_topology(p);
  const ClosureSystem sys(p, topo);
  const auto design = waterbomb::waterbomb_bistability(4, to_radians(60.0), 1.0, 1.0);
  const auto want = design.stable_states();
  ASSERT_EQ(want.size(), 2u);

  // The rest state as a user would give it: a folded frame (coordinates only) of the file.
  Eigen::VectorXd rest = Eigen::VectorXd::Zero(p.num_edges());
  for (int e = 0; e < p.num_edges(); ++e) {
    if (p.assignments[e] == Assignment::Mountain) rest[e] = design.springs.rest.gamma_m;
    if (p.assignments[e] == Assignment::Valley) rest[e] = design.springs.rest.gamma_v;
  }
  CreasePattern with = with_folded_frame(p, place_faces(p, topo, rest, reference_fold_angles(p, topo)), rest, "rest");
  for (auto& f : with.extra["file_frames"]) f.erase("edges_foldAngle");
  const CreaseSprings springs =
      make_crease_springs(p, stiffness_by_assignment(p, {1.0, 1.0, 1.0}), rest_angles_from_frame(with));

  // Generic starts by letter only: valleys folded far more than mountains (the far side of
  // flat, where the vertex has gone through) and the reverse, with random asymmetry.
  std::mt19937_64 rng(2014);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Eigen::VectorXd> starts;
  for (auto [v, m] : {std::pair{0.8, -0.3}, std::pair{0.3, -1.2}}) {
    Eigen::VectorXd x(sys.num_unknowns());
    for (int k = 0; k < sys.num_unknowns(); ++k)
      x[k] = (p.assignments[sys.edge_of_unknown(k)] == Assignment::Valley ? v : m) + u(rng);
    starts.push_back(x);
  }
  const std::vector<Equilibrium> got = stable_states(sys, topo, springs, starts);
  ASSERT_EQ(got.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    for (int e = 0; e < p.num_edges(); ++e) {
      const double w = p.assignments[e] == Assignment::Mountain ? want[i].path.angles.gamma_m
                       : p.assignments[e] == Assignment::Valley ? want[i].path.angles.gamma_v
                                                                : 0.0;
      EXPECT_NEAR(got[i].edge_angles[e], w, 1e-9) << "state " << i << " edge " << e;
    }
    EXPECT_NEAR(got[i].energy, want[i].path.energy, 1e-9 * std::max(want[i].path.energy, 1e-300) + 1e-20);
    EXPECT_GT(got[i].min_eigenvalue, 0.0);
  }
}

}}  // namespace
}  // namespace rigidfold
